#version 330 core
// Leaves, petals and spheres in the turtle frame (SurfaceInstance: position, size,
// heading, colour, up, kind: 12 words).
#include "instances"
layout(location = 0) in vec3 aPosition;  // x along L, y along H, z along U
layout(location = 1) in vec3 aNormal;
uniform mat4 uViewProj;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    int id = instanceIndex();
    if (id >= uCount) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    int base = (uFirst + id) * 12;
    vec3 H = normalize(fetchVec3(base + 4));
    vec3 U = normalize(fetchVec3(base + 8));
    vec3 L = cross(U, H);
    mat3 frame = mat3(L, H, U);
    vWorld = fetchVec3(base) + fetchFloat(base + 3) * (frame * aPosition);
    vNormal = frame * aNormal;
    vColour = fetchColour(base + 7);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
