// The baked triangles' vertices (BakedVertex, Renderer's vertex arrays), for the programs that
// draw them: polygon.vert, polygon_lit.vert.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColour;  // bytes of 0xRRGGBBAA as stored: a, b, g, r
uniform mat4 uViewProj;
