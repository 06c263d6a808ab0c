#include "core/language/vlab/colours.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace sprout::vlab {

std::optional<MaterialSet> readMaterials(std::string_view bytes, std::string& error) {
    constexpr size_t kRecord = 15;
    if (bytes.empty()) {
        error = "byte 0: expected a material (15 bytes: index, transparency, ambient, diffuse, emission, specular, shininess); the file is empty";
        return std::nullopt;
    }
    if (bytes.size() % kRecord != 0) {
        const size_t at = bytes.size() - bytes.size() % kRecord;
        error = "byte " + std::to_string(at) + ": a material of " + std::to_string(bytes.size() - at) +
                " bytes; expected 15 (index, transparency, ambient, diffuse, emission, specular, shininess): the file is cut short";
        return std::nullopt;
    }
    MaterialSet out;
    auto byte = [&](size_t k) { return float(static_cast<unsigned char>(bytes[k])); };
    for (size_t at = 0; at < bytes.size(); at += kRecord) {
        Material m;
        m.transparency = byte(at + 1) / 255.0f;
        for (size_t c = 0; c < 3; ++c) {
            m.ambient[c] = byte(at + 2 + c) / 255.0f;
            m.diffuse[c] = byte(at + 5 + c) / 255.0f;
            m.emission[c] = byte(at + 8 + c) / 255.0f;
            m.specular[c] = byte(at + 11 + c) / 255.0f;
        }
        m.shininess = byte(at + 14);
        auto& slot = out.materials[static_cast<unsigned char>(bytes[at])];
        if (!slot) ++out.count;
        slot = m;
    }
    return out;
}

std::optional<ColourMap> readColourMap(std::string_view bytes, std::string& error) {
    if (bytes.size() < 768) {
        error = "byte " + std::to_string(bytes.size()) + ": expected 768 bytes (256 colours, red green blue each); the file ends at colour " +
                std::to_string(bytes.size() / 3);
        return std::nullopt;
    }
    ColourMap out;
    for (size_t k = 0; k < 256; ++k) {
        auto b = [&](size_t c) { return std::uint32_t(static_cast<unsigned char>(bytes[3 * k + c])); };
        out.colours[k] = b(0) << 16 | b(1) << 8 | b(2);
    }
    return out;
}

std::string writeMaterials(const MaterialSet& set) {
    std::string out;
    auto byte = [](float v) { return char(static_cast<unsigned char>(std::clamp(v * 255.0f, 0.0f, 255.0f))); };  // medit: (char)(v * 255)
    for (size_t i = 0; i < set.materials.size(); ++i) {
        if (!set.materials[i]) continue;
        const Material& m = *set.materials[i];
        out += char(static_cast<unsigned char>(i));
        out += byte(m.transparency);
        for (const auto* c : {&m.ambient, &m.diffuse, &m.emission, &m.specular})
            for (float v : *c) out += byte(v);
        out += char(static_cast<unsigned char>(std::clamp(m.shininess, 0.0f, 255.0f)));
    }
    return out;
}

std::string writeColourMap(const ColourMap& map) {
    std::string out;
    for (std::uint32_t c : map.colours) out += {char(c >> 16 & 0xFF), char(c >> 8 & 0xFF), char(c & 0xFF)};
    return out;
}

std::optional<int> colourSetNumber(std::string_view option) {
    if (option.size() < 2) return std::nullopt;
    std::string_view digits = option.substr(2);
    if (digits.empty() || !std::isdigit(static_cast<unsigned char>(digits[0]))) return 1;
    int n = 0;
    for (char ch : digits) {
        if (!std::isdigit(static_cast<unsigned char>(ch))) break;
        n = n * 10 + (ch - '0');
        if (n > 99) return std::nullopt;
    }
    return n < 12 ? std::optional<int>(n) : std::nullopt;
}

std::uint32_t materialColour(const Material& m) {
    auto channel = [&](size_t c) {
        const float v = m.emission[c] + m.diffuse[c];
        return std::uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const std::uint32_t alpha = std::uint32_t(std::lround((1.0f - m.transparency) * 255.0f));
    return channel(0) << 24 | channel(1) << 16 | channel(2) << 8 | alpha;
}

}  // namespace sprout::vlab
