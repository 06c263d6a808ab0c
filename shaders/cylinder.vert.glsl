#version 330 core
// A tapered cylinder with hemispherical end caps per stem segment (CylinderInstance:
// start xyz, start radius, end xyz, end radius, colour, order | step: 10 words).
#include "instances"
layout(location = 0) in vec4 aShape;  // x, z: ring direction; y: cap offset in radii; w: 0 start / 1 end
uniform mat4 uViewProj;
uniform float uMinRadius;  // keeps far, thin stems at least about a pixel wide
uniform int uBillboard;    // 1: the mesh is a strip (x across, y along past the ends)
uniform vec3 uEye;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    int id = instanceIndex();
    if (id >= uCount) {  // past the end of the last batch
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    int base = (uFirst + id) * 10;
    vec3 start = fetchVec3(base);
    vec3 end = fetchVec3(base + 4);
    vec3 axis = end - start;
    float len = length(axis);
    vec3 d = len > 1e-9 ? axis / len : vec3(0.0, 1.0, 0.0);
    float r = max(mix(fetchFloat(base + 3), fetchFloat(base + 7), aShape.w), uMinRadius);
    vec3 centre = mix(start, end, aShape.w);
    if (uBillboard == 1) {
        // Thin stems: a flat strip turned towards the eye, shaded as if round. Two triangles
        // instead of dozens of sub-pixel ones, which software rasterisers pay for dearly.
        vec3 toEye = normalize(uEye - centre);
        vec3 side = cross(d, toEye);
        float sl = length(side);
        side = sl > 1e-6 ? side / sl : vec3(1.0, 0.0, 0.0);
        vec3 facing = cross(side, d);
        vWorld = centre + r * (aShape.x * side + d * aShape.y);
        vNormal = aShape.x * side + facing * 0.8;
    } else {
        vec3 helper = abs(d.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 s1 = normalize(cross(d, helper));
        vec3 s2 = cross(d, s1);
        vec3 offset = aShape.x * s1 + aShape.z * s2 + d * aShape.y;
        vWorld = centre + r * offset;
        vNormal = offset;
    }
    vColour = fetchColour(base + 8);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
