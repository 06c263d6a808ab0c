#version 330 core
layout(location = 0) in vec2 aCorner;  // -1..1
uniform mat4 uViewProj;
uniform vec3 uCentre;
uniform float uRadius;
out vec3 vWorld;
out vec2 vLocal;
void main() {
    vLocal = aCorner;
    vWorld = uCentre + vec3(aCorner.x, 0.0, aCorner.y) * uRadius;
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
