#version 330 core
// The desk reaches as far as the paper can slide (the floor the simulation knows has no
// edge): the quad goes where the camera looks, as large as its fade.
layout(location = 0) in vec3 aPos;
uniform mat4 uViewProj;
uniform float uGround;
uniform vec2 uCenter;
uniform float uReach;
out vec2 vXZ;
void main() {
    vXZ = uCenter + aPos.xz * uReach;
    // Half a millimetre below the nominal ground, so paper lying on it wins the depth test.
    gl_Position = uViewProj * vec4(vXZ.x, uGround - 0.0005, vXZ.y, 1.0);
}
