#include "core/base/read_file.hpp"

#include <cerrno>
#include <fstream>
#include <iterator>

namespace sprout {

std::optional<std::string> readFile(const std::filesystem::path& path, ReadFailure* why) {
    auto fail = [why](ReadFailure f) -> std::optional<std::string> {
        if (why) *why = f;
        return std::nullopt;
    };
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    // errno says it too, for messages written with strerror.
    if (status.type() == std::filesystem::file_type::not_found) return errno = ENOENT, fail(ReadFailure::Missing);
    if (status.type() == std::filesystem::file_type::directory) return errno = EISDIR, fail(ReadFailure::Directory);
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(ReadFailure::Unreadable);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return fail(ReadFailure::Unreadable);
    if (why) *why = ReadFailure::None;
    return bytes;
}

}  // namespace sprout
