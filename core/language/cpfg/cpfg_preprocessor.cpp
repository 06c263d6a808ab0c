// The cpfg family's C preprocessor, as the grammar's reader meets it (cpfg manual): C
// comments, lines continued with '\\', #define (numbers become sliders, function-like macros
// are expanded in expressions, any other text is put in place where its name is used) and
// #include of files beside the grammar: the CpfgReader's first steps. cpfg_lines.cpp makes
// the lines it leaves logical lines.
#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/language/cpfg/cpfg_reader.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {

constexpr int kMaxIncludeDepth = 16;

}  // namespace

// Comments become spaces (newlines kept), so every position in the text stays where it was.
// Returns the offset of an unterminated `/*`, or npos.
size_t CpfgReader::blankComments(std::string& text) {
    size_t i = 0;
    while (i + 1 < text.size()) {
        if (text[i] == '"') {  // an #include "name" may hold '//'
            size_t end = text.find_first_of("\"\n", i + 1);
            i = end == std::string::npos ? text.size() : end + 1;
            continue;
        }
        if (text[i] == '/' && text[i + 1] == '*') {
            size_t end = text.find("*/", i + 2);
            size_t stop = end == std::string::npos ? text.size() : end + 2;
            for (size_t k = i; k < stop; ++k)
                if (text[k] != '\n') text[k] = ' ';
            if (end == std::string::npos) return i;
            i = stop;
            continue;
        }
        // `//` starts a comment at the start of a line or after a space; glued to a module it
        // is two rolls (`[//&&l]`), as L-system Explorer reads it.
        if (text[i] == '/' && text[i + 1] == '/' && (i == 0 || isSpace(text[i - 1]) || text[i - 1] == '\n')) {
            while (i < text.size() && text[i] != '\n') text[i++] = ' ';
            continue;
        }
        if (text[i] == '/') {  // a run of rolls: none of its slashes starts a comment
            while (i + 1 < text.size() && text[i] == '/' && text[i + 1] != '*') ++i;
            if (i + 1 == text.size()) ++i;
            continue;
        }
        ++i;
    }
    return std::string::npos;
}

// A line that ends with '\\' goes on on the next one (the C preprocessor's continuation,
// in multi-line #defines): one line, at the first line's number.
void CpfgReader::joinContinuations(std::vector<SourceLine>& lines, bool top) {
    for (size_t i = 0; i + 1 < lines.size(); ++i) {
        std::string_view t = lines[i].text;
        while (!t.empty() && isSpace(t.back())) t.remove_suffix(1);
        if (!t.ends_with('\\')) continue;
        std::string joined(t.substr(0, t.size() - 1));
        size_t j = i;
        while (j + 1 < lines.size()) {
            std::string_view next = lines[++j].text;
            lines[j].text = next.substr(0, 0);
            while (!next.empty() && isSpace(next.back())) next.remove_suffix(1);
            const bool more = next.ends_with('\\');
            joined += ' ';
            joined += more ? next.substr(0, next.size() - 1) : next;
            if (!more) break;
        }
        m_store.push_back(std::move(joined));
        lines[i].text = m_store.back();
        if (top) lines[i].original = m_store.back();
        i = j;
    }
}

