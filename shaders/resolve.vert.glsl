#version 330 core
// A quad over the viewport from gl_VertexID (a strip of four, as background.vert draws), with
// nothing to interpolate: resolve.frag reads its pixel by gl_FragCoord.
void main() {
    vec2 p = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
