#version 330 core
#include "common"
const bool kShadowed = false;  // no shadow map lookups in the code (shadeWith's note)
#include "overlay_body"
