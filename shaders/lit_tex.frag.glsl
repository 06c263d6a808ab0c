#version 330 core
#include "common"
// lit.frag for textured triangles: the image times the vertex colour (OpenGL's modulate, as
// PlantGL and cpfg draw a texture), lit; the image's clear parts (alpha below one half) cut
// away, as a leaf's outline. Images are stored top row first: v = 0 is the image's bottom.
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
in vec2 vUV;
out vec4 fragColour;
uniform sampler2D uImage;
uniform float uTranslucent;  // 1: translucent triangles, blended by their alpha times the image's
void main() {
    vec4 texel = texture(uImage, vec2(vUV.x, 1.0 - vUV.y));
    if (texel.a < 0.5) discard;
    fragColour = vec4(shadeMaterial(vColour.rgb * texel.rgb, vWorld, vNormal, true), mix(1.0, vColour.a * texel.a, uTranslucent));
}
