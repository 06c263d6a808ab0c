// The grammar inside a PNG that Sprout wrote: its uncompressed iTXt (or tEXt) chunk with the
// keyword "lsys" (or "ifs", "forest"). No image decoding, so core needs no libpng.
#include <cstdint>
#include <string>

#include "core/language/import/import.hpp"

namespace sprout {

std::optional<std::string> pngTextChunk(std::string_view png, std::string_view keyword, std::string& error) {
    static const char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
    if (png.size() < 8 || png.substr(0, 8) != std::string_view(kSignature, 8)) {
        error = "is not a PNG file";
        return std::nullopt;
    }
    auto be32 = [&](size_t at) {
        return std::uint32_t(std::uint8_t(png[at])) << 24 | std::uint32_t(std::uint8_t(png[at + 1])) << 16 |
               std::uint32_t(std::uint8_t(png[at + 2])) << 8 | std::uint32_t(std::uint8_t(png[at + 3]));
    };
    bool compressed = false;
    for (size_t at = 8; at + 12 <= png.size();) {
        const std::uint32_t length = be32(at);
        if (length > png.size() - at - 12) {
            error = "is a damaged PNG file (a chunk runs past the end at byte " + std::to_string(at) + ")";
            return std::nullopt;
        }
        std::string_view type = png.substr(at + 4, 4), data = png.substr(at + 8, length);
        at += 12 + size_t(length);
        if (type == "IEND") break;
        if (type != "tEXt" && type != "iTXt") continue;
        size_t nul = data.find('\0');
        if (nul == std::string_view::npos || data.substr(0, nul) != keyword) continue;
        std::string_view rest = data.substr(nul + 1);
        if (type == "tEXt") return std::string(rest);
        // iTXt: compression flag, method, language tag\0, translated keyword\0, text.
        if (rest.size() < 2) continue;
        if (rest[0] != 0) {
            compressed = true;
            continue;
        }
        size_t lang = rest.find('\0', 2);
        if (lang == std::string_view::npos) continue;
        size_t translated = rest.find('\0', lang + 1);
        if (translated == std::string_view::npos) continue;
        return std::string(rest.substr(translated + 1));
    }
    error = compressed ? "holds a compressed grammar, which Sprout does not read" : "";
    return std::nullopt;
}

ImportResult importPng(std::string_view png) {
    ImportResult r;
    std::string error;
    for (const char* key : {"lsys", "ifs", "forest"}) {
        if (auto text = pngTextChunk(png, key, error)) {
            r.text = std::move(*text);
            r.source = FileKind::Png;
            r.kind = std::string_view(key) == "ifs"      ? FileKind::Ifs
                     : std::string_view(key) == "forest" ? FileKind::Forest
                                                         : detectFileKind("", r.text);  // .lsys or cpfg
            return r;
        }
        if (!error.empty()) break;
    }
    if (error.empty()) error = "is a picture without a grammar in it (Sprout's pictures carry theirs; this one was not written by Sprout)";
    r.diagnostics.push_back({0, 0, error, Severity::Error});
    return r;
}

}  // namespace sprout
