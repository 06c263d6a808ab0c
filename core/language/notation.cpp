// Grammars as people write them (issue 22): ABOP's printed notation, the web's L-system
// dialects and text pasted from a PDF or a web page, read by the .lsys parser. This file holds
// the words of those notations (setting aliases, rule labels, other tools' settings) and the
// pasted characters' replacements; parser_run.cpp's classify() uses them line by line.
//
// Index of this file:
//   [SECTION] The words of the notations
//   [SECTION] Characters pasted from PDFs and web pages
//   [SECTION] Settings, constants and rules written with '='
//   [SECTION] ABOP's lines: successors over several lines, words as modules
//   [SECTION] Settings applied, and the list of those read

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>

#include "core/language/parser_impl.hpp"

namespace sprout::detail {

// [SECTION] The words of the notations

namespace {

std::string lowerCollapsed(std::string_view key) {
    std::string k;
    for (char c : key) {
        if (isSpace(c)) {
            if (!k.empty() && k.back() != ' ') k += ' ';
            continue;
        }
        k += char(std::tolower(static_cast<unsigned char>(c)));
    }
    while (!k.empty() && k.back() == ' ') k.pop_back();
    return k;
}

}  // namespace

const char* settingAlias(std::string_view key) {
    static const std::pair<const char*, const char*> aliases[] = {
        {"\xCE\xB4", "angle"},  // δ
        {"\xCE\x94", "angle"},  // Δ (a capital in some transcriptions)
        {"delta", "angle"},
        {"angle", "angle"},
        {"\xCF\x89", "axiom"},  // ω
        {"w", "axiom"},
        {"axiom", "axiom"},
        {"start", "axiom"},
        {"initiator", "axiom"},
        {"n", "n"},
        {"iterations", "iterations"},
        {"dlength", "n"},
        {"derivation length", "n"},
        {"generations", "n"},
        {"seed", "seed"},
        {"step", "step"},
        {"stepsize", "step"},
        {"step size", "step"},
    };
    const std::string k = lowerCollapsed(key);
    for (const auto& [from, to] : aliases)
        if (k == from) return to;
    return nullptr;
}

bool isForeignSetting(std::string_view key) {
    static const char* const names[] = {"stemsize", "xpos", "ypos", "zpos", "zoom", "camera", "rotation", "rotate",
                                        "scale", "linewidth", "linelength", "background", "bgcolor", "color",
                                        "colour", "thickness", "leafsize", "renderer", "canvas", "view"};
    const std::string k = lowerCollapsed(key);
    return std::any_of(std::begin(names), std::end(names), [&](const char* n) { return k == n; });
}

// A setting of the web's dialects that its rules may also read as a variable (L-system
// Explorer's `delta`, `stemsize`): read as the setting and defined as a constant.
bool webVariable(std::string_view key) {
    const std::string k = lowerCollapsed(key);
    return k == "delta" || k == "angle" || k == "stemsize" || k == "step" || k == "stepsize";
}

bool isRuleLabel(std::string_view s) {
    // After normalizePasted, subscript digits are plain digits: p1, P2, p3 (from p₃).
    // ABOP writes a lone production "p : F -> ..." too.
    if (s.empty() || (s[0] != 'p' && s[0] != 'P')) return false;
    return std::all_of(s.begin() + 1, s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

void Parser::warnForeign(const SourceLine& line, std::string_view key) {
    m_sink.warning(line, key, "'" + std::string(key) + "' is another L-system tool's view setting: Sprout leaves it out");
    m_notation = true;
}

// [SECTION] Characters pasted from PDFs and web pages

namespace {

// Every replacement keeps the byte length (padded with spaces): columns stay those of the
// text as written. `what` (when set) is a warning at the place; `abop` marks ABOP's
// printed notation.
struct PastedSub {
    const char* from;
    const char* to;
    const char* what;
    bool abop;
    bool lsysOnly;  // not in cpfg files, where the characters mean something else
};
const PastedSub kPastedSubs[] = {
    {"\xE2\x86\x92", "-> ", nullptr, true, false},  // → (an accepted arrow, no warning)
    {"\xE2\x9F\xB6", "-> ", nullptr, true, false},  // ⟶
    {"\xE2\x87\x92", "-> ", nullptr, true, false},  // ⇒
    {"\xE2\x9F\xB9", "-> ", nullptr, true, false},  // ⟹
    {"\xE2\x88\x92", "-  ", "the Unicode minus sign '\xE2\x88\x92' was read as '-'", false, false},
    {"\xE2\x80\x93", "-  ", "the dash '\xE2\x80\x93' was read as '-'", false, false},
    {"\xC2\xA0", "  ", nullptr, false, false},  // no-break space
    {"\xE2\x80\x82", "   ", nullptr, false, false},  // en space .. hair space, zero width
    {"\xE2\x80\x83", "   ", nullptr, false, false},
    {"\xE2\x80\x84", "   ", nullptr, false, false},
    {"\xE2\x80\x85", "   ", nullptr, false, false},
    {"\xE2\x80\x86", "   ", nullptr, false, false},
    {"\xE2\x80\x87", "   ", nullptr, false, false},
    {"\xE2\x80\x88", "   ", nullptr, false, false},
    {"\xE2\x80\x89", "   ", nullptr, false, false},  // thin space
    {"\xE2\x80\x8A", "   ", nullptr, false, false},
    {"\xE2\x80\x8B", "   ", nullptr, false, false},
    {"\xE2\x80\xAF", "   ", nullptr, false, false},  // narrow no-break space
    {"\xEF\xBB\xBF", "   ", nullptr, false, false},  // a byte order mark inside the text
    {"\xE2\x80\x98", "'  ", nullptr, false, false},  // smart quotes
    {"\xE2\x80\x99", "'  ", nullptr, false, false},
    {"\xE2\x80\x9C", "\"  ", nullptr, false, false},
    {"\xE2\x80\x9D", "\"  ", nullptr, false, false},
    {"\xE2\x80\xB2", "'  ", nullptr, false, false},   // prime
    {"\xE2\x80\xB3", "'' ", nullptr, false, false},   // double prime
    {"\xC2\xB0", "  ", nullptr, true, false},         // degree sign
    {"\xC3\x97", "* ", nullptr, false, false},        // ×
    {"\xC2\xB7", "* ", nullptr, false, false},        // ·
    {"\xE2\x8B\x85", "*  ", nullptr, false, false},   // ⋅
    {"\xE2\x89\xA5", ">= ", nullptr, false, false},   // ≥
    {"\xE2\x89\xA4", "<= ", nullptr, false, false},   // ≤
    {"\xE2\x89\xA0", "!= ", nullptr, false, false},   // ≠
    {"\xE2\x88\xA7", "^  ", nullptr, true, false},    // ∧: ABOP's pitch up, printed as a wedge
    {"\xE2\x88\xA8", "&  ", nullptr, true, false},    // ∨: pitch down in some printings
    {"\xE2\x82\x80", "0  ", nullptr, true, false},    // subscript digits (p₃)
    {"\xE2\x82\x81", "1  ", nullptr, true, false},
    {"\xE2\x82\x82", "2  ", nullptr, true, false},
    {"\xE2\x82\x83", "3  ", nullptr, true, false},
    {"\xE2\x82\x84", "4  ", nullptr, true, false},
    {"\xE2\x82\x85", "5  ", nullptr, true, false},
    {"\xE2\x82\x86", "6  ", nullptr, true, false},
    {"\xE2\x82\x87", "7  ", nullptr, true, false},
    {"\xE2\x82\x88", "8  ", nullptr, true, false},
    {"\xE2\x82\x89", "9  ", nullptr, true, false},
    // LaTeX as lecture notes and converted PDFs write it.
    {"\\longrightarrow", "->             ", nullptr, true, true},
    {"\\rightarrow", "->         ", nullptr, true, true},
    {"\\Rightarrow", "->         ", nullptr, true, true},
    {"\\mapsto", "->     ", nullptr, true, true},
    {"\\to ", "->  ", nullptr, true, true},
    {"\\delta", "delta ", nullptr, true, true},
    {"\\omega", "axiom ", nullptr, true, true},
    {"^{\\circ}", "        ", nullptr, true, true},
    {"^\\circ", "      ", nullptr, true, true},
    {"\\circ", "     ", nullptr, true, true},
    {"\\wedge", "^     ", nullptr, true, true},
    {"\\land", "^    ", nullptr, true, true},
    {"\\cdot", "*    ", nullptr, true, true},
    {"\\times", "*     ", nullptr, true, true},
    {"\\&", "& ", nullptr, true, true},
    {"\\{", "{ ", nullptr, true, true},
    {"\\}", "} ", nullptr, true, true},
    {"\\,", "  ", nullptr, true, true},
    {"\\;", "  ", nullptr, true, true},
    {"=>", "->", nullptr, true, true},
};

// The pasted characters replaced, in one pass.
void replacePastedCharacters(std::string& text, std::vector<std::pair<size_t, std::string>>& replaced, bool cpfg,
                             bool& notation) {
    // One pass over the text (it may be a written-out axiom of millions of modules, parsed again
    // at each edit): only the bytes that start a replacement look further.
    constexpr size_t kSubs = std::size(kPastedSubs);
    static const std::array<std::vector<std::uint8_t>, 256> byFirstByte = [] {
        std::array<std::vector<std::uint8_t>, 256> t;
        for (size_t k = 0; k < kSubs; ++k) t[static_cast<unsigned char>(kPastedSubs[k].from[0])].push_back(std::uint8_t(k));
        return t;
    }();
    std::array<size_t, kSubs> first, count{};
    first.fill(std::string::npos);
    for (size_t at = 0; at < text.size();) {
        const auto& candidates = byFirstByte[static_cast<unsigned char>(text[at])];
        const PastedSub* hit = nullptr;
        size_t k = 0;
        for (std::uint8_t c : candidates) {
            const PastedSub& s = kPastedSubs[c];
            if ((s.lsysOnly && cpfg) || text.compare(at, std::strlen(s.from), s.from) != 0) continue;
            if (s.from[0] == '=' && at > 0 && text[at - 1] != '\0' && std::strchr("=<>!", text[at - 1])) continue;  // "==>"? leave comparisons alone
            hit = &s;
            k = c;
            break;
        }
        if (!hit) {
            ++at;
            continue;
        }
        const size_t len = std::strlen(hit->from);
        text.replace(at, len, hit->to);
        if (first[k] == std::string::npos) first[k] = at;
        ++count[k];
        notation |= hit->abop;
        if (hit->from[0] == '\\') {
            // The math delimiters around a LaTeX arrow: 'F'  $\rightarrow$  'FF'.
            size_t b = at;
            while (b > 0 && isSpace(text[b - 1])) --b;
            if (b > 0 && text[b - 1] == '$') text[b - 1] = ' ';
            size_t f = at + len;
            while (f < text.size() && isSpace(text[f])) ++f;
            if (f < text.size() && text[f] == '$') text[f] = ' ';
        }
        at += len;
    }
    // One warning for a character replaced all over a pasted text: at its first place.
    for (size_t k = 0; k < kSubs; ++k)
        if (kPastedSubs[k].what && count[k])
            replaced.emplace_back(first[k], std::string(kPastedSubs[k].what) +
                                                (count[k] > 1 ? " (and in " + std::to_string(count[k] - 1) + (count[k] == 2 ? " more place)" : " more places)") : ""));
}

// Markdown's italics around words, as PDF converters write ABOP's module names
// (`*plant* -> *internode* + [*leaf*]`), in a text already in ABOP's notation: a '*' that
// opens or closes a word, outside parentheses. `* < + > *` and `x*2` stay.
void blankMarkdownItalics(std::string& text) {
    auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ')' || c == '('; };
    int depth = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') depth = 0;
        else if (c == '(') ++depth;
        else if (c == ')') depth = std::max(0, depth - 1);
        if (c != '*' || depth > 0) continue;
        const char before = i > 0 ? text[i - 1] : ' ', after = i + 1 < text.size() ? text[i + 1] : ' ';
        const bool opens = letter(after) && !word(before) && before != '*';
        const bool closes = letter(before) && !word(after) && after != '*';
        if (opens || closes) text[i] = ' ';
    }
}

// C comments on one line, as ABOP prints its #define lines ("#define r1 0.9 /* ratio */").
void blankLineComments(std::string& text, bool& notation) {
    for (size_t at = text.find("/*"); at != std::string::npos; at = text.find("/*", at + 2)) {
        const size_t close = text.find("*/", at + 2), eol = text.find('\n', at);
        if (close == std::string::npos || (eol != std::string::npos && close > eol)) continue;
        for (size_t i = at; i < close + 2; ++i) text[i] = ' ';
        notation = true;
    }
}

// Inline LaTeX math: a line that starts with '$' ("$n=5, \delta=18^\circ$", "$p1$: ...")
// loses its dollar signs. Elsewhere '$' is ABOP's roll to the horizontal and stays.
void blankMathDollars(std::string& text, bool& notation) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        size_t first = start;
        while (first < end && isSpace(text[first])) ++first;
        if (first < end && text[first] == '$') {
            notation = true;
            for (size_t i = first; i < end; ++i)
                if (text[i] == '$') text[i] = ' ';
        }
        start = end + 1;
    }
}

}  // namespace

