#pragma once
// Internal to app/plant: reading the Python an L-Py model's INITIALISATION part holds, as L-Py
// Studio writes it (lpy_objects.cpp's curves, lpy_materials.cpp's materials): spaces, words,
// numbers, and the parenthesis that closes another.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace sprout::python_text {

inline bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

inline size_t skipSpace(std::string_view t, size_t k) {
    while (k < t.size() && std::isspace(static_cast<unsigned char>(t[k]))) ++k;
    return k;
}

// `word` at k, spaces before it skipped: k moves past it.
inline bool eat(std::string_view t, size_t& k, std::string_view word) {
    const size_t at = skipSpace(t, k);
    if (t.substr(at, word.size()) != word) return false;
    k = at + word.size();
    return true;
}

inline std::optional<double> number(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    if (s.empty() || s.size() > 40) return std::nullopt;
    const std::string text(s);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// The ')' closing the '(' at `open` (strings skipped), or npos.
inline size_t closing(std::string_view t, size_t open) {
    int depth = 0;
    for (size_t k = open; k < t.size(); ++k) {
        const char c = t[k];
        if (c == '\'' || c == '"') {
            const size_t q = t.find(c, k + 1);
            if (q == std::string_view::npos) return q;
            k = q;
        } else if (c == '(') {
            ++depth;
        } else if (c == ')' && --depth == 0) {
            return k;
        }
    }
    return std::string_view::npos;
}


// A number as L-Py Studio writes one (six significant digits).
inline std::string formatted(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace sprout::python_text
