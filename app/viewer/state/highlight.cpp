// The editor's colours: each line of every language Sprout opens cut into spans of tokens.
//
// Index of this file:
//   [SECTION] The lexer
//   [SECTION] Rules and settings
//   [SECTION] Comments, by language
//   [SECTION] Lines, by language
//   [SECTION] A line highlighted
//   [SECTION] Brackets

#include "app/viewer/state/highlight.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace sprout::viewer::editor {
namespace {

bool alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// [SECTION] The lexer
struct Lexer {
    std::string_view s;
    std::vector<Span>& out;
    void add(int b, int e, Token t) {
        if (e > b) out.push_back({b, e, t});
    }
    // A number at i: digits, a point, an exponent.
    int number(int i) const {
        int j = i;
        while (j < int(s.size()) && (digit(s[size_t(j)]) || s[size_t(j)] == '.')) ++j;
        if (j < int(s.size()) && (s[size_t(j)] == 'e' || s[size_t(j)] == 'E')) {
            int k = j + 1;
            if (k < int(s.size()) && (s[size_t(k)] == '+' || s[size_t(k)] == '-')) ++k;
            if (k < int(s.size()) && digit(s[size_t(k)])) {
                j = k;
                while (j < int(s.size()) && digit(s[size_t(j)])) ++j;
            }
        }
        return j;
    }
    // An expression from i up to `end` (parameters, numbers, operators, brackets).
    void expression(int i, int end) {
        while (i < end) {
            const char c = s[size_t(i)];
            if (c == ' ' || c == '\t') {
                ++i;
            } else if (digit(c) || (c == '.' && i + 1 < end && digit(s[size_t(i + 1)]))) {
                const int j = number(i);
                add(i, j, Token::Number);
                i = j;
            } else if (alpha(c)) {
                int j = i;
                while (j < end && alnum(s[size_t(j)])) ++j;
                add(i, j, Token::Parameter);
                i = j;
            } else if (c == '(' || c == ')' || c == '{' || c == '}' || c == '[' || c == ']') {
                add(i, i + 1, Token::Bracket);
                ++i;
            } else {
                add(i, i + 1, Token::Operator);
                ++i;
            }
        }
    }
    // A quoted string from i (at its quote) to its closing quote or the end; its end.
    int quoted(int i, int end) {
        const char q = s[size_t(i)];
        int j = i + 1;
        for (; j < end && s[size_t(j)] != q; ++j)
            if (s[size_t(j)] == '\\') ++j;
        j = std::min(end, j + 1);
        add(i, j, Token::String);
        return j;
    }
    // Python (an L-Py model's preamble, rule bodies, INITIALISATION part): keywords, names,
    // numbers, strings; `produce` / `nproduce` followed by the lstring they make.
    void python(int i, int end) {
        static const std::string_view keywords[] = {
            "def", "class", "import", "from", "as", "return", "if", "elif", "else", "for", "while", "in", "not", "and", "or",
            "is", "global", "nonlocal", "lambda", "True", "False", "None", "pass", "break", "continue", "with", "try", "except",
            "finally", "raise", "assert", "yield", "del"};
        while (i < end) {
            const char c = s[size_t(i)];
            if (c == ' ' || c == '\t') {
                ++i;
            } else if (c == '\'' || c == '"') {
                i = quoted(i, end);
            } else if (digit(c) || (c == '.' && i + 1 < end && digit(s[size_t(i + 1)]))) {
                const int j = number(i);
                add(i, j, Token::Number);
                i = j;
            } else if (alpha(c)) {
                int j = i;
                while (j < end && alnum(s[size_t(j)])) ++j;
                const std::string_view word = s.substr(size_t(i), size_t(j - i));
                if (word == "produce" || word == "nproduce" || word == "nsproduce") {
                    add(i, j, Token::Keyword);
                    modules(j, end);
                    return;
                }
                bool keyword = false;
                for (std::string_view k : keywords) keyword = keyword || k == word;
                add(i, j, keyword ? Token::Keyword : Token::Parameter);
                i = j;
            } else if (c == '(' || c == ')' || c == '{' || c == '}' || c == '[' || c == ']') {
                add(i, i + 1, Token::Bracket);
                ++i;
            } else {
                add(i, i + 1, Token::Operator);
                ++i;
            }
        }
    }
    // A module string from i to end: names, brackets, and each module's arguments.
    void modules(int i, int end) {
        while (i < end) {
            const char c = s[size_t(i)];
            if (c == ' ' || c == '\t' || c == ',') {
                ++i;
            } else if (c == '[' || c == ']' || c == '{' || c == '}') {
                add(i, i + 1, Token::Bracket);
                ++i;
            } else if (c == '(') {  // arguments up to the matching ')'
                int depth = 0, j = i;
                for (; j < end; ++j) {
                    depth += s[size_t(j)] == '(' ? 1 : s[size_t(j)] == ')' ? -1 : 0;
                    if (depth == 0) break;
                }
                add(i, i + 1, Token::Bracket);
                expression(i + 1, j);
                if (j < end) add(j, j + 1, Token::Bracket);
                i = j + 1;
            } else {
                // One module: ?E, @M, ~l take their letter; a name runs on over letters and digits
                // only where the language has long names (an identifier here is one module each letter
                // in .lsys, but colour does not tell them apart).
                int j = i + 1;
                if ((c == '?' || c == '@' || c == '~') && j < end && alpha(s[size_t(j)])) ++j;
                else if (alpha(c))
                    while (j < end && alnum(s[size_t(j)])) ++j;
                add(i, j, Token::Module);
                i = j;
            }
        }
    }
};

// [SECTION] Rules and settings
// The first `->` / `-->` / `→` of a line that is not inside brackets, or npos.
size_t arrow(std::string_view s, size_t& length) {
    int depth = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        depth += c == '(' || c == '{' ? 1 : c == ')' || c == '}' ? -1 : 0;
        if (depth > 0) continue;
        if (s.compare(i, 3, "-->") == 0) return length = 3, i;
        if (s.compare(i, 2, "->") == 0) return length = 2, i;
        if (s.compare(i, 3, "\xE2\x86\x92") == 0) return length = 3, i;
    }
    return std::string_view::npos;
}

