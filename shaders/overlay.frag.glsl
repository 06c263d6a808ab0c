#version 330 core
#include "common"
const bool kShadowed = true;
#include "overlay_body"
