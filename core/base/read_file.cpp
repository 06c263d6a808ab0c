#include "core/base/read_file.hpp"

#include <cerrno>
#include <fstream>
#include <iterator>

namespace sprout {

std::optional<std::string> readFile(const std::filesystem::path& path) {
    std::error_code ec;
    const auto type = std::filesystem::status(path, ec).type();
    if (type == std::filesystem::file_type::not_found) {
        errno = ENOENT;
        return std::nullopt;
    }
    if (type == std::filesystem::file_type::directory) {
        errno = EISDIR;
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return std::nullopt;
    return bytes;
}

}  // namespace sprout
