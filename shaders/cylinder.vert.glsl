#version 330 core
// One instanced tapered cylinder with hemispherical end caps per stem segment.
layout(location = 0) in vec4 aShape;      // x, z: ring direction; y: cap offset in radii; w: 0 start / 1 end
layout(location = 1) in vec4 iStart;      // xyz start, w start radius
layout(location = 2) in vec4 iEnd;        // xyz end, w end radius
layout(location = 3) in vec4 iColour;     // bytes of 0xRRGGBBAA as stored: a, b, g, r
uniform mat4 uViewProj;
uniform float uMinRadius;  // keeps far, thin stems at least about a pixel wide
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    vec3 axis = iEnd.xyz - iStart.xyz;
    float len = length(axis);
    vec3 d = len > 1e-9 ? axis / len : vec3(0.0, 1.0, 0.0);
    vec3 helper = abs(d.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 s1 = normalize(cross(d, helper));
    vec3 s2 = cross(d, s1);
    float r = max(mix(iStart.w, iEnd.w, aShape.w), uMinRadius);
    vec3 centre = mix(iStart.xyz, iEnd.xyz, aShape.w);
    vec3 radial = aShape.x * s1 + aShape.z * s2;
    vec3 offset = radial + d * aShape.y;
    vWorld = centre + r * offset;
    vNormal = offset;
    vColour = iColour.wzyx;
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
