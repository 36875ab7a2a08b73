#version 330 core
// The sheet pressed flat onto the ground: a contact shadow that fades with height.
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
uniform float uGround;
out float vHeight;
void main() {
    vHeight = max(aPos.y - uGround, 0.0);
    gl_Position = uViewProj * vec4(aPos.x, uGround - 0.0002, aPos.z, 1.0); // above the desk, below paper lying on it
}
