#version 330 core
// A desk: warm grey, darker than paper seen edgewise, with a faint 5 cm grid, fading
// with distance from where the camera looks into the background's own shade at that
// height of the screen.
in vec2 vXZ;
uniform vec3 uBackground;
uniform vec2 uCenter;
uniform float uReach;
uniform float uHeight; // of the viewport, in pixels
uniform vec2 uShade;   // the background's shade, as background.frag has it
out vec4 fragColor;
void main() {
    vec2 cell = abs(fract(vXZ / 0.05 + 0.5) - 0.5) / fwidth(vXZ / 0.05);
    float grid = 1.0 - min(min(cell.x, cell.y), 1.0);
    vec3 desk = vec3(0.47, 0.46, 0.44) - 0.05 * grid;
    float fade = smoothstep(0.35, 1.0, length(vXZ - uCenter) / uReach);
    float screenY = 2.0 * gl_FragCoord.y / uHeight - 1.0;
    vec3 background = uBackground * (uShade.x + uShade.y * screenY);
    fragColor = vec4(mix(desk, background, fade), 1.0);
}
