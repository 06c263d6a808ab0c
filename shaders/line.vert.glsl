#version 330 core
// Stems thinner than about a pixel: plain lines (two vertices each, no instancing).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColour;  // bytes of 0xRRGGBBAA as stored: a, b, g, r
uniform mat4 uViewProj;
out vec4 vColour;
void main() {
    vColour = aColour.wzyx;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
