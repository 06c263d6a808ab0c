#version 330 core
#include "common"
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
out vec4 fragColour;
uniform float uSpecular;
void main() {
    fragColour = vec4(shade(vColour.rgb, vWorld, vNormal, uSpecular), 1.0);
}