void normalizePasted(std::string& text, std::vector<std::pair<size_t, std::string>>& replaced, bool cpfg,
                     bool& notation) {
    replacePastedCharacters(text, replaced, cpfg, notation);
    if (cpfg) return;
    if (notation) blankMarkdownItalics(text);
    blankLineComments(text, notation);
    blankMathDollars(text, notation);
}

// [SECTION] Settings, constants and rules written with '='

namespace {

// The first top-level '=' of `t` that is an assignment, not part of == <= >= != or =>.
size_t assignment(std::string_view t) {
    int depth = 0;
    for (size_t i = 0; i < t.size(); ++i) {
        const char c = t[i];
        if (c == '(' || c == '{' || c == '[') ++depth;
        else if (c == ')' || c == '}' || c == ']') depth = std::max(0, depth - 1);
        else if (c == '=' && depth == 0) {
            const bool before = i > 0 && t[i - 1] != '\0' && std::strchr("=<>!", t[i - 1]) != nullptr;
            const bool after = i + 1 < t.size() && (t[i + 1] == '=' || t[i + 1] == '>');
            if (!before && !after) return i;
        }
    }
    return std::string_view::npos;
}

// A line's parts at its top-level commas and semicolons ("n=5, δ=25.7°"; the web's
// statements "n=30;delta=22.5;"), empty ones left out.
std::vector<std::string_view> topLevelParts(std::string_view t) {
    std::vector<std::string_view> parts;
    int depth = 0;
    size_t start = 0;
    for (size_t i = 0; i <= t.size(); ++i) {
        const char c = i < t.size() ? t[i] : ',';
        if (c == '(' || c == '{' || c == '[') ++depth;
        else if (c == ')' || c == '}' || c == ']') depth = std::max(0, depth - 1);
        else if ((c == ',' || c == ';') && depth == 0) {
            if (!trim(t.substr(start, i - start)).empty()) parts.push_back(t.substr(start, i - start));
            start = i + 1;
        }
    }
    if (parts.empty()) parts.push_back(t);
    return parts;
}

}  // namespace

