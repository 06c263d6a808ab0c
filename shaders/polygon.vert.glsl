#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColour;
uniform mat4 uViewProj;
out vec3 vWorld;
out vec3 vNormal;
out vec4 vColour;
void main() {
    vWorld = aPosition;
    vNormal = aNormal;
    vColour = aColour.wzyx;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
