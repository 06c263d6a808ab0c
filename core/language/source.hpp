#pragma once
// Positions in grammar text. Parsers keep string_views into the line they read, so a
// position is a pointer difference and columns are counted in code points when reported.
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout {

struct SourceLine {
    int number = 0;
    std::string_view text;      // the whole line, without its newline, as parsed
    std::string_view original;  // as typed (columns are counted here); empty: same as text
};

// 1-based column of the byte at `offset`, counting UTF-8 code points.
int columnOf(std::string_view line, size_t offset);

class DiagnosticSink {
public:
    void error(const SourceLine& line, std::string_view at, std::string message);
    void warning(const SourceLine& line, std::string_view at, std::string message);
    void add(Diagnostic d) { m_diags.push_back(std::move(d)); }
    std::vector<Diagnostic>& all() { return m_diags; }
    size_t errorCount() const;

private:
    Diagnostic make(const SourceLine& line, std::string_view at, std::string message, Severity s);
    std::vector<Diagnostic> m_diags;
};

inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
std::string_view trim(std::string_view s);

}  // namespace sprout
