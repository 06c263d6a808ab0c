#pragma once
// The one reader of a whole file: a grammar, a species beside a forest scene, a picture's
// recipe, a file a cpfg grammar or an L-Py model names, a script. A directory is refused (a
// std::ifstream opens one on Linux and reads nothing).
#include <filesystem>
#include <optional>
#include <string>

namespace sprout {

// The file's bytes as they are; nullopt when it cannot be read, errno saying why for messages
// written with strerror (ENOENT, EISDIR, or the open's own).
std::optional<std::string> readFile(const std::filesystem::path& path);

}  // namespace sprout
