#version 330 core
// Planar curves (Koch, Sierpinski, dragon) as screen-space ribbons of constant pixel width,
// extended by half a width at both ends so corners close.
#include "instances"
layout(location = 0) in vec2 aCorner;  // x: 0 start / 1 end, y: -1 / +1 side
uniform mat4 uViewProj;
uniform vec2 uViewport;
uniform float uWidth;  // pixels
void main() {
    int id = instanceIndex();
    if (id >= uCount) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    int base = (uFirst + id) * 10;
    vec4 a = uViewProj * vec4(fetchVec3(base), 1.0);
    vec4 b = uViewProj * vec4(fetchVec3(base + 4), 1.0);
    vec2 sa = a.xy / a.w * uViewport * 0.5;
    vec2 sb = b.xy / b.w * uViewport * 0.5;
    vec2 dir = sb - sa;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);
    vec4 p = mix(a, b, aCorner.x);
    vec2 offset = (normal * aCorner.y + dir * (aCorner.x * 2.0 - 1.0)) * uWidth * 0.5;
    p.xy += offset / (uViewport * 0.5) * p.w;
    gl_Position = p;
}
