#version 330 core
// A desk: warm grey with a faint 5 cm grid, fading into the background.
in vec2 vXZ;
uniform vec3 uBackground;
out vec4 fragColor;
void main() {
    vec2 cell = abs(fract(vXZ / 0.05 + 0.5) - 0.5) / fwidth(vXZ / 0.05);
    float grid = 1.0 - min(min(cell.x, cell.y), 1.0);
    vec3 desk = vec3(0.56, 0.55, 0.53) - 0.05 * grid;
    float fade = smoothstep(0.35, 1.0, length(vXZ));
    fragColor = vec4(mix(desk, uBackground, fade), 1.0);
}
