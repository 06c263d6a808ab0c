// Instance data fetched from a buffer texture: llvmpipe pays ~10 us per instance of an
// instanced draw, so each draw instance carries a batch of uBatch mesh copies and each copy
// looks up its own segment (copy index aCopy). One draw call covers thousands of segments.
uniform usamplerBuffer uInstances;
uniform int uFirst;   // first instance of this draw in the buffer
uniform int uCount;   // instances in this draw
uniform int uBatch;   // mesh copies per draw instance
layout(location = 7) in float aCopy;

int instanceIndex() { return gl_InstanceID * uBatch + int(aCopy + 0.5); }
float fetchFloat(int i) { return uintBitsToFloat(texelFetch(uInstances, i).r); }
vec3 fetchVec3(int i) { return vec3(fetchFloat(i), fetchFloat(i + 1), fetchFloat(i + 2)); }
vec4 fetchColour(int i) {  // 0xRRGGBBAA
    uint v = texelFetch(uInstances, i).r;
    return vec4(float((v >> 24) & 255u), float((v >> 16) & 255u), float((v >> 8) & 255u), float(v & 255u)) / 255.0;
}
