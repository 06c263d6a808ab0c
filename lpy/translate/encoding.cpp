// A model file's bytes as the UTF-8 text the translation reads (translate.hpp's
// modelTextAsUtf8): what L-Py's Python reads of any file it runs. L-Py hands the file's bytes
// to Python's tokenizer (Lsystem::read, PyRun_String), which decodes them by the file's
// coding cookie (PEP 263) and otherwise as UTF-8, where a byte that is not UTF-8 passes
// unread in a comment. So: a cookie naming Latin-1 or Windows-1252 decodes the file with
// it; otherwise each valid UTF-8 sequence is kept and any other byte is read as the Latin-1
// character it is (a Latin-1 comment opens; a Latin-1 string literal, which L-Py refuses,
// keeps its letter).
#include <array>
#include <cctype>
#include <string>
#include <string_view>

#include "lpy/translate/translate.hpp"

namespace sprout::lpy {
namespace {

void appendCodePoint(std::string& out, unsigned cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

// Windows-1252's 0x80..0x9F (0: undefined there, read as Latin-1's control character).
constexpr std::array<unsigned short, 32> kCp1252 = {
    0x20AC, 0, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0, 0x017D, 0,
    0, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0, 0x017E, 0x0178};

// The length of the valid UTF-8 sequence at s[i] (0: none), as Python's decoder accepts it
// (no overlong forms, no surrogates, nothing past U+10FFFF).
size_t utf8Length(std::string_view s, size_t i) {
    const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned c = b(i);
    if (c < 0x80) return 1;
    const auto cont = [&](size_t k) { return k < s.size() && (b(k) & 0xC0) == 0x80; };
    if (c >= 0xC2 && c <= 0xDF) return cont(i + 1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
        if (!cont(i + 1) || !cont(i + 2)) return 0;
        if ((c == 0xE0 && b(i + 1) < 0xA0) || (c == 0xED && b(i + 1) >= 0xA0)) return 0;
        return 3;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        if (!cont(i + 1) || !cont(i + 2) || !cont(i + 3)) return 0;
        if ((c == 0xF0 && b(i + 1) < 0x90) || (c == 0xF4 && b(i + 1) >= 0x90)) return 0;
        return 4;
    }
    return 0;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (char& c : s) if (c == '_') c = '-';
    return s;
}

// PEP 263: `coding[:=]\s*([-\w.]+)` in a comment on the first or second line; empty if none.
std::string codingCookie(std::string_view text) {
    size_t start = 0;
    for (int line = 0; line < 2 && start < text.size(); ++line) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view l = text.substr(start, end - start);
        size_t k = l.find_first_not_of(" \t\f");
        if (k != std::string_view::npos && l[k] == '#') {
            size_t c = l.find("coding", k);
            if (c != std::string_view::npos && c + 6 < l.size() && (l[c + 6] == ':' || l[c + 6] == '=')) {
                size_t v = l.find_first_not_of(" \t", c + 7), e = v;
                while (e < l.size() && (std::isalnum(static_cast<unsigned char>(l[e])) || l[e] == '-' || l[e] == '_' || l[e] == '.'))
                    ++e;
                if (v != std::string_view::npos && e > v) return lower(std::string(l.substr(v, e - v)));
            }
        } else if (k != std::string_view::npos) {
            break;  // a line of code: no cookie after it
        }
        start = end + 1;
    }
    return {};
}

}  // namespace

std::string modelTextAsUtf8(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // a UTF-8 byte order mark
    const std::string cookie = codingCookie(bytes);
    const bool latin1 = cookie == "latin-1" || cookie == "iso-8859-1" || cookie == "iso8859-1" || cookie == "latin1" ||
                        cookie == "l1" || cookie == "iso-latin-1" || cookie == "8859";
    const bool cp1252 = cookie == "cp1252" || cookie == "windows-1252";
    std::string out;
    out.reserve(bytes.size() + bytes.size() / 8);
    for (size_t i = 0; i < bytes.size();) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        const size_t n = (latin1 || cp1252) ? (c < 0x80 ? 1 : 0) : utf8Length(bytes, i);
        if (n > 0) {
            out.append(bytes.substr(i, n));
            i += n;
            continue;
        }
        unsigned cp = c;
        if (cp1252 && c >= 0x80 && c <= 0x9F && kCp1252[c - 0x80]) cp = kCp1252[c - 0x80];
        appendCodePoint(out, cp);
        ++i;
    }
    return out;
}

}  // namespace sprout::lpy
