#version 330 core
// Shadow map pass of the textured triangles: the image's clear parts cast no shadow.
in vec2 vUV;
uniform sampler2D uImage;
void main() {
    if (texture(uImage, vec2(vUV.x, 1.0 - vUV.y)).a < 0.5) discard;
}
