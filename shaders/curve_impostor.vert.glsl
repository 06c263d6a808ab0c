#version 330 core
// A big curve's coverage image from an earlier view, drawn as the quad its corners map to in
// this view (the map between two orthographic views of a plane is affine): while the view is
// dragged the curve moves without being rasterised again; the still view rasterises anew.
uniform vec2 uCorners[4];  // clip-space positions of the image's corners (bottom left, bottom right, top left, top right)
out vec2 vUv;
void main() {
    vUv = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    gl_Position = vec4(uCorners[gl_VertexID], 0.0, 1.0);
}
