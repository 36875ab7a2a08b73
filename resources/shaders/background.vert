#version 330 core
out float vY;
void main() {
    // One triangle covering the screen, no vertex buffer needed.
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    vY = p.y;
    gl_Position = vec4(p, 1.0, 1.0); // the far plane: it fills what nothing covers
}
