#pragma once
// The only header through which app/render sees OpenGL (glad's 3.3 core loader). Nothing
// outside app/render includes it.
#include <glad/gl.h>
