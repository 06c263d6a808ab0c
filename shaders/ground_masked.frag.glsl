#version 330 core
#include "common"
// ground.frag with the plant's shadow read from its texture (ground_shadow.frag): moving
// frames on a software rasteriser.
in vec3 vWorld;
in vec2 vLocal;
uniform vec3 uGroundColour;
uniform sampler2D uGroundShadow;
out vec4 fragColour;
void main() {
    float r = length(vLocal);
    if (r > 1.0) discard;
    vec3 v = normalize(uEye - vWorld);
    vec3 n = v.y < 0.0 ? vec3(0.0, -1.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 c = shadeVisible(uGroundColour, n, v, 0.0, texture(uGroundShadow, vLocal * 0.5 + 0.5).r);
    fragColour = vec4(c, 1.0 - smoothstep(0.55, 1.0, r));
}
