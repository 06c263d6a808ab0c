#pragma once
// Files compiled into the binary (presets, shaders, L-Py's Python modules) by
// cmake/EmbedFiles.cmake. In core/base, the lowest stage, so that every layer that embeds
// files (app/, lpy/) can name the struct without reaching into another's folder.
#include <span>
#include <string_view>

namespace sprout {

struct EmbeddedFile {
    std::string_view stem;      // "fern"
    std::string_view fileName;  // "fern.lsys"
    std::string_view data;
};

}  // namespace sprout
