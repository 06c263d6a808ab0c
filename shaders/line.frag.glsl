#version 330 core
#include "common"
// A line has no normal: light it as a stem seen from the side, half in the sun.
in vec4 vColour;
out vec4 fragColour;
void main() {
    vec3 base = toLinear(vColour.rgb);
    fragColour = vec4(toDisplay(base * (uSkyAmbient * 0.8 + uSunColour * 0.45)), 1.0);
}
