#version 330 core
// A picture drawn at a fraction of the view's size, stretched over the view (Renderer::stretch):
// a quad from gl_VertexID whose texture coordinates, interpolated, put the outermost pixels'
// centres on the outermost drawn texels' centres (none beyond them is read).
uniform vec4 uMap;  // texture coordinates at the quad's lower-left corner, and their span
out vec2 vUv;
void main() {
    vec2 p = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    vUv = uMap.xy + p * uMap.zw;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