// A rule: predecessor with its contexts and condition, the arrow, the successor and its
// probability.
void rule(Lexer& lx, int begin, int end, size_t at, size_t arrowLength) {
    const std::string_view s = lx.s;
    // Before the arrow: contexts (< >), then ':' and a condition.
    int colon = -1, depth = 0;
    for (int i = begin; i < int(at); ++i) {
        const char c = s[size_t(i)];
        depth += c == '(' || c == '{' ? 1 : c == ')' || c == '}' ? -1 : 0;
        if (depth == 0 && c == ':') {
            colon = i;
            break;
        }
    }
    const int predEnd = colon >= 0 ? colon : int(at);
    int i = begin;
    while (i < predEnd) {  // modules, split at the context marks
        int j = i;
        while (j < predEnd && s[size_t(j)] != '<' && s[size_t(j)] != '>') {
            if (s[size_t(j)] == '(') {
                int d = 0;
                for (; j < predEnd; ++j) {
                    d += s[size_t(j)] == '(' ? 1 : s[size_t(j)] == ')' ? -1 : 0;
                    if (d == 0) break;
                }
            }
            ++j;
        }
        lx.modules(i, std::min(j, predEnd));
        if (j < predEnd) lx.add(j, j + 1, Token::Operator);
        i = j + 1;
    }
    if (colon >= 0) {
        lx.add(colon, colon + 1, Token::Operator);
        lx.expression(colon + 1, int(at));
    }
    lx.add(int(at), int(at + arrowLength), Token::Arrow);
    // After the arrow: the successor, then ': probability' (outside brackets).
    int prob = -1;
    depth = 0;
    for (int k = int(at + arrowLength); k < end; ++k) {
        const char c = s[size_t(k)];
        depth += c == '(' || c == '{' ? 1 : c == ')' || c == '}' ? -1 : 0;
        if (depth == 0 && c == ':') {
            prob = k;
            break;
        }
    }
    lx.modules(int(at + arrowLength), prob >= 0 ? prob : end);
    if (prob >= 0) lx.add(prob, end, Token::Probability);
}

// "key: value": a setting, its value numbers and words (the axiom's value as modules).
bool setting(Lexer& lx, int begin, int end, bool axiomModules) {
    const std::string_view s = lx.s;
    int i = begin;
    while (i < end && (alnum(s[size_t(i)]) || s[size_t(i)] == ' ' || s[size_t(i)] == '-')) ++i;
    if (i >= end || s[size_t(i)] != ':' || i == begin || !alpha(s[size_t(begin)])) return false;
    lx.add(begin, i + 1, Token::Setting);
    std::string key(s.substr(size_t(begin), size_t(i - begin)));
    for (char& c : key) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (axiomModules && (key == "axiom" || key == "ignore" || key == "consider" || key == "module")) lx.modules(i + 1, end);
    else lx.expression(i + 1, end);
    return true;
}