// Whether `value` is an expression of numbers and the constants known so far (no parameters).
bool Parser::isConstantExpr(const SourceLine& line, std::string_view value) {
    if (trim(value).empty()) return false;
    DiagnosticSink scratch;
    ExprScope scope{nullptr, &m_assignedNames, &m_macros};
    return compileExpr(value, line, scope, scratch).has_value() && scratch.errorCount() == 0;
}

// Whether a rule of the text reads `name` (as a word: `&(delta/2)`), so a setting of that
// name is a variable of the rules too.
bool Parser::readInRules(std::string_view name) const {
    for (const auto& other : m_lines) {
        const std::string_view o = trim(other.src.text);
        if (o.find("->") == std::string_view::npos || o.starts_with("#") || o.starts_with("//")) continue;
        for (size_t at = o.find(name); at != std::string_view::npos; at = o.find(name, at + 1)) {
            auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
            const bool before = at > 0 && word(o[at - 1]);
            const bool after = at + name.size() < o.size() && word(o[at + name.size()]);
            if (!before && !after) return true;
        }
    }
    return false;
}

bool Parser::classifyNotation(Line& l, std::string_view t) {
    const size_t eq = assignment(t);
    if (eq == std::string_view::npos) return false;
    const size_t colon = t.find(':');
    if (colon != std::string_view::npos && colon < eq) return false;  // "define: x = 1", a label
    // Every name given a value with '=' in the text: a value naming them is a constant.
    // Found in passes: a name whose value is a number or uses names found before (R = 1.456,
    // L = 2 * R); "F = F+F" names itself and stays a rule.
    if (!m_assignedScanned) {
        m_assignedScanned = true;
        std::vector<std::pair<std::string_view, std::string_view>> pending;
        for (const auto& other : m_lines) {
            std::string_view o = trim(other.src.text);
            const size_t e = assignment(o);
            if (e == std::string_view::npos || o.find("->") != std::string_view::npos) continue;
            if (const size_t c = o.find(':'); c != std::string_view::npos && c < e) continue;
            for (auto part : topLevelParts(o)) {
                const size_t pe = assignment(part);
                if (pe == std::string_view::npos) continue;
                std::string_view name = trim(part.substr(0, pe));
                if (isIdentifier(name) && (!settingAlias(name) || webVariable(name)))
                    pending.emplace_back(name, trim(part.substr(pe + 1)));
            }
        }
        // One pass in file order (a constant uses the ones above it): linear in the text.
        for (auto& [name, value] : pending)
            if (isConstantExpr(l.src, value)) m_assignedNames.emplace(std::string(name), 1.0);
        // The one-letter modules written in rules (outside parentheses), for the warning below.
        for (const auto& other : m_lines) {
            if (other.src.text.find("->") == std::string_view::npos) continue;
            int depth = 0;
            for (char c : other.src.text) {
                if (c == '(') ++depth;
                else if (c == ')') depth = std::max(0, depth - 1);
                else if (depth == 0 && static_cast<unsigned char>(c) < 128) m_moduleLetters[static_cast<unsigned char>(c)] = true;
            }
        }
    }
    auto usedAsModule = [&](std::string_view key) {
        return key.size() == 1 && static_cast<unsigned char>(key[0]) < 128 && m_moduleLetters[static_cast<unsigned char>(key[0])];
    };
    auto isConstant = [&](std::string_view value) { return isConstantExpr(l.src, value); };
    // "n=5, δ=25.7°" (a caption) is several settings; otherwise the whole line is one.
    std::vector<std::string_view> parts = topLevelParts(t);
    bool caption = parts.size() > 1;
    for (auto part : parts) {
        const size_t pe = assignment(part);
        if (pe == std::string_view::npos || !(settingAlias(trim(part.substr(0, pe))) || isIdentifier(trim(part.substr(0, pe))))) {
            caption = false;
            break;
        }
    }
    if (!caption) {
        // "n=5;": a statement of the web's dialects, its ';' no module (a rule written with
        // '=', "F = F;", keeps it).
        std::string_view u = t;
        while (!u.empty() && (u.back() == ';' || isSpace(u.back()))) u.remove_suffix(1);
        const size_t ue = u.size() < t.size() ? assignment(u) : std::string_view::npos;
        if (ue != std::string_view::npos) {
            const std::string_view k = trim(u.substr(0, ue)), v = trim(u.substr(ue + 1));
            if (settingAlias(k) || isForeignSetting(k) || (isIdentifier(k) && isConstant(v))) t = u;
        }
        parts = {t};
    }
    m_notation = true;
    bool first = true;
    for (auto part : parts) {
        const size_t pe = assignment(part);
        const std::string_view key = trim(part.substr(0, pe));
        const std::string_view value = trim(part.substr(pe + 1));
        const Directive* d = nullptr;
        std::string_view directiveValue = value, writtenKey = key;
        // The web's settings are variables too (`delta=5` ... `&(delta/2)`): a constant as well.
        const bool variable = webVariable(key) && isConstantExpr(l.src, value) && m_assignedNames.count(std::string(key)) &&
                              readInRules(key);
        if (const char* alias = settingAlias(key); alias && !(std::string_view(alias) == "axiom" && key.size() == 1 && isConstant(value))) {
            d = directiveNamed(alias);
            if (key == alias) writtenKey = {};
            if (variable) l.more.push_back({directiveNamed("define"), part, {}});
        } else if (isForeignSetting(key)) {
            warnForeign(l.src, key);
            if (variable) {
                if (first) l.kind = Line::DirectiveLine, l.directive = directiveNamed("define"), l.value = part, l.key = {}, first = false;
                else l.more.push_back({directiveNamed("define"), part, {}});
            }
            continue;
        } else if (const Directive* own = directiveNamed(key); own && key != "define" && key != "module") {
            d = own;  // Sprout's own settings written with '=' (width = 2, tropism = 0 -1 0 0.2)
            writtenKey = {};
        } else if (isIdentifier(key) && isConstant(value)) {
            d = directiveNamed("define");
            directiveValue = part;
            writtenKey = {};
            if (usedAsModule(key) && !m_options.explorer)  // that tool reads `name = value` as a variable, always
                m_sink.warning(l.src, key, "'" + std::string(trim(part)) + "' was read as the constant " + std::string(key) +
                                               " (a slider); for a rule that rewrites the module " + std::string(key) +
                                               ", write '" + std::string(key) + " -> " + std::string(value) + "'");
        } else if (!caption && !key.empty() && value.find("->") == std::string_view::npos) {
            // A rule in the dialects that write them with '=' (F = FF, X = F[+X]F).
            l.kind = Line::Rule;
            l.equalsArrow = size_t(t.data() - l.src.text.data()) + eq;
            return true;
        } else {
            m_sink.error(l.src, part, "expected a setting such as 'n = 5', a constant such as 'R = 1.456' or a rule such as 'F -> F+F'");
            return true;
        }
        if (!d) continue;
        if (first) {
            l.kind = Line::DirectiveLine;
            l.directive = d;
            l.value = directiveValue;
            l.key = writtenKey;
            first = false;
        } else {
            l.more.push_back({d, directiveValue, writtenKey});
        }
    }
    return true;
}