// Preprocessor lines first, in order: #define and #include. Returns the other lines, an
// included file's in place of its #include.
std::vector<SourceLine> CpfgReader::preprocess(const std::vector<SourceLine>& lines, bool top, int includeLine,
                                               int depth, std::vector<std::string>& stack) {
    std::vector<SourceLine> body;
    // #if / #ifdef / #ifndef ... #elif / #else ... #endif, as the C preprocessor cpfg runs:
    // per open #if, whether its lines are read now and whether a branch was taken already.
    struct Conditional { bool reading, taken, outer; };
    std::vector<Conditional> open;
    auto reading = [&] { return open.empty() || open.back().reading; };
    for (const auto& src : lines) {
        std::string_view t = trim(src.text);
        std::string_view word = t.starts_with("#") ? t.substr(0, t.find_first_of(" \t\"<(")) : std::string_view();
        std::string_view rest = trim(t.substr(word.size()));
        if (word == "#if" || word == "#ifdef" || word == "#ifndef") {
            const bool outer = reading();
            const bool holds = outer && condition(src, word, rest);
            open.push_back({outer && holds, holds, outer});
            continue;
        }
        if (word == "#elif" || word == "#else" || word == "#endif") {
            if (open.empty()) {
                m_parser.sink().error(src, word, "'" + std::string(word) + "' without an '#if' before it");
                continue;
            }
            Conditional& c = open.back();
            if (word == "#endif") {
                open.pop_back();
            } else {
                const bool holds = c.outer && !c.taken && (word == "#else" || condition(src, "#if", rest));
                c.reading = holds;
                c.taken = c.taken || holds;
            }
            continue;
        }
        if (!reading()) continue;
        if (!t.starts_with("#")) {
            body.push_back(src);
            continue;
        }
        if (word == "#undef") {
            const std::string name(rest.substr(0, rest.find_first_of(" \t")));
            m_parser.grammar().defines.erase(name);
            m_macros.erase(name);
            std::erase_if(m_textMacros, [&](const auto& m) { return m.first == name; });
            continue;
        }
        if (word == "#define") {
            readDefine(src, rest, top);
        } else if (word == "#include") {
            readInclude(src, t, rest, top, includeLine, depth, stack, body);
        } else if (word == "#ignore") {
            body.push_back(src);  // read by the `ignore` directive below
        }
        // Any other '#' line is a comment (L-Py files use Python's '#').
    }
    if (!open.empty()) m_parser.sink().error(lines.back(), lines.back().text, "an '#if' is never closed with '#endif'");
    return body;
}

// Whether an #if's, #ifdef's or #ifndef's condition holds: a name defined, or an expression
// of the defined numbers that is not 0 (`defined(NAME)` too; an unknown name is 0, as in C).
bool CpfgReader::condition(const SourceLine& line, std::string_view word, std::string_view rest) {
    auto defined = [&](std::string_view name) {
        const std::string n(trim(name));
        return m_parser.grammar().defines.count(n) > 0 || m_macros.count(n) > 0 ||
               std::any_of(m_textMacros.begin(), m_textMacros.end(), [&](const auto& m) { return m.first == n; });
    };
    if (word == "#ifdef") return defined(rest);
    if (word == "#ifndef") return !defined(rest);
    std::string text;  // defined(X) and unknown names made numbers
    for (size_t i = 0; i < rest.size();) {
        if (std::isalpha(static_cast<unsigned char>(rest[i])) || rest[i] == '_') {
            size_t j = i;
            while (j < rest.size() && isIdentChar(rest[j])) ++j;
            std::string_view name = rest.substr(i, j - i);
            if (name == "defined") {
                size_t k = j;
                while (k < rest.size() && (rest[k] == ' ' || rest[k] == '(')) ++k;
                size_t e = k;
                while (e < rest.size() && isIdentChar(rest[e])) ++e;
                text += defined(rest.substr(k, e - k)) ? "1" : "0";
                while (e < rest.size() && (rest[e] == ' ' || rest[e] == ')')) ++e;
                i = e;
                continue;
            }
            text += defined(name) || (j < rest.size() && rest[j] == '(') ? std::string(name) : "0";
            i = j;
            continue;
        }
        text += rest[i++];
    }
    std::vector<std::string> active;  // `#define TWO 1+1` is text: put in place first
    bool tooLong = false;
    text = expandTextMacros(text, active, tooLong);
    SourceLine scratchLine = line;
    scratchLine.text = text;
    scratchLine.original = text;
    DiagnosticSink scratch;
    ExprScope scope{nullptr, &m_parser.grammar().defines, &m_macros};
    auto e = compileExpr(text, scratchLine, scope, scratch);
    if (!e || !e->isConstant()) {
        m_parser.sink().warning(line, rest, "this '#if' is not a condition of defined numbers: read as false");
        return false;
    }
    return e->constantValue() != 0;
}