// [SECTION] Comments, by language
// Python's comments: '#' outside a string; where the line's code ends.
int endOfPython(std::string_view line) {
    char quote = 0;
    for (int i = 0; i < int(line.size()); ++i) {
        const char c = line[size_t(i)];
        if (quote) {
            if (c == '\\') ++i;
            else if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '#') {
            return i;
        }
    }
    return int(line.size());
}

// The cpfg family's comments: block comments carry over lines; // runs to the end. Where the
// line's code begins and ends; false when the whole line is a comment (highlighted).
bool cpfgCode(std::string_view line, LineState& state, Lexer& lx, int& begin, int& end) {
    const int n = int(line.size());
    if (state.inBlockComment) {
        const size_t close = line.find("*/");
        if (close == std::string_view::npos) {
            lx.add(0, n, Token::Comment);
            return false;
        }
        lx.add(0, int(close) + 2, Token::Comment);
        begin = int(close) + 2;
        state.inBlockComment = false;
    }
    for (int i = begin; i + 1 < n; ++i) {
        if (line.compare(size_t(i), 2, "//") == 0) {
            end = i;
            break;
        }
        if (line.compare(size_t(i), 2, "/*") == 0) {
            const size_t close = line.find("*/", size_t(i) + 2);
            if (close == std::string_view::npos) {
                state.inBlockComment = true;
                end = i;
                break;
            }
            // A comment inside the line: highlight around it (rare; the rest is plain).
            end = i;
            break;
        }
    }
    return true;
}

// [SECTION] Lines, by language
// An L-Py line: the L-system's lines (sections, settings, rules written with an arrow, module
// declarations) as the cpfg family's; everything else is Python.
void highlightLpy(Lexer& lx, std::string_view line, std::string_view body, int begin, int end) {
    static const char* words[] = {"endlsystem", "decomposition", "homomorphism", "production", "interpretation",
                                  "module", "endgroup", "group", "consider", "ignore"};
    bool keyword = false;
    for (const char* w : words) {
        const std::string_view ws(w);
        if (body.compare(0, ws.size(), ws) == 0 && (body.size() == ws.size() || !alnum(body[ws.size()]))) {
            lx.add(begin, begin + int(ws.size()), Token::Keyword);
            int j = begin + int(ws.size());
            while (j < end && line[size_t(j)] == ' ') ++j;
            if (j < end && line[size_t(j)] == ':') lx.add(j, j + 1, Token::Operator), ++j;
            lx.modules(j, end);
            keyword = true;
            break;
        }
    }
    if (keyword) return;
    static const char* settings[] = {"Axiom:", "derivation length:", "maximum depth:", "decomposition maximum depth:"};
    bool isSetting = false;
    for (const char* w : settings) isSetting = isSetting || body.rfind(w, 0) == 0;
    size_t len = 0;
    const size_t at = arrow(body, len);
    if (isSetting) {
        const int colon = begin + int(body.find(':'));
        lx.add(begin, colon + 1, Token::Setting);
        if (body.rfind("Axiom:", 0) == 0) lx.modules(colon + 1, end);
        else lx.python(colon + 1, end);
    } else if (at != std::string_view::npos && line.substr(size_t(begin) + at, len) == "-->") {
        rule(lx, begin, end, size_t(begin) + at, len);
    } else {
        lx.python(begin, end);
    }
}

// A cpfg line: #define and #include, section keywords, rules, settings.
void highlightCpfg(Lexer& lx, std::string_view line, std::string_view body, int begin, int end) {
    if (body[0] == '#') {  // #define, #include
        int j = begin + 1;
        while (j < end && alpha(line[size_t(j)])) ++j;
        lx.add(begin, j, Token::Keyword);
        lx.expression(j, end);
        return;
    }
    static const char* words[] = {"endlsystem", "decomposition", "homomorphism", "production", "interpretation",
                                  "produce", "nproduce", "module", "endgroup", "group"};
    bool keyword = false;
    for (const char* w : words) {
        const std::string_view ws(w);
        if (body.compare(0, ws.size(), ws) == 0 && (body.size() == ws.size() || !alnum(body[ws.size()]))) {
            lx.add(begin, begin + int(ws.size()), Token::Keyword);
            lx.modules(begin + int(ws.size()), end);
            keyword = true;
            break;
        }
    }
    if (keyword) return;
    size_t len = 0;
    const size_t at = arrow(body, len);
    if (at != std::string_view::npos) rule(lx, begin, end, size_t(begin) + at, len);
    else setting(lx, begin, end, true) || (lx.modules(begin, end), true);
}