// [SECTION] ABOP's lines: successors over several lines, words as modules

void Parser::joinNotationLines() {
    auto blank = [](std::string_view t) {
        t = trim(t);
        return t.empty() || t.starts_with("#") || t.starts_with("//");
    };
    // Only a successor left open goes on: empty after its arrow, or ending with a turn, a roll
    // or a bracket ("... - - //"); a rule ending with a module is whole, and a line after it
    // that is no setting and no rule is an error to show, not more successor.
    Line* rule = nullptr;  // the rule the lines after it may go on
    std::string joined;    // its text with the lines that went on it
    char last = 0;         // the last character of its successor so far (0: none yet)
    auto finish = [&] {
        if (rule && joined.size() > rule->src.text.size()) {
            m_store.push_back(std::move(joined));  // one logical line, reported at the rule's line
            rule->src.text = rule->src.original = m_store.back();
        }
        rule = nullptr;
    };
    for (auto& l : m_lines) {
        std::string_view t = trim(l.src.text);
        if (blank(t)) {
            if (t.starts_with("#define") || t.starts_with("#ignore")) finish();
            continue;
        }
        if (const size_t arrow = findTopLevel(t, "->"); arrow != std::string_view::npos) {
            finish();
            rule = &l;
            joined = std::string(l.src.text);
            const std::string_view succ = trim(t.substr(arrow + 2));
            last = succ.empty() ? 0 : succ.back();
            continue;
        }
        const bool setting = t.find(':') != std::string_view::npos || assignment(t) != std::string_view::npos;
        const bool open = rule && (last == 0 || std::strchr("+-/\\&^|[{", last) != nullptr);
        if (open && !setting) {
            joined += ' ';
            joined += t;
            last = t.back();
            l.src.text = l.src.text.substr(0, 0);
            continue;
        }
        finish();
    }
    finish();
    // Words as modules: a predecessor written as a word of several letters ("plant", "seg")
    // is one module wherever it is written, as ABOP's fig. 1.26 declares them.
    std::vector<std::string> words;
    for (const auto& l : m_lines) {
        std::string_view t = trim(l.src.text);
        const size_t arrow = findTopLevel(t, "->");
        if (arrow == std::string_view::npos) continue;
        std::string_view head = t.substr(0, arrow);
        if (head.ends_with("-")) head.remove_suffix(1);
        if (const size_t colon = findTopLevel(head, ":"); colon != std::string_view::npos) {
            std::string_view label = trim(head.substr(0, colon));
            if (isRuleLabel(label)) head = head.substr(colon + 1);
        }
        head = trim(head);
        if (head.size() > 1 && isIdentifier(head) && !isRuleLabel(head)) words.emplace_back(head);
    }
    if (!words.empty()) {
        std::string names;
        for (const auto& w : words) names += w + " ";
        declareModules(SourceLine{}, names);
    }
}

