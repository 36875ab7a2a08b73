#version 330 core
in float vY;
uniform vec3 uBackground;
uniform vec2 uShade; // the background's shade at screen height y: x + y * this
out vec4 fragColor;
void main() { fragColor = vec4(uBackground * (uShade.x + uShade.y * vY), 1.0); }
