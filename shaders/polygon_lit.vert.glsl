#version 330 core
#include "common"
#include "polygon_inputs"
// polygon.vert lit at the vertices, no shadows (lit_plain.frag's light, per vertex):
// moving frames on a software rasteriser, whose fragments then only pass on a colour.
uniform float uTranslucent;  // 1: the translucent triangles, blended by their alpha
out vec4 vColour;
void main() {
    vColour = vec4(shadeMaterial(aColour.wzy, aPosition, aNormal, false), mix(1.0, aColour.x, uTranslucent));
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
