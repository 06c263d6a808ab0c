#version 330 core
#include "common"
// The plant's shadow on the ground, as the ground's lookups find it (ground.frag), averaged
// over each texel: drawn once into a texture over the ground's square (ground.vert with
// uViewProj mapping it to the whole target) for the moving frames of a software rasteriser,
// which read it with one lookup a pixel (ground_masked.frag) instead of nine. A texel spans
// several of the shadow map's: 4x4 lookups across it, so that a thin stem's shadow falls on
// all the texels it crosses, not on a dotted line of them.
in vec3 vWorld;
in vec2 vLocal;
out vec4 fragColour;
void main() {
    vec4 lc = uLightViewProj * vec4(vWorld + vec3(0.0, 1.0, 0.0) * uShadowTexel * 1.5, 1.0);
    vec3 c = lc.xyz / lc.w * 0.5 + 0.5;
    vec2 across = dFdx(c.xy), down = dFdy(c.xy);  // one texel of this texture, in the map
    float s = 0.0;
    for (int x = 0; x < 4; ++x)
        for (int y = 0; y < 4; ++y) {
            vec2 at = c.xy + across * (float(x) - 1.5) / 4.0 + down * (float(y) - 1.5) / 4.0;
            s += (at.x < 0.0 || at.x > 1.0 || at.y < 0.0 || at.y > 1.0 || c.z > 1.0) ? 1.0 : texture(uShadowMap, vec3(at, c.z - 0.0015));
        }
    fragColour = vec4(s / 16.0, 0.0, 0.0, 1.0);
}
