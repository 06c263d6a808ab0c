#version 330 core
uniform vec3 uInk;
out vec4 fragColour;
void main() { fragColour = vec4(uInk, 1.0); }
