#version 330 core
// A big planar curve rasterised on the CPU (app/render/curve_raster.cpp): its coverage image
// blended in as ink over the background.
in vec2 vUv;
uniform sampler2D uCoverage;
uniform vec3 uInk;
out vec4 fragColour;
void main() { fragColour = vec4(uInk, texture(uCoverage, vUv).r); }
