#version 330 core
// The colour the vertices made (polygon_lit.vert).
in vec4 vColour;
out vec4 fragColour;
void main() { fragColour = vColour; }