void Parser::declareNamedModules() {
    // `SetContour("leaf")`, `SetGuide('axis')`: a word before a quoted name is one module (as
    // L-Py's vocabulary is), where it would otherwise be a letter each.
    std::string names;
    const std::string_view t = m_text;
    for (size_t i = 0; i < t.size(); ++i) {
        if (t[i] != '(') continue;
        size_t q = i + 1;
        while (q < t.size() && isSpace(t[q])) ++q;
        if (q >= t.size() || (t[q] != '\'' && t[q] != '"')) continue;
        size_t b = i;
        while (b > 0 && (std::isalnum(static_cast<unsigned char>(t[b - 1])) || t[b - 1] == '_')) --b;
        if (i - b > 1 && std::isalpha(static_cast<unsigned char>(t[b]))) names += std::string(t.substr(b, i - b)) + " ";
    }
    if (!names.empty()) declareModules(SourceLine{}, names);
}

// [SECTION] Settings applied, and the list of those read

void Parser::applyDirective(const Directive& d, const SourceLine& src, std::string_view value, std::string_view key) {
    if (m_options.explorer && trim(value).empty() && std::string_view(d.name) != "module") {
        // `dlength:` with nothing after it: that tool passes over it.
        const std::string_view t = trim(src.text);
        m_sink.warning(src, t, "'" + std::string(trim(t.substr(0, t.find(':')))) + ":' has no value: left out");
        return;
    }
    m_g.settingsRead.push_back({src.number, d.name, std::string(trim(value)), std::string(key)});
    d.handler(*this, src, value);
}

}  // namespace sprout::detail

namespace sprout {

const char* settingNamed(std::string_view key) { return detail::settingAlias(key); }

std::vector<std::string> settingsReadLines(const Grammar& g) {
    std::vector<std::string> out;
    for (const auto& s : g.settingsRead) {
        std::string line = "line " + std::to_string(s.line) + ": ";
        line += s.name == "define" ? "constant " + s.value : s.name + " = " + s.value;
        if (!s.written.empty()) line += "  (written '" + s.written + "')";
        out.push_back(std::move(line));
    }
    for (const RuleSet* rs : {&g.rules, &g.interpretation, &g.decomposition})
        for (const auto& p : rs->productions)
            if (!p.label.empty()) out.push_back("line " + std::to_string(p.line) + ": rule " + p.label);
    return out;
}

}  // namespace sprout
