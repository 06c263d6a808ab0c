#version 330 core
#include "polygon_inputs"
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    vWorld = aPosition;
    vNormal = aNormal;
    vColour = aColour.wzyx;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
