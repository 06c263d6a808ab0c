#version 330 core
#include "common"
// lit.frag without shadows (shadeWith's note): moving frames with no shadow pass.
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
out vec4 fragColour;
uniform float uTranslucent;  // 1: the translucent triangles, blended by their alpha
void main() {
    fragColour = vec4(shadeMaterial(vColour.rgb, vWorld, vNormal, false), mix(1.0, vColour.a, uTranslucent));
}
