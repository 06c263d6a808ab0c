// The environment drawn with the plant (core/environment_drawing.hpp): its opaque parts first
// (uPass 0, alpha 1, writing depth), then translucent shapes in two passes, the far side (1)
// and then the near side (2), so that a convex shape blends in the right order without sorting.
// Included by overlay.frag (lit with the shadow map) and overlay_plain.frag (without its
// lookups: moving frames on a software rasteriser, and pictures without shadows), which say
// which by kShadowed.
in vec3 vWorld;
in vec3 vNormal;
in vec4 vColour;
out vec4 fragColour;
uniform int uPass;
void main() {
    vec3 v = normalize(uEye - vWorld);
    float facing = dot(normalize(vNormal), v);
    bool opaque = vColour.a >= 0.99;
    if ((uPass == 0) != opaque) discard;
    if (uPass > 0 && (uPass == 2) != (facing >= 0.0)) discard;
    vec3 c = shadeWith(vColour.rgb, vWorld, vNormal, 0.25, kShadowed);
    // Glass: more opaque at its rim, where the eye looks through more of it.
    float a = opaque ? 1.0 : clamp(vColour.a * (0.55 + 0.9 * (1.0 - abs(facing))), 0.0, 1.0);
    fragColour = vec4(c, a);
}
