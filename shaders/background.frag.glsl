#version 330 core
in vec2 vUv;
uniform vec3 uTop;
uniform vec3 uBottom;
out vec4 fragColour;
void main() {
    float t = smoothstep(0.0, 1.0, vUv.y);
    fragColour = vec4(mix(uBottom, uTop, t), 1.0);
}