// An Lparser or Fractint line: "X=successor" rules; Fractint's "Name {", "Angle 6", "Axiom F";
// Lparser's numbers.
void highlightImported(Lexer& lx, FileKind kind, std::string_view line, std::string_view body, int begin, int end) {
    const size_t eq = body.find('=');
    if (eq != std::string_view::npos) {
        lx.modules(begin, begin + int(eq));
        lx.add(begin + int(eq), begin + int(eq) + 1, Token::Arrow);
        lx.modules(begin + int(eq) + 1, end);
    } else if (alpha(body[0])) {
        int j = begin;
        while (j < end && alnum(line[size_t(j)])) ++j;
        std::string word(line.substr(size_t(begin), size_t(j - begin)));
        for (char& c : word) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (word == "angle" || word == "axiom") {
            lx.add(begin, j, Token::Keyword);
            if (word == "axiom") lx.modules(j, end);
            else lx.expression(j, end);
        } else if (kind == FileKind::Fractint) {
            lx.add(begin, j, Token::Setting);  // a system's name
            lx.expression(j, end);
        } else {
            lx.modules(begin, end);
        }
    } else {
        lx.expression(begin, end);
    }
}

}  // namespace

// [SECTION] A line highlighted
void highlightLine(FileKind kind, std::string_view line, LineState& state, std::vector<Span>& out) {
    Lexer lx{line, out};
    const int n = int(line.size());
    int end = n;
    int begin = 0;
    if (kind == FileKind::Lpy) {
        end = endOfPython(line);
    } else if (cpfgFamily(kind)) {
        if (!cpfgCode(line, state, lx, begin, end)) return;
    } else {
        const char mark = kind == FileKind::Fractint ? ';' : '#';
        const size_t c = line.find(mark);
        if (c != std::string_view::npos) end = int(c);
    }
    // Leading blanks.
    while (begin < end && (line[size_t(begin)] == ' ' || line[size_t(begin)] == '\t')) ++begin;
    const std::string_view body = line.substr(size_t(begin), size_t(end - begin));
    if (!body.empty()) switch (kind) {
        case FileKind::Lpy:
            highlightLpy(lx, line, body, begin, end);
            break;
        case FileKind::Cpfg:
            highlightCpfg(lx, line, body, begin, end);
            break;
        case FileKind::Lsys: {
            size_t len = 0;
            const size_t at = arrow(body, len);
            if (at != std::string_view::npos) rule(lx, begin, end, size_t(begin) + at, len);
            else if (!setting(lx, begin, end, true)) lx.modules(begin, end);
            break;
        }
        case FileKind::Lparser:
        case FileKind::Fractint:
            highlightImported(lx, kind, line, body, begin, end);
            break;
        case FileKind::Ifs:
            lx.expression(begin, end);
            break;
        case FileKind::Forest:
        case FileKind::Png:
            if (!setting(lx, begin, end, false)) lx.expression(begin, end);
            break;
    }
    if (end < n) lx.add(end, n, Token::Comment);
}

// [SECTION] Brackets
std::optional<Pos> matchingBracket(const TextModel& t, Pos at) {
    auto charAt = [&](Pos p) { return p.col < int(t.line(p.line).size()) ? t.line(p.line)[size_t(p.col)] : '\0'; };
    static const std::string open = "([{", close = ")]}";
    Pos p = at;
    char c = charAt(p);
    if (open.find(c) == std::string::npos && close.find(c) == std::string::npos) {
        if (p.col == 0) return std::nullopt;
        --p.col;
        c = charAt(p);
        if (c == '\0' || (open.find(c) == std::string::npos && close.find(c) == std::string::npos)) return std::nullopt;
    }
    const bool forward = open.find(c) != std::string::npos;
    const char want = forward ? close[open.find(c)] : open[close.find(c)];
    int depth = 0;
    for (int line = p.line, col = p.col; line >= 0 && line < t.lineCount();) {
        const std::string& l = t.line(line);
        for (; col >= 0 && col < int(l.size()); col += forward ? 1 : -1) {
            if (l[size_t(col)] == c) ++depth;
            else if (l[size_t(col)] == want && --depth == 0) return Pos{line, col};
        }
        line += forward ? 1 : -1;
        if (line < 0 || line >= t.lineCount()) break;
        col = forward ? 0 : int(t.line(line).size()) - 1;
    }
    return std::nullopt;
}

}  // namespace sprout::viewer::editor