// Whether `v` is one value wherever its text is put: a number, a name or a call, or a
// parenthesised expression, after signs (which bind tightest in cpfg). Not `1+1`, `2*x`, `a^b`.
bool CpfgReader::wholeValue(std::string_view v) {
    size_t i = 0;
    while (i < v.size() && (v[i] == '-' || v[i] == '+' || v[i] == '!' || isSpace(v[i]))) ++i;
    if (i == v.size()) return false;
    if (std::isdigit(static_cast<unsigned char>(v[i])) || v[i] == '.') {  // a number, all of it
        double d = 0;
        auto r = std::from_chars(v.data() + i, v.data() + v.size(), d);
        return r.ec == std::errc() && trim(v.substr(size_t(r.ptr - v.data()))).empty();
    }
    while (i < v.size() && isIdentChar(v[i])) ++i;
    while (i < v.size() && isSpace(v[i])) ++i;
    if (i == v.size()) return true;  // a name
    if (v[i] != '(') return false;
    int depth = 0;
    for (size_t k = i; k < v.size(); ++k) {  // a call or parentheses closed at the end
        depth += v[k] == '(' ? 1 : v[k] == ')' ? -1 : 0;
        if (depth == 0) return trim(v.substr(k + 1)).empty();
    }
    return false;
}

// `#define NAME value`, `#define NAME(a, b) body` or `#define FLAG` (`rest` follows the word).
void CpfgReader::readDefine(const SourceLine& src, std::string_view rest, bool top) {
    size_t nameEnd = 0;
    while (nameEnd < rest.size() && isIdentChar(rest[nameEnd])) ++nameEnd;
    std::string name(rest.substr(0, nameEnd));
    if (name.empty()) {
        m_parser.sink().error(src, rest, "expected '#define NAME value'");
        return;
    }
    if (nameEnd < rest.size() && rest[nameEnd] == '(') {  // function-like
        size_t close = rest.find(')', nameEnd);
        if (close == std::string_view::npos) {
            m_parser.sink().error(src, rest.substr(nameEnd), "this '(' is never closed");
            return;
        }
        ExprMacro m;
        std::string_view params = rest.substr(nameEnd + 1, close - nameEnd - 1);
        size_t a = 0;
        while (a <= params.size()) {
            size_t b = params.find(',', a);
            if (b == std::string_view::npos) b = params.size();
            std::string_view param = trim(params.substr(a, b - a));
            if (!param.empty()) m.params.emplace_back(param);
            a = b + 1;
        }
        m.body = std::string(trim(rest.substr(close + 1)));
        // `#define f(x) \\` then the body on the next line: the C preprocessor joins the lines
        // and keeps the first backslash, a stray character cpfg's lexer passes over.
        for (size_t k = 0; k < m.body.size(); ++k)
            if (m.body[k] == '\\' && (k + 1 == m.body.size() || isSpace(m.body[k + 1]))) m.body[k] = ' ';
        m.body = std::string(trim(m.body));
        if (m.body.empty()) {
            m_parser.sink().error(src, rest, "'#define " + name + "(...)' needs a body");
            return;
        }
        m_macros[name] = std::move(m);
        return;
    }
    std::string_view value = trim(rest.substr(nameEnd));
    if (value.empty()) {
        // `#define DEBUG`: a flag for #ifdef, nothing to compute.
        m_parser.grammar().defines.emplace(name, 1.0);
        return;
    }
    // A number (or an expression of numbers) is a constant with a slider; anything
    // else (`#define LEAF ~l(2)`) is text put in place where its name is used.
    DiagnosticSink scratch;
    Grammar& g = m_parser.grammar();
    ExprScope scope{nullptr, &g.defines, &m_macros};
    // A random value (`#define ANGLE nran(80, 4)`) is text too: each use draws its own, as
    // the C preprocessor puts the call in place. So is an expression whose operators the
    // text around a use could take apart (`#define TWO 1+1`: TWO*3 is 1+1*3, 4).
    if (auto e = compileExpr(value, src, scope, scratch); e && !e->usesRandom() && wholeValue(value)) {
        m_parser.define(src, rest);
        // A slider writes its value back into the text it edits: only the grammar's
        // own defines get one, not those of an included file.
        if (!top && !g.defineOrder.empty() && g.defineOrder.back() == name) g.defineOrder.pop_back();
    } else {
        m_textMacros.emplace_back(name, std::string(value));
    }
}

