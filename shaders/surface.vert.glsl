#version 330 core
// Instanced leaves, petals and spheres placed in the turtle frame.
layout(location = 0) in vec3 aPosition;   // x along L, y along H, z along U
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 iPositionSize;
layout(location = 3) in vec3 iHeading;
layout(location = 4) in vec4 iColour;
layout(location = 5) in vec3 iUp;
uniform mat4 uViewProj;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    vec3 H = normalize(iHeading);
    vec3 U = normalize(iUp);
    vec3 L = cross(U, H);
    mat3 frame = mat3(L, H, U);
    vWorld = iPositionSize.xyz + iPositionSize.w * (frame * aPosition);
    vNormal = frame * aNormal;
    vColour = iColour.wzyx;
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
