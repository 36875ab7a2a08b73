#version 330 core
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
uniform float uGround;
out vec2 vXZ;
void main() {
    vXZ = aPos.xz;
    // Half a millimetre below the nominal ground, so paper lying on it wins the depth test.
    gl_Position = uViewProj * vec4(aPos.x, uGround - 0.0005, aPos.z, 1.0);
}
