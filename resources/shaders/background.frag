#version 330 core
in float vY;
uniform vec3 uBackground;
out vec4 fragColor;
void main() { fragColor = vec4(uBackground * (0.92 + 0.1 * vY), 1.0); }
