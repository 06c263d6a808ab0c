#version 330 core
#include "polygon_inputs"
// polygon.vert with each vertex's place in its texture image (issue 53): the textured
// triangles, read through a vertex array that adds their u, v (Renderer::Impl::drawTextured).
layout(location = 3) in vec2 aUV;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
out vec2 vUV;
void main() {
    vWorld = aPosition;
    vNormal = aNormal;
    vColour = aColour.wzyx;
    vUV = aUV;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
