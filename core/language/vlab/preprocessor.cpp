// The C preprocessor over a VLab file, as cpfg runs `preproc` (or vlabcpp) before reading it.
//
// Index of this file:
//   [SECTION] Lines: comments blanked, continued lines joined
//   [SECTION] Macros put in place
//   [SECTION] Directives and conditions
//   [SECTION] A file's words

#include "core/language/vlab/preprocessor.hpp"

#include <algorithm>
#include <charconv>
#include <map>

namespace sprout::vlab {
namespace {

constexpr int kMaxIncludeDepth = 16;
constexpr size_t kMaxLineBytes = 1 << 20;    // one line's expansion
constexpr size_t kMaxTotalBytes = 4 << 20;   // all lines' expansions together
constexpr size_t kMaxExpansions = 1 << 20;   // macros put in place, over the whole file
constexpr size_t kMaxNesting = 256;          // macros inside macros
constexpr size_t kMaxProblems = 64;
constexpr size_t kMaxFiles = 256;

struct Pos {
    int line = 0, col = 0;
};

// A logical line: its text, and where each of its bytes was written.
struct Line {
    std::string text;
    std::vector<Pos> at;
};

struct Macro {
    bool function = false;
    std::vector<std::string> params;
    std::string body;
};

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool identStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool identChar(char c) { return identStart(c) || digit(c); }

std::string_view trim(std::string_view s) {
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// The identifier at the start of `s` ("" when none).
std::string_view identifierAt(std::string_view s) {
    if (s.empty() || !identStart(s[0])) return {};
    size_t n = 1;
    while (n < s.size() && identChar(s[n])) ++n;
    return s.substr(0, n);
}

class Preprocessor {
public:
    Preprocessor(Preprocessed& out, const IncludeReader& include) : m_out(out), m_include(include) {}
    void run(std::string text, std::uint16_t file, int depth);

private:
    struct Condition {
        bool parentActive = true, active = true, taken = false, sawElse = false;
        Pos at;
    };
    void problem(std::uint16_t file, Pos at, std::string message, Severity s = Severity::Error) {
        if (m_out.problems.size() < kMaxProblems) m_out.problems.push_back({file, {at.line, at.col, std::move(message), s}});
    }
    std::vector<Line> lines(std::string& text, std::uint16_t file);
    bool expand(std::string_view text, const Pos* at, Pos fixed, Line& out, std::uint16_t file);
    bool call(const std::string& name, const Macro& m, std::string_view text, size_t& i, Pos p, Line& out, std::uint16_t file);
    bool copy(char c, Pos p, Line& out, std::uint16_t file);
    void directive(const Line& l, size_t hash, std::uint16_t file, int depth, std::vector<Condition>& conditions);
    void define(std::string_view rest, Pos p, std::uint16_t file);
    void include(std::string_view rest, Pos p, std::uint16_t file, int depth);
    bool condition(std::string_view rest, Pos p, std::uint16_t file);
    void words(const Line& l, std::uint16_t file);

    Preprocessed& m_out;
    const IncludeReader& m_include;
    std::map<std::string, Macro> m_macros;
    std::vector<std::string> m_active;  // the macros being put in place, innermost last
    std::vector<std::string> m_reading;  // the files being read, for #include cycles
    size_t m_bytes = 0, m_expansions = 0;
    bool m_overflow = false;
};

// [SECTION] Lines: comments blanked, continued lines joined

std::vector<Line> Preprocessor::lines(std::string& text, std::uint16_t file) {
    // Comments become spaces (their line breaks stay), so that every byte keeps its column.
    for (size_t i = 0; i + 1 < text.size(); ++i) {
        if (text[i] == '/' && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n') text[i++] = ' ';
        } else if (text[i] == '/' && text[i + 1] == '*') {
            const size_t open = i;
            const size_t close = text.find("*/", i + 2);
            const size_t end = close == std::string::npos ? text.size() : close + 2;
            if (close == std::string::npos) {
                const int line = 1 + int(std::count(text.begin(), text.begin() + long(open), '\n'));
                const size_t lineStart = text.rfind('\n', open);
                problem(file, {line, int(open - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1},
                        "a comment '/*' is never closed with '*/'");
            }
            for (; i < end; ++i)
                if (text[i] != '\n') text[i] = ' ';
            --i;
        }
    }
    std::vector<Line> out;
    bool continued = false;
    int number = 0;
    for (size_t start = 0; start <= text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++number;
        std::string_view t(text.data() + start, end - start);
        if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
        if (!continued) out.emplace_back();
        Line& l = out.back();
        continued = !t.empty() && t.back() == '\\';
        if (continued) t.remove_suffix(1);
        for (size_t k = 0; k < t.size(); ++k) {
            l.text += t[k];
            l.at.push_back({number, int(k) + 1});
        }
        if (continued) l.text += ' ', l.at.push_back({number, int(t.size()) + 1});
        if (end == text.size()) break;
        start = end + 1;
    }
    return out;
}

// [SECTION] Macros put in place

bool Preprocessor::copy(char c, Pos p, Line& out, std::uint16_t file) {
    if (out.text.size() >= kMaxLineBytes || m_bytes >= kMaxTotalBytes) {
        if (!m_overflow) problem(file, p, "the #define names on this line expand to more than 1 MB of text (or the file's to 4 MB)");
        m_overflow = true;
        return false;
    }
    ++m_bytes;
    out.text += c;
    out.at.push_back(p);
    return true;
}

// `text` with the macros defined so far put in place, appended to `out`: each byte's position
// from `at`, or `fixed` for all of them (a macro's text, shown where its name was).
bool Preprocessor::expand(std::string_view text, const Pos* at, Pos fixed, Line& out, std::uint16_t file) {
    auto pos = [&](size_t i) { return at ? at[i] : fixed; };
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (digit(c) || (c == '.' && i + 1 < text.size() && digit(text[i + 1]))) {
            // A number as the preprocessor reads one (1e5, 2.5f): no name inside it is a macro.
            size_t j = i + 1;
            while (j < text.size() && (identChar(text[j]) || text[j] == '.' ||
                                       ((text[j] == '+' || text[j] == '-') && (text[j - 1] == 'e' || text[j - 1] == 'E'))))
                ++j;
            for (; i < j; ++i)
                if (!copy(text[i], pos(i), out, file)) return false;
            continue;
        }
        const std::string_view name = identifierAt(text.substr(i));
        const auto it = name.empty() ? m_macros.end() : m_macros.find(std::string(name));
        if (it == m_macros.end() || std::find(m_active.begin(), m_active.end(), name) != m_active.end()) {
            const size_t j = i + std::max<size_t>(name.size(), 1);
            for (; i < j; ++i)
                if (!copy(text[i], pos(i), out, file)) return false;
            continue;
        }
        if (++m_expansions > kMaxExpansions || m_active.size() >= kMaxNesting) {
            if (!m_overflow) problem(file, pos(i), "the #define names expand too many times (more than a million, or 256 inside each other)");
            m_overflow = true;
            return false;
        }
        const Pos p = pos(i);
        const std::string key(name);
        const Macro& m = it->second;  // stays valid: the map does not change while a line expands
        i += name.size();
        if (m.function) {
            size_t k = i;
            while (k < text.size() && space(text[k])) ++k;
            if (k >= text.size() || text[k] != '(') {  // the name alone: not a call
                for (char ch : key)
                    if (!copy(ch, p, out, file)) return false;
                continue;
            }
            i = k;
            if (!call(key, m, text, i, p, out, file)) return false;
            continue;
        }
        m_active.push_back(key);
        const bool ok = expand(m.body, nullptr, p, out, file);
        m_active.pop_back();
        if (!ok) return false;
    }
    return true;
}

// A function-like macro's call, `text[i]` its '(': its arguments put in place of its
// parameters, the result expanded again; `i` moves past the ')'.
bool Preprocessor::call(const std::string& name, const Macro& m, std::string_view text, size_t& i, Pos p, Line& out,
                        std::uint16_t file) {
    std::vector<std::string_view> args;
    int level = 0;
    size_t start = i + 1, e = i + 1;
    for (; e < text.size(); ++e) {
        if (text[e] == '(') ++level;
        else if (text[e] == ')' && level-- == 0) break;
        else if (text[e] == ',' && level == 0) args.push_back(trim(text.substr(start, e - start))), start = e + 1;
    }
    if (e >= text.size()) {
        problem(file, p, "'" + name + "(' is never closed with ')' on its line");
        return false;
    }
    args.push_back(trim(text.substr(start, e - start)));
    if (m.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
    if (args.size() != m.params.size()) {
        problem(file, p, "'" + name + "' takes " + std::to_string(m.params.size()) + " argument" + (m.params.size() == 1 ? "" : "s") +
                             "; found " + std::to_string(args.size()));
        return false;
    }
    i = e + 1;
    std::string body;
    for (size_t k = 0; k < m.body.size();) {
        const std::string_view w = identifierAt(std::string_view(m.body).substr(k));
        if (w.empty()) {
            body += m.body[k++];
            continue;
        }
        const auto param = std::find(m.params.begin(), m.params.end(), w);
        body += param == m.params.end() ? w : args[size_t(param - m.params.begin())];
        k += w.size();
        if (body.size() > kMaxLineBytes) {
            problem(file, p, "'" + name + "(...)' expands to more than 1 MB of text");
            return false;
        }
    }
    m_active.push_back(name);
    const bool ok = expand(body, nullptr, p, out, file);
    m_active.pop_back();
    return ok;
}

// [SECTION] Directives and conditions

void Preprocessor::define(std::string_view rest, Pos p, std::uint16_t file) {
    rest = trim(rest);
    const std::string_view name = identifierAt(rest);
    if (name.empty()) return problem(file, p, "expected '#define NAME text'");
    Macro m;
    rest.remove_prefix(name.size());
    if (!rest.empty() && rest[0] == '(') {
        m.function = true;
        const size_t close = rest.find(')');
        if (close == std::string_view::npos)
            return problem(file, p, "'#define " + std::string(name) + "(' is never closed with ')'");
        std::string_view list = rest.substr(1, close - 1);
        while (!trim(list).empty()) {
            const size_t comma = list.find(',');
            const std::string_view param = trim(list.substr(0, comma));
            if (identifierAt(param).size() != param.size() || param.empty())
                return problem(file, p, "'#define " + std::string(name) + "(...)': its parameters are names separated by commas");
            m.params.emplace_back(param);
            if (comma == std::string_view::npos) break;
            list.remove_prefix(comma + 1);
        }
        rest.remove_prefix(close + 1);
    }
    m.body = std::string(trim(rest));
    m_macros[std::string(name)] = std::move(m);
}

void Preprocessor::include(std::string_view rest, Pos p, std::uint16_t file, int depth) {
    rest = trim(rest);
    const char close = rest.empty() ? 0 : rest[0] == '"' ? '"' : rest[0] == '<' ? '>' : 0;
    const size_t end = close ? rest.find(close, 1) : std::string_view::npos;
    if (end == std::string_view::npos || end == 1) return problem(file, p, "expected '#include \"file\"'");
    const std::string name(rest.substr(1, end - 1));
    if (depth >= kMaxIncludeDepth) return problem(file, p, "#include is nested too deeply (more than 16 files)");
    std::string path, error;
    std::optional<std::string> text;
    if (m_include) text = m_include(m_out.files[file], name, path, error);
    else error = "no folder to read it from";
    if (!text) return problem(file, p, "cannot include '" + name + "': " + error);
    if (std::find(m_reading.begin(), m_reading.end(), path) != m_reading.end())
        return problem(file, p, "'" + name + "' includes itself (through the files that include it)");
    if (m_out.files.size() >= kMaxFiles) return problem(file, p, "more than 256 files are included");
    m_out.files.push_back(path);
    run(std::move(*text), std::uint16_t(m_out.files.size() - 1), depth + 1);
}

// `#if`'s condition: a whole number (after the macros are put in place), `defined NAME` or
// `defined(NAME)`, each perhaps after '!'.
bool Preprocessor::condition(std::string_view rest, Pos p, std::uint16_t file) {
    std::string_view e = trim(rest);
    bool negate = false;
    while (!e.empty() && e[0] == '!') negate = !negate, e = trim(e.substr(1));
    if (identifierAt(e) == "defined") {
        e = trim(e.substr(7));
        const bool parens = !e.empty() && e[0] == '(';
        if (parens) e = trim(e.substr(1));
        const std::string_view name = identifierAt(e);
        e = trim(e.substr(name.size()));
        if (name.empty() || (parens && (e.empty() || e[0] != ')'))) {
            problem(file, p, "expected 'defined NAME' or 'defined(NAME)' after '#if'");
            return false;
        }
        return negate != (m_macros.count(std::string(name)) > 0);
    }
    Line expanded;
    long value = 0;
    if (expand(e, nullptr, p, expanded, file)) {
        const std::string_view t = trim(expanded.text);
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec == std::errc() && end == t.data() + t.size() && !t.empty()) return negate != (value != 0);
    }
    problem(file, p, "this '#if' is not a whole number or 'defined NAME': read as false", Severity::Warning);
    return false;
}

void Preprocessor::directive(const Line& l, size_t hash, std::uint16_t file, int depth, std::vector<Condition>& conditions) {
    std::string_view rest = std::string_view(l.text).substr(hash + 1);
    const size_t afterSpaces = rest.find_first_not_of(" \t\r\f\v");
    rest.remove_prefix(afterSpaces == std::string_view::npos ? rest.size() : afterSpaces);
    const std::string word(identifierAt(rest));
    rest.remove_prefix(word.size());
    const Pos p = l.at[hash];
    const bool active = conditions.empty() || conditions.back().active;
    if (word == "ifdef" || word == "ifndef" || word == "if") {
        Condition c;
        c.parentActive = active;
        c.at = p;
        const std::string_view name = identifierAt(trim(rest));
        if (active && word != "if" && name.empty()) problem(file, p, "expected '#" + word + " NAME'");
        const bool holds = !active ? false
                           : word == "if" ? condition(rest, p, file)
                                          : (m_macros.count(std::string(name)) > 0) == (word == "ifdef");
        c.active = c.taken = holds;
        conditions.push_back(c);
    } else if (word == "elif" || word == "else") {
        if (conditions.empty()) return problem(file, p, "'#" + word + "' without an '#if' before it");
        Condition& c = conditions.back();
        if (c.sawElse) return problem(file, p, "'#" + word + "' after the '#else' of its '#if'");
        const bool holds = c.parentActive && !c.taken && (word == "else" || condition(rest, p, file));
        c.active = holds;
        c.taken = c.taken || holds;
        c.sawElse = word == "else";
    } else if (word == "endif") {
        if (conditions.empty()) return problem(file, p, "'#endif' without an '#if' before it");
        conditions.pop_back();
    } else if (!active) {
        return;
    } else if (word == "define") {
        define(rest, p, file);
    } else if (word == "undef") {
        const std::string_view name = identifierAt(trim(rest));
        if (name.empty()) return problem(file, p, "expected '#undef NAME'");
        m_macros.erase(std::string(name));
    } else if (word == "include") {
        include(rest, p, file, depth);
    } else if (word == "error") {
        problem(file, p, "#error" + std::string(rest));
    } else if (word.empty() && (rest.empty() || digit(rest[0]))) {
        // `# 12 "file"`: a line marker another preprocessor left, or a lone '#'
    } else if (word != "pragma" && word != "line") {
        problem(file, p, "unknown preprocessor directive '#" + word + "': the line is skipped", Severity::Warning);
    }
}

// [SECTION] A file's words

void Preprocessor::words(const Line& l, std::uint16_t file) {
    for (size_t i = 0; i < l.text.size();) {
        while (i < l.text.size() && space(l.text[i])) ++i;
        const size_t start = i;
        while (i < l.text.size() && !space(l.text[i])) ++i;
        if (i > start) m_out.words.push_back({l.text.substr(start, i - start), file, l.at[start].line, l.at[start].col});
    }
}

void Preprocessor::run(std::string text, std::uint16_t file, int depth) {
    m_reading.push_back(m_out.files[file]);
    std::vector<Condition> conditions;
    for (const Line& l : lines(text, file)) {
        const size_t first = l.text.find_first_not_of(" \t\r\f\v");
        if (first == std::string::npos) continue;
        if (l.text[first] == '#') {
            directive(l, first, file, depth, conditions);
            continue;
        }
        if (!conditions.empty() && !conditions.back().active) continue;
        Line expanded;
        m_overflow = false;
        if (expand(l.text, l.at.data(), {}, expanded, file)) words(expanded, file);
    }
    for (const Condition& c : conditions) problem(file, c.at, "an '#if' is never closed with '#endif'");
    m_reading.pop_back();
}

}  // namespace

Preprocessed preprocessWords(std::string_view text, const std::string& file, const IncludeReader& include) {
    Preprocessed out;
    out.files.push_back(file);
    Preprocessor(out, include).run(std::string(text), 0, 0);
    return out;
}

}  // namespace sprout::vlab
