#version 330 core
// The multisampled image resolved: each pixel the mean of its samples, summed in order and
// scaled, as Mesa's own resolve does it (u_blitter), so that the picture is the same one.
// glBlitFramebuffer did this on llvmpipe at the cost of building its blitter's shaders for each
// process (40-50 ms of a small plant's `sprout render`); a program of ours comes from the
// shader cache.
uniform sampler2DMS uImage;
uniform int uSamples;
uniform float uScale;    // 1 / uSamples
uniform ivec2 uOffset;   // the target's pixel where the image's first one goes
out vec4 fragColour;
void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy) - uOffset;
    vec4 sum = texelFetch(uImage, texel, 0);
    for (int i = 1; i < uSamples; ++i) sum += texelFetch(uImage, texel, i);
    fragColour = sum * uScale;
}
