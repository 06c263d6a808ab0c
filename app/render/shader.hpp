#pragma once
// GLSL programs built from the shaders embedded from shaders/ (see cmake/EmbedFiles.cmake).
#include <string>
#include <string_view>

namespace sprout::render {

// Compiles shaders/<vertex>.glsl and shaders/<fragment>.glsl (by stem) into a program;
// returns 0 and fills `error` with the compiler log on failure.
unsigned buildProgram(std::string_view vertex, std::string_view fragment, std::string& error);

}  // namespace sprout::render
