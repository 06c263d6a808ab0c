#pragma once
// The readers' shared cursor over a function or contour file: its lines (any line ending),
// their whitespace-separated words with columns, numbers read as cpfg's sscanf("%f") and
// std::stof read them (to float, correctly rounded), and the problems, each at a line and column
// with what was expected there. Internal to core/language/vlab/.
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/read_file.hpp"
#include "core/language/vlab/curve_files.hpp"

namespace sprout::vlab_detail {

struct Word {
    std::string_view text;
    int col = 1;  // 1-based
};

inline std::vector<Word> words(std::string_view line) {
    std::vector<Word> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\f' || line[i] == '\v')) ++i;
        const size_t start = i;
        while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\f' || line[i] == '\v')) ++i;
        if (i > start) out.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return out;
}

// A number as strtof reads a whole word: a sign, digits, a point, an exponent (not inf, nan or
// hexadecimal: no editor writes them). Finite only.
inline std::optional<float> floatWord(std::string_view w) {
    if (!w.empty() && w[0] == '+') w.remove_prefix(1);
    if (w.empty() || w.size() > 64) return std::nullopt;
    for (char c : w)
        if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == 'e' || c == 'E' || c == '+')) return std::nullopt;
    float v = 0;
    auto r = std::from_chars(w.data(), w.data() + w.size(), v, std::chars_format::general);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// A whole number as sscanf("%d") reads a word, within [lo, hi].
inline std::optional<long> intWord(std::string_view w, long lo, long hi) {
    if (!w.empty() && w[0] == '+') w.remove_prefix(1);
    long v = 0;
    auto r = std::from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size() || v < lo || v > hi) return std::nullopt;
    return v;
}

class LineReader {
public:
    LineReader(std::string_view text, const std::string& file, std::vector<CurveFileDiagnostic>& out)
        : m_file(file), m_out(out) {
        size_t i = 0;
        while (i < text.size()) {
            size_t end = text.find_first_of("\r\n", i);
            if (end == std::string_view::npos) end = text.size();
            m_lines.push_back(text.substr(i, end - i));
            i = end;
            if (i < text.size() && text[i] == '\r') ++i;
            if (i < text.size() && text[i] == '\n') ++i;
        }
    }
    bool atEnd() {
        return m_next >= m_lines.size();
    }
    // The next line that is not blank (cpfg's fscanf skips blank lines between numbers).
    bool skipBlank() {
        while (m_next < m_lines.size() && words(m_lines[m_next]).empty()) ++m_next;
        return m_next < m_lines.size();
    }
    std::string_view peek() const { return m_next < m_lines.size() ? m_lines[m_next] : std::string_view(); }
    int lineNo() const { return int(m_next) + 1; }
    void advance() { ++m_next; }

    void error(int line, int col, std::string message, bool warning = false) {
        if (m_out.size() < 64) m_out.push_back({m_file, line, col, std::move(message), warning});
    }
    // The words after `key` (e.g. "points:") on the next non-blank line, which must start with
    // it; the line is consumed. An error naming `expected` when it does not.
    std::optional<std::vector<Word>> keyed(std::string_view key, const std::string& expected) {
        if (!skipBlank()) {
            error(lineNo(), 1, "the file ends where " + expected + " was expected");
            return std::nullopt;
        }
        std::vector<Word> w = words(peek());
        if (w.empty() || w[0].text != key) {
            error(lineNo(), w.empty() ? 1 : w[0].col, "expected " + expected + " here");
            return std::nullopt;
        }
        advance();
        w.erase(w.begin());
        return w;
    }
    // One whole number after `key`, within [lo, hi].
    std::optional<long> keyedInt(std::string_view key, long lo, long hi, const std::string& what) {
        const int line = lineNo();
        auto w = keyed(key, "'" + std::string(key) + " " + what + "'");
        if (!w) return std::nullopt;
        std::optional<long> v = w->empty() ? std::nullopt : intWord((*w)[0].text, lo, hi);
        if (!v)
            error(line, w->empty() ? int(key.size()) + 2 : (*w)[0].col,
                  "expected " + what + " after '" + std::string(key) + "' (a whole number from " + std::to_string(lo) +
                      " to " + std::to_string(hi) + ")");
        return v;
    }

private:
    const std::string& m_file;
    std::vector<CurveFileDiagnostic>& m_out;
    std::vector<std::string_view> m_lines;
    size_t m_next = 0;
};

// A file read whole and given to `read`; a file that cannot be read is one diagnostic naming it.
template <class Read, class F>
Read fromFile(const std::filesystem::path& path, F read) {
    errno = 0;
    std::optional<std::string> text = readFile(path);
    if (!text) {
        Read r;
        const int err = errno;
        r.diagnostics.push_back({path.string(), 0, 0, std::string("cannot read the file: ") +
                                                          (err ? std::strerror(err) : "unknown error")});
        return r;
    }
    return read(*text);
}

inline bool noErrors(const std::vector<CurveFileDiagnostic>& d) {
    for (const CurveFileDiagnostic& x : d)
        if (!x.warning) return false;
    return true;
}

}  // namespace sprout::vlab_detail
