#version 330 core
#include "common"
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
out vec4 fragColour;
uniform float uTranslucent;  // 1: the translucent triangles, blended by their alpha
void main() {
    fragColour = vec4(shadeMaterial(vColour.rgb, vWorld, vNormal, true), mix(1.0, vColour.a, uTranslucent));
}
