#pragma once
// The one reader of a whole file: a grammar, a species beside a forest scene, a picture's
// recipe, a file a cpfg grammar or an L-Py model names, a script. A directory is refused (a
// std::ifstream opens one on Linux and reads nothing), and what went wrong is said as a value.
#include <filesystem>
#include <optional>
#include <string>

namespace sprout {

enum class ReadFailure { None, Missing, Directory, Unreadable };

// The file's bytes as they are; nullopt, with the reason in `why` when given (and in errno, for
// strerror), when it cannot be read.
std::optional<std::string> readFile(const std::filesystem::path& path, ReadFailure* why = nullptr);

}  // namespace sprout
