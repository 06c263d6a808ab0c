#version 330 core
// Only a filtered lookup: llvmpipe draws such a quad on its fast path for plain texturing
// (stretch.vert).
in vec2 vUv;
uniform sampler2D uPicture;
out vec4 fragColour;
void main() { fragColour = texture(uPicture, vUv); }
