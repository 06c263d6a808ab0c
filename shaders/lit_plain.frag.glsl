#version 330 core
#include "common"
// lit.frag without shadows (shadeWith's note): moving frames with no shadow pass.
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
out vec4 fragColour;
uniform float uSpecular;
void main() {
    fragColour = vec4(shadeWith(vColour.rgb, vWorld, vNormal, uSpecular, false), 1.0);
}
