#version 330 core
in float vHeight;
out vec4 fragColor;
void main() { fragColor = vec4(0.0, 0.0, 0.0, 0.42 * exp(-vHeight / 0.025)); }
