#version 330 core
// Shadow map pass of the translucent triangles: those at least half opaque cast a shadow
// (a vertex's alpha, 1 - its material's transparency).
in vec4 vColour;
void main() {
    if (vColour.a < 0.5) discard;
}
