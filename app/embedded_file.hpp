#pragma once
// Files compiled into the binary (presets, shaders) by cmake/EmbedFiles.cmake.
#include <span>
#include <string_view>

namespace sprout {

struct EmbeddedFile {
    std::string_view stem;      // "fern"
    std::string_view fileName;  // "fern.lsys"
    std::string_view data;
};

}  // namespace sprout
