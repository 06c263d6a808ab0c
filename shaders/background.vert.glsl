#version 330 core
// A full-screen quad from gl_VertexID (a triangle strip of four): no buffers needed. (One
// oversized triangle left some 64x64 tiles unpainted on llvmpipe.)
out vec2 vUv;
void main() {
    vec2 p = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
