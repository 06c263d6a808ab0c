uniform vec3 uEye;

// Lighting shared by every lit surface: a sun with soft shadows (3x3 PCF), sky/ground
// hemisphere ambient, a little specular. Colours arrive as sRGB and are lit in linear space.
uniform vec3 uSunDir;       // towards the sun, normalised
uniform vec3 uSunColour;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
uniform mat4 uLightViewProj;
uniform sampler2DShadow uShadowMap;
uniform int uShadows;
uniform float uShadowTexel;  // world size of one shadow texel, for the normal offset

float sunVisibility(vec3 world, vec3 normal) {
    if (uShadows == 0) return 1.0;
    vec4 lc = uLightViewProj * vec4(world + normal * uShadowTexel * 1.5, 1.0);
    vec3 c = lc.xyz / lc.w * 0.5 + 0.5;
    if (c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z > 1.0) return 1.0;
    // Nine bilinear lookups a texel apart (x, y in -1..1) weigh the 4x4 texels around the
    // point by (1 - f, 1, 1, f) each way, f the point's place between texels; two bilinear
    // lookups each way weigh them so too: one over the first two texels, (1 - f) : 1, the
    // other over the last two, 1 : f, weighted by their sums. The same shadow in four
    // lookups: a software rasteriser spent most of a picture's time on the nine.
    vec2 size = vec2(textureSize(uShadowMap, 0));
    vec2 p = c.xy * size - 0.5;
    vec2 i = floor(p), f = p - i;
    vec2 wA = 2.0 - f, wB = 1.0 + f;
    vec2 a = (i - 0.5 + 1.0 / wA) / size, b = (i + 1.5 + f / wB) / size;
    float z = c.z - 0.0015;
    float s = wA.x * wA.y * texture(uShadowMap, vec3(a.x, a.y, z)) + wB.x * wA.y * texture(uShadowMap, vec3(b.x, a.y, z)) +
              wA.x * wB.y * texture(uShadowMap, vec3(a.x, b.y, z)) + wB.x * wB.y * texture(uShadowMap, vec3(b.x, b.y, z));
    return s / 9.0;
}

// Gamma 2.0 instead of 2.2: a square and a square root cost far less than pow() per
// fragment on a software rasteriser, and look the same here.
vec3 toLinear(vec3 c) { return c * c; }
vec3 toDisplay(vec3 c) { return sqrt(c); }

// Lit with the sun's visibility `vis` (1: in full sun). The programs drawn without shadows call
// it with 1 and leave the shadow map's lookups out of their code: a software rasteriser runs
// both sides of a branch on uShadows, so shadows switched off by a uniform still cost nine
// lookups a fragment (half a moving frame of a leafy plant).
// Lit with the sun's visibility `vis`, the normal `n` facing the eye, `v` towards the eye.
vec3 shadeVisible(vec3 baseSrgb, vec3 n, vec3 v, float specular, float vis) {
    vec3 base = toLinear(baseSrgb);
    float diffuse = max(dot(n, uSunDir), 0.0);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, n.y * 0.5 + 0.5);
    vec3 h = normalize(uSunDir + v);
    float nh = max(dot(n, h), 0.0);
    float nh2 = nh * nh, nh4 = nh2 * nh2, nh8 = nh4 * nh4, nh16 = nh8 * nh8;
    float spec = nh16 * nh16 * specular;  // (n.h)^32
    vec3 lit = base * (ambient + uSunColour * diffuse * vis) + uSunColour * spec * vis;
    return toDisplay(lit);
}

vec3 shadeWith(vec3 baseSrgb, vec3 world, vec3 normal, float specular, bool shadowed) {
    vec3 n = normalize(normal);
    vec3 v = normalize(uEye - world);
    if (dot(n, v) < 0.0) n = -n;  // double-sided: leaves, petals and polygons
    return shadeVisible(baseSrgb, n, v, specular, shadowed ? sunVisibility(world, n) : 1.0);
}

vec3 shade(vec3 baseSrgb, vec3 world, vec3 normal, float specular) { return shadeWith(baseSrgb, world, normal, specular, true); }

// A plant's surface: shadeWith's light with the surface's material (Renderer::Impl::plainLight,
// shineLight): the highlight in its specular colour at its exponent, and its emission added.
// Every surface but a shining material's has (0.1, 0.1, 0.1) at 32 and none: shadeWith's.
uniform vec3 uSpecular;
uniform float uShininess;
uniform vec3 uEmission;
vec3 shadeMaterial(vec3 baseSrgb, vec3 world, vec3 normal, bool shadowed) {
    vec3 n = normalize(normal);
    vec3 v = normalize(uEye - world);
    if (dot(n, v) < 0.0) n = -n;
    float vis = shadowed ? sunVisibility(world, n) : 1.0;
    vec3 base = toLinear(baseSrgb);
    float diffuse = max(dot(n, uSunDir), 0.0);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, n.y * 0.5 + 0.5);
    float spec = pow(max(dot(n, normalize(uSunDir + v)), 0.0), uShininess);
    vec3 lit = base * (ambient + uSunColour * diffuse * vis) + uSunColour * uSpecular * spec * vis + toLinear(uEmission);
    return toDisplay(lit);
}
