#version 330 core
// The picture, filtered (stretch.vert).
in vec2 vUv;
uniform sampler2D uPicture;
out vec4 fragColour;
void main() { fragColour = texture(uPicture, vUv); }
