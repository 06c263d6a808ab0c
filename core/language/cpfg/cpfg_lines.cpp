// The cpfg / lpfg / L-Py family's logical lines (cpfg manual; L-Py documentation): the
// CpfgReader's part after the preprocessor: a file's lines, productions written over several
// lines (statement blocks, L-Py's `produce`) made one, and diagnostics moved back to the lines
// they were written on. The words of a cpfg line, which the Parser's classifyCpfg reads too
// (cpfg_classify.cpp), are here. The C preprocessor's part (comments, #define, #include) is
// cpfg_preprocessor.cpp.
//
// Index of this file:
//   [SECTION] Reading a cpfg line: keys, section words, arrows
//   [SECTION] A file's logical lines
//   [SECTION] Productions and blocks written over several lines
//   [SECTION] Diagnostics at the lines they were written on

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "core/language/cpfg/cpfg_reader.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout::detail {
namespace {


constexpr int kIncludeLineBase = 1'000'000;  // included lines are numbered apart, then reported at the #include
constexpr int kMaxJoinedLines = 40;  // a production written over more lines than this is a mistake

// [SECTION] Reading a cpfg line: keys, section words, arrows

std::string lowerCollapsed(std::string_view s) {
    std::string out;
    bool space = false;
    for (char c : s) {
        if (isSpace(c)) {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += char(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

}  // namespace

// The arrow of a production outside parentheses and blocks: cpfg's `-->`, or `->`.
size_t arrowAt(std::string_view s) {
    int depth = 0;
    for (size_t i = 0; i + 1 < s.size(); ++i) {
        char c = s[i];
        if (c == '(' || c == '{') ++depth;
        else if (c == ')' || c == '}') depth = std::max(0, depth - 1);
        else if (depth == 0 && c == '-' && s[i + 1] == '>') return i;
    }
    return std::string_view::npos;
}

namespace {

// Open parentheses, and braces before the arrow, in `s` (negative when more close than
// open). After the arrow a brace is a polygon's start or end, which a successor may leave
// open (`A -> [&FA{.].` and `B -> B&.F.}`).
int openCount(std::string_view s) {
    const size_t arrow = arrowAt(s);
    int depth = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        const bool block = arrow == std::string_view::npos || i < arrow;
        if (c == '(' || (block && c == '{')) ++depth;
        else if (c == ')' || (block && c == '}')) --depth;
    }
    return depth;
}

}  // namespace

bool startsWithWord(std::string_view t, std::string_view word) {
    return t.starts_with(word) && (t.size() == word.size() || !isIdentChar(t[word.size()]));
}

// The key of a `key: value` line in canonical form ("derivation length"), or "" when the
// text before the ':' is not made of words.
std::string keyOf(std::string_view t, std::string_view& value) {
    size_t colon = t.find(':');
    if (colon == std::string_view::npos) return "";
    std::string_view key = trim(t.substr(0, colon));
    if (key.empty() || !std::all_of(key.begin(), key.end(), [](char c) { return isIdentChar(c) || isSpace(c); }))
        return "";
    value = trim(t.substr(colon + 1));
    std::string k = lowerCollapsed(key);
    // cpfg's lexer (lsys_input.l) takes the space in these as optional.
    if (k == "derivationlength") return "derivation length";
    if (k == "start each" || k == "end each") k.erase(k.find(' '), 1);
    return k;
}

// The cpfg settings Sprout reads, by their cpfg names, and the .lsys directive they set.
const std::map<std::string, std::string>& cpfgKeys() {
    static const std::map<std::string, std::string> k = {
        {"derivation length", "n"}, {"axiom", "axiom"}, {"ignore", "ignore"},
        {"angle increment", "angle"},  // from cpfg's view file, when written in the grammar
    };
    return k;
}

// `homomorphism`, `decomposition:`, `endlsystem` ...: a line that opens a section (a remark
// after its ':' is allowed, as cpfg's `homomorphism: no warnings`).
std::string sectionWord(std::string_view t) {
    std::string head = lowerCollapsed(t.substr(0, t.find(':')));
    static const char* words[] = {"homomorphism", "interpretation", "decomposition", "production", "productions",
                                  "endlsystem", "group", "endgroup", "ring lsystem"};
    for (const char* w : words)
        if (head == w) return head;
    return "";
}

// cpfg's blocks of statements: constants (`define: {...}`) and the global blocks run
// before and after the derivation and each of its steps.
bool isStatementBlockKey(const std::string& key) {
    return key == "define" || key == "start" || key == "starteach" || key == "endeach" || key == "end";
}

namespace {

// Braces open in `s` (negative when more close than open).
int braceDepth(std::string_view s) {
    int depth = 0;
    for (char c : s) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    return depth;
}

bool knownKey(const std::string& key) {
    if (cpfgKeys().count(key) || key == "lsystem" || key == "consider" || key == "maximum depth" || key == "surface" ||
        key == "angle factor" || isStatementBlockKey(key))
        return true;
    for (const auto& d : directives())
        if (key == d.name) return true;
    return false;
}

// Whether a rule's successor is empty: nothing after its arrow.
bool successorEmpty(std::string_view r) {
    const size_t a = arrowAt(r);
    if (a == std::string_view::npos) return false;
    size_t k = a;
    while (k < r.size() && (r[k] == '-' || r[k] == '>')) ++k;
    return trim(r.substr(k)).empty();
}

}  // namespace

// [SECTION] A file's logical lines

std::vector<SourceLine> CpfgReader::read(std::string& text, std::string_view original) {
    m_original = original;
    if (size_t open = blankComments(text); open != std::string::npos) {
        // Report at the '/*' and read the text before it.
        size_t lineStart = text.rfind('\n', open);
        lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
        size_t lineEnd = m_original.find('\n', open);
        SourceLine l;
        l.number = int(std::count(text.begin(), text.begin() + std::ptrdiff_t(open), '\n')) + 1;
        l.text = std::string_view(text).substr(lineStart, (lineEnd == std::string::npos ? text.size() : lineEnd) - lineStart);
        l.original = m_original.substr(lineStart, l.text.size());
        m_parser.sink().error(l, l.text.substr(open - lineStart), "this comment '/*' is never closed with '*/'");
    }
    std::vector<std::string> stack;
    if (!m_options.fileName.empty()) stack.push_back(m_options.fileName);
    return readFile(text, "", 0, 0, stack);
}

std::vector<SourceLine> CpfgReader::readFile(std::string_view text, const std::string& includeName, int includeLine,
                                             int depth, std::vector<std::string>& stack) {
    // `text` is the grammar's own (comments already blanked) or an included file kept in m_store.
    const bool top = includeName.empty();
    const int originBase = top ? 0 : kIncludeLineBase * int(m_origins.size() + 1);
    if (!top) {
        Origin o;
        o.logical = originBase;
        o.includeName = includeName;
        o.includeLine = includeLine;
        m_origins.push_back(o);
    }
    std::vector<SourceLine> lines = physicalLines(text, top, originBase);
    joinContinuations(lines, top);
    std::vector<SourceLine> body = preprocess(lines, top, includeLine, depth, stack);
    putTextMacros(body);
    std::vector<SourceLine> logical;
    if (m_options.tabContinues) joinTabLines(body);
    joinLines(body, logical);
    return logical;
}

// The text's lines as they stand, numbered from originBase + 1 (an included file's apart).
std::vector<SourceLine> CpfgReader::physicalLines(std::string_view text, bool top, int originBase) const {
    std::vector<SourceLine> lines;
    size_t start = 0;
    int number = 1;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        SourceLine l;
        l.number = originBase + number++;
        l.text = text.substr(start, end - start);
        if (top) l.original = m_original.substr(start, end - start);
        if (l.text.ends_with('\r')) l.text.remove_suffix(1);
        lines.push_back(l);
        start = end + 1;
    }
    return lines;
}

// [SECTION] Productions and blocks written over several lines

// cpfg's lexer reads a newline followed by a tab as a space: each line that starts with a tab
// goes on the line before it (whatever that line is), which keeps the joined text.
void CpfgReader::joinTabLines(std::vector<SourceLine>& body) {
    for (size_t i = 0; i < body.size(); ++i) {
        size_t j = i;
        while (j + 1 < body.size() && body[j + 1].text.starts_with('\t')) ++j;
        if (j == i) continue;
        std::string joined(body[i].text);
        Origin o;
        o.logical = body[i].number;
        o.pieces.emplace_back(0, body[i].number);
        o.pieceStart.push_back(0);
        for (size_t k = i + 1; k <= j; ++k) {
            joined += ' ';
            o.pieces.emplace_back(joined.size(), body[k].number);
            o.pieceStart.push_back(0);
            joined += body[k].text;
            body[k].text = body[k].text.substr(0, 0);
            body[k].original = body[k].text;
        }
        m_store.push_back(std::move(joined));
        body[i].text = m_store.back();
        body[i].original = m_store.back();
        m_origins.push_back(std::move(o));
        i = j;
    }
}

// Productions written over several lines become one logical line.
void CpfgReader::joinLines(std::vector<SourceLine>& body, std::vector<SourceLine>& lines) {
    for (size_t i = 0; i < body.size(); ++i) {
        std::string_view t = trim(body[i].text);
        SourceLine out = body[i];
        std::string_view value;
        std::string key = keyOf(t, value);
        if (isStatementBlockKey(key) && value.starts_with("{") && braceDepth(t) > 0) {
            // `define: {` or `EndEach: {` with its statements on the lines after: one line.
            joinStatementBlock(body, i);
            out = body[i];
            t = trim(body[i].text);
            key = keyOf(t, value);
        }
        const bool directive = (!key.empty() && arrowAt(t) == std::string_view::npos && knownKey(key)) ||
                               !sectionWord(t).empty() || startsWithWord(t, "module");
        // A rule whose successor is on the lines after its arrow (`M(t) : 1 {...} -->` then the
        // successor, indented: L-system Explorer's files) goes on to the next line.
        const bool successorNext = arrowAt(t) != std::string_view::npos && openCount(t) <= 0 && successorEmpty(t) &&
                                   i + 1 < body.size() && !trim(body[i + 1].text).empty() && isSpace(body[i + 1].text[0]) &&
                                   arrowAt(body[i + 1].text) == std::string_view::npos;
        bool complete = t.empty() || directive || t.starts_with("#") ||
                        (arrowAt(t) != std::string_view::npos && openCount(t) <= 0 && !successorNext);
        if (!complete) i = joinProduction(body, i, out);
        lines.push_back(out);
    }
}

// `define: {` ... `}` over several lines: one line, in place of the first.
void CpfgReader::joinStatementBlock(std::vector<SourceLine>& body, size_t i) {
    std::string joined(body[i].text);
    size_t j = i;
    while (braceDepth(joined) > 0 && j + 1 < body.size() && j - i < size_t(kMaxJoinedLines)) {
        joined += ' ';
        joined += body[++j].text;
    }
    for (size_t k = i + 1; k <= j; ++k) body[k].text = body[k].text.substr(0, 0);
    m_store.push_back(std::move(joined));
    body[i].text = m_store.back();
    body[i].original = m_store.back();
}

// Join while a block or parenthesis is open, or no arrow has come yet and the next line
// continues the production (a block, the arrow, ':' or L-Py's produce). Returns the last
// line read into `out` (i when none was joined).
size_t CpfgReader::joinProduction(std::vector<SourceLine>& body, size_t i, SourceLine& out) {
    std::string joined(body[i].text);
    Origin o;
    o.pieces.emplace_back(0, body[i].number);
    o.pieceStart.push_back(0);
    size_t j = i;
    bool done = false, python = false;
    while (j + 1 < body.size() && j - i < size_t(kMaxJoinedLines)) {
        std::string_view cur = trim(joined);
        std::string_view next = trim(body[j + 1].text);
        const bool hasArrow = arrowAt(joined) != std::string_view::npos;
        const bool open = openCount(joined) > 0;
        const bool produce = startsWithWord(next, "produce") || startsWithWord(next, "nproduce");
        const bool successor = hasArrow && !open && successorEmpty(joined) && !next.empty();
        if (!open && !successor && (hasArrow || next.empty())) break;
        if (!open && !successor && !(cur.ends_with(":") || cur.ends_with("}") || next.starts_with("{") ||
                       next.starts_with("-->") || next.starts_with("->") || next.starts_with(":") ||
                       next.starts_with("}") || produce))
            break;
        if (!produce && !open && !successor && (startsWithWord(next, "if") || startsWithWord(next, "elif") || startsWithWord(next, "else") ||
                         startsWithWord(next, "for") || startsWithWord(next, "while") || startsWithWord(next, "return"))) {
            m_parser.sink().error(body[j + 1], next, "Python code in an L-Py rule is not supported: Sprout reads 'produce ...' alone "
                                            "(write a condition, 'A(x) : x > 1 --> B', instead of 'if')");
            python = true;
            break;
        }
        ++j;
        joined += ' ';
        o.pieces.emplace_back(joined.size(), body[j].number);
        o.pieceStart.push_back(0);
        std::string piece(body[j].text);
        if (produce) {  // L-Py: `A(x) :` then `produce F(x) A(x+1)`
            size_t at = piece.find_first_not_of(" \t");
            size_t len = piece[at] == 'n' ? 8 : 7;
            piece.replace(at, len, std::string("-->") + std::string(len - 3, ' '));
        }
        joined += piece;
        if (arrowAt(joined) != std::string_view::npos && openCount(joined) <= 0 && !successorEmpty(joined)) {
            done = true;
            break;
        }
    }
    if (python) {  // reported once, at the Python line; its rule is not read
        // The rule's indented body goes with it.
        for (size_t k = i + 1; k < body.size() && (k <= j + 1 || (!body[k].text.empty() && isSpace(body[k].text[0]))); ++k)
            body[k].text = body[k].text.substr(0, 0);
        out.text = out.text.substr(0, 0);
    } else if (done) {
        m_store.push_back(std::move(joined));
        out.text = m_store.back();
        out.original = m_store.back();
        o.logical = body[i].number;
        m_origins.push_back(std::move(o));
        return j;
    }
    return i;
}

// [SECTION] Diagnostics at the lines they were written on

void CpfgReader::placeDiagnostics(std::vector<Diagnostic>& diags) const {
    std::map<int, const Origin*> byLine;
    for (const auto& o : m_origins)
        if (!o.pieces.empty()) byLine[o.logical] = &o;
    for (auto& d : diags) {
        if (auto it = byLine.find(d.line); it != byLine.end()) {  // a joined production
            const Origin& o = *it->second;
            const size_t offset = size_t(std::max(0, d.col - 1));
            size_t k = 0;
            while (k + 1 < o.pieces.size() && o.pieces[k + 1].first <= offset) ++k;
            d.line = o.pieces[k].second;
            d.col = int(offset - o.pieces[k].first + o.pieceStart[k]) + 1;
        }
        if (d.line >= kIncludeLineBase) {  // a line of an included file
            const size_t index = size_t(d.line / kIncludeLineBase) - 1;
            const int inner = d.line % kIncludeLineBase;
            for (const auto& o : m_origins) {
                if (o.logical != kIncludeLineBase * int(index + 1) || o.includeName.empty()) continue;
                d.message = "in '" + o.includeName + "' line " + std::to_string(inner) + ": " + d.message;
                d.line = o.includeLine;
                d.col = 1;
                break;
            }
        }
    }
    std::stable_sort(diags.begin(), diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return a.line != b.line ? a.line < b.line : a.col < b.col;
    });
}

}  // namespace sprout::detail
