#version 330 core
#include "common"
// ground.frag without shadows (shadeWith's note): moving frames with no shadow pass.
in vec3 vWorld;
in vec2 vLocal;
uniform vec3 uGroundColour;
out vec4 fragColour;
void main() {
    float r = length(vLocal);
    if (r > 1.0) discard;
    vec3 c = shadeWith(uGroundColour, vWorld, vec3(0.0, 1.0, 0.0), 0.0, false);
    fragColour = vec4(c, 1.0 - smoothstep(0.55, 1.0, r));
}
