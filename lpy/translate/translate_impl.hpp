#pragma once
// Internals of translate() (lpy/translate/translate.hpp), shared by its files:
//   text.cpp      scanning Python text (strings, parentheses, keywords, lines)
//   lstring.cpp   module classes and lstrings (L-Py's predefined modules, readLstring)
//   rules.cpp     a rule's header and body, and `produce` statements
//   translate.cpp           the file's sections, line by line (the driver)
// In a namespace of its own, not lpy::detail: the lpy/ libraries link together, and helper
// names such as trim() would meet.
#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lpy/translate/translate.hpp"

namespace sprout::lpy::translate_detail {

// Small text tests, inline as they were when this was one file (they run on every character).
inline bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
inline bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

inline std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

inline bool isIdentifier(std::string_view s) {
    if (s.empty() || !isIdentStart(s[0])) return false;
    return std::all_of(s.begin(), s.end(), isIdent);
}

inline bool startsWithWord(std::string_view t, std::string_view w) {
    return t.substr(0, w.size()) == w && (t.size() == w.size() || !isIdent(t[w.size()]));
}

inline int indentOf(std::string_view line) {
    int n = 0;
    while (size_t(n) < line.size() && (line[size_t(n)] == ' ' || line[size_t(n)] == '\t')) ++n;
    return n;
}

// text.cpp

// Skips a Python string literal starting at s[i] (a quote); returns the index after it.
size_t skipString(std::string_view s, size_t i);
// The delimiter of a triple-quoted string that `line` opens and leaves open (`"""` or `'''`),
// or empty: the lines up to its end are text, not sections or rules (as L-Py reads them).
std::string openTripleQuote(std::string_view line);
// The commas of `s` outside brackets and string literals.
std::vector<size_t> topCommas(std::string_view s);
// Splits the text inside a module's parentheses at top-level commas.
std::vector<std::string> splitArgs(std::string_view s);
// The index of the ')' closing the '(' at s[open], or npos.
size_t closeParen(std::string_view s, size_t open);
bool isNumberLiteral(std::string_view s);
bool isLiteral(std::string_view s);
// Finds `word` as a whole word in a line of Python, outside strings and comments.
size_t findKeyword(std::string_view line, std::string_view word, size_t from = 0);
// Where a Python comment starts in a line (outside strings), or the line's end.
size_t commentStart(std::string_view line);
std::vector<std::string> splitLines(std::string_view text);

// lstring.cpp

// The Python expression for an lstring: a list of class ids, (id, (args,)) tuples, and
// Python objects for `$v`.
std::string pythonLstring(const std::vector<WrittenModule>& mods);

// The translation of one file: its lines in, Translation out. Its methods are spread over
// translate.cpp (the sections), rules.cpp (rules and `produce`) and
// contexts.cpp (contexts tested in a body).
class Translator {
public:
    explicit Translator(std::string_view text) : m_lines(splitLines(text)) {}

    Translation run();
    void seed(const ModuleClasses& ids) { m_out.classes = ModuleClasses::seededFrom(ids); }
    // contexts.cpp: one pattern read alone (readContextPattern), what reading it said.
    ContextPattern contextPattern(std::string_view text);
    const std::vector<Diagnostic>& diagnostics() const { return m_out.diagnostics; }

private:
    enum class Mode { Python, Production, Decomposition, Interpretation };

    void error(int line, int col, std::string msg) { m_out.diagnostics.push_back({line, col, std::move(msg), Severity::Error}); }
    void warning(int line, int col, std::string msg) {
        m_out.diagnostics.push_back({line, col, std::move(msg), Severity::Warning});
    }

    // translate.cpp
    void translateMain(std::vector<std::string>& lines);
    void declareModules(std::string_view rest, int line, size_t index);
    void filterLine(std::string_view rest, bool consider, int line, int col);
    static bool keyword(std::string_view t, std::string_view word, std::string_view& rest);

    // rules.cpp
    void translateProduces(std::vector<std::string>& lines, size_t i);
    bool plainBody(const std::vector<std::string>& lines, size_t i, size_t last);
    // The names a pattern binds, in binding order, added to `names` (a name bound twice is an
    // error at `line`); sets each repetition's count of variables.
    void bindNames(std::vector<PatternModule>& ps, std::vector<std::string>& names, int line);

    // contexts.cpp
    void translateInContexts(std::string& line, int lineNo);
    PatternModule pattern(const WrittenModule& w, int line);
    std::vector<PatternModule> patterns(std::string_view text, int line, int col);
    void parseHeader(Rule& r, std::string_view h, int line);
    size_t rule(std::vector<std::string>& lines, size_t i, Mode mode);

    std::vector<std::string> m_lines, m_outLines;
    Translation m_out;
    int m_group = 0;
    int m_filter = -1;
    // translateProduces: the last `produce` read (not nproduce or makestring), and how many.
    std::vector<WrittenModule> m_produced;
    int m_produces = 0;
};

}  // namespace sprout::lpy::translate_detail
