#version 330 core
// Expands each line into a screen-space quad uWidth pixels wide: core profile
// only guarantees 1-pixel lines.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 gColor[];
uniform vec2 uViewport;
uniform float uWidth;
out vec4 fColor;
void main() {
    vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
    if (p0.w <= 0.0 || p1.w <= 0.0) return; // behind the eye
    vec2 s0 = p0.xy / p0.w * uViewport, s1 = p1.xy / p1.w * uViewport;
    vec2 dir = s1 - s0;
    float len = length(dir);
    if (len < 1e-6) return;
    vec2 offset = vec2(-dir.y, dir.x) / len * uWidth / uViewport;
    fColor = gColor[0];
    gl_Position = vec4(p0.xy + offset * p0.w, p0.zw); EmitVertex();
    gl_Position = vec4(p0.xy - offset * p0.w, p0.zw); EmitVertex();
    fColor = gColor[1];
    gl_Position = vec4(p1.xy + offset * p1.w, p1.zw); EmitVertex();
    gl_Position = vec4(p1.xy - offset * p1.w, p1.zw); EmitVertex();
    EndPrimitive();
}