// `#include "file"`: the file's lines read now and added to `body`, in order (`t` is the
// whole line, `rest` what follows the word).
void CpfgReader::readInclude(const SourceLine& src, std::string_view t, std::string_view rest, bool top,
                             int includeLine, int depth, std::vector<std::string>& stack,
                             std::vector<SourceLine>& body) {
    std::string_view name = rest;
    if ((name.starts_with("\"") && name.ends_with("\"") && name.size() >= 2) ||
        (name.starts_with("<") && name.ends_with(">") && name.size() >= 2))
        name = name.substr(1, name.size() - 2);
    else {
        m_parser.sink().error(src, rest.empty() ? t : rest, "expected '#include \"file\"'");
        return;
    }
    std::string file(name);
    if (std::find(stack.begin(), stack.end(), file) != stack.end()) {
        m_parser.sink().error(src, rest, "'" + file + "' includes itself" +
                                    (stack.size() > 1 && file != stack.back() ? " through '" + stack.back() + "'" : ""));
        return;
    }
    if (depth >= kMaxIncludeDepth) {
        m_parser.sink().error(src, rest, "#include is nested too deeply (more than 16 files)");
        return;
    }
    if (!m_options.include) {
        m_parser.sink().error(src, rest, "#include \"" + file + "\" needs the grammar's folder: save the grammar beside it first");
        return;
    }
    std::string error;
    auto included = m_options.include(file, error);
    if (!included) {
        m_parser.sink().error(src, rest, "cannot include '" + file + "': " + error);
        return;
    }
    m_store.push_back(std::move(*included));
    std::string& stored = m_store.back();
    for (size_t k = 0; k < stored.size(); ++k)
        if (stored[k] == '\r' && (k + 1 == stored.size() || stored[k + 1] != '\n')) stored[k] = '\n';
    if (size_t open = blankComments(stored); open != std::string::npos) {
        m_parser.sink().error(src, rest, "in '" + file + "': a comment '/*' is never closed with '*/'");
        return;
    }
    stack.push_back(file);
    // The included lines take their place here: read them now, in order.
    std::vector<SourceLine> inner = readFile(stored, file, top ? src.number : includeLine, depth + 1, stack);
    stack.pop_back();
    // Keep the order: flush what came before, then the included lines.
    for (const auto& l : inner) body.push_back(l);
}

// Textual #defines put in place (the line keeps its number; columns after a replacement
// are counted in the replaced text). As the C preprocessor does, a macro is not expanded
// again inside its own expansion (`#define a &(a) F` would otherwise grow without end),
// and an expansion past 64 KB is refused.
void CpfgReader::putTextMacros(std::vector<SourceLine>& body) {
    if (m_textMacros.empty()) return;
    for (auto& l : body) {
        std::vector<std::string> active;
        bool tooLong = false;
        std::string expanded = expandTextMacros(l.text, active, tooLong);
        if (tooLong) {
            m_parser.sink().error(l, l.text, "the #define names on this line expand to more than 64 KB of text");
            l.text = l.text.substr(0, 0);
            continue;
        }
        if (expanded != l.text) {
            m_store.push_back(std::move(expanded));
            l.text = m_store.back();
            l.original = m_store.back();
        }
    }
}

std::string CpfgReader::expandTextMacros(std::string_view text, std::vector<std::string>& active, bool& tooLong) const {
    std::string out;
    size_t i = 0;
    while (i < text.size() && !tooLong) {
        if (!(std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') || (i > 0 && isIdentChar(text[i - 1]))) {
            out += text[i++];
            continue;
        }
        size_t end = i;
        while (end < text.size() && isIdentChar(text[end])) ++end;
        const std::string_view word = text.substr(i, end - i);
        i = end;
        const std::string* value = nullptr;
        for (const auto& [name, v] : m_textMacros)
            if (name == word) value = &v;
        if (!value || std::find(active.begin(), active.end(), word) != active.end()) {
            out += word;
            continue;
        }
        active.emplace_back(word);
        out += expandTextMacros(*value, active, tooLong);
        active.pop_back();
        if (out.size() > (64u << 10)) tooLong = true;
    }
    return out;
}

}  // namespace sprout::detail
