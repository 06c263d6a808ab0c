#version 330 core
// Planar curves (Koch, Sierpinski, dragon) as screen-space ribbons of constant pixel width,
// extended by half a width at both ends so corners close.
layout(location = 0) in vec2 aCorner;     // x: 0 start / 1 end, y: -1 / +1 side
layout(location = 1) in vec4 iStart;
layout(location = 2) in vec4 iEnd;
uniform mat4 uViewProj;
uniform vec2 uViewport;
uniform float uWidth;  // pixels
void main() {
    vec4 a = uViewProj * vec4(iStart.xyz, 1.0);
    vec4 b = uViewProj * vec4(iEnd.xyz, 1.0);
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
