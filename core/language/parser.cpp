// The .lsys parser's pieces (see parser_run.cpp for the whole file and parser_rules.cpp for
// rules): module names and tokens, constants and settings' numbers, defines, the axiom.
//
// Index of this file:
//   [SECTION] Module names, tokens and symbols
//   [SECTION] Constants and settings' numbers
//   [SECTION] Declared names: modules and defines
//   [SECTION] The axiom, and quoted names as parameters
//   [SECTION] Modules contexts ignore

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/language/parser_impl.hpp"

namespace sprout {
namespace detail {

// [SECTION] Module names, tokens and symbols

Parser::Parser(std::string_view text, const ParseOptions& options) : m_cpfg(options.cpfg), m_options(options) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
    m_text = std::string(text);
    m_original = m_text;
    m_g.environment.program = options.environmentProgram;  // a VLab object's -e program
    m_g.curves = options.curves;  // func() and @# use them at derive and draw time
    m_g.settings.viewTextures = options.viewTextures;  // @Tx(n)
    // The turtle's multi-letter modules (cpfg's predefined surfaces, sphere, disc, moves,
    // generalized cylinders and query modules; the Lparser extensions; L-system Explorer's
    // move without drawing, home, contours and their use, radius spline; cpfg's @!, the sides of
    // its contours).
    m_moduleNames = {"~leaf", "~petal", "@O", "@o", "~l", "~p", "~L", "~P", "@L", "@A", "@W", "@T",
                     "@M", "@R", "@v", "@c", "@b", "@Gs", "@Gc", "@Ge", "@Gt", "?P", "?H", "?U", "?L", "?E",
                     "@m", "@H", "@#", "@Gr", "@Cs", "@Ce", "@Ca", "@Cb", "@Cc", "@Cm", "@Cn", "@Ct", "@Ds", "@De",
                     "@Di", "@bo", "@bd", "@!",
                     // cpfg's scale, tropism elasticity and twist, texture, patch and circle modules (blackbox.c)
                     "@D", "@Dd", "@Ts", "@Ti", "@Td", "@Tp", "@Tf", "@Tx", "@PS", "@PC", "@PD", "@bc"};
    indexModuleNames();
}

void Parser::indexModuleNames() {
    std::stable_sort(m_moduleNames.begin(), m_moduleNames.end(),
                     [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
    m_nameStart.fill(false);
    for (const auto& name : m_moduleNames)
        if (!name.empty()) m_nameStart[static_cast<unsigned char>(name[0])] = true;
}

size_t Parser::nameLength(std::string_view s, size_t pos) const {
    // Most characters start no multi-letter name: one table lookup instead of a comparison
    // with each name (a 5 M-module axiom spent a third of its parse here).
    if (m_nameStart[static_cast<unsigned char>(s[pos])])
        for (const auto& name : m_moduleNames)
            if (s.substr(pos, name.size()) == name) return name.size();
    // cpfg: '~' and one character name a surface (~l a leaf, ~s the surface file s.s ...).
    if (m_cpfg && s[pos] == '~' && pos + 1 < s.size() && std::isalnum(static_cast<unsigned char>(s[pos + 1]))) return 2;
    return std::min(s.size() - pos, utf8Length(static_cast<unsigned char>(s[pos])));
}

bool Parser::tokenize(const SourceLine& line, std::string_view text, std::vector<RawModule>& out) {
    size_t i = 0;
    while (i < text.size()) {
        if (isSpace(text[i])) {
            ++i;
            continue;
        }
        char c = text[i];
        if ((c == '(' || c == ')') && m_options.explorer) {  // that tool reads past it
            m_sink.warning(line, text.substr(i), std::string("a '") + c + "' that follows no module name: left out, as L-system Explorer leaves it out");
            ++i;
            continue;
        }
        if (c == '(' || c == ')') {
            m_sink.error(line, text.substr(i),
                         c == '(' ? "'(' must follow a module name, as in F(1)"
                                  : "')' has no matching '('");
            return false;
        }
        RawModule m;
        size_t len = nameLength(text, i);
        m.name = text.substr(i, len);
        i += len;
        size_t j = i;
        while (j < text.size() && isSpace(text[j])) ++j;
        if (j < text.size() && text[j] == '(') {
            m.hasParens = true;
            int depth = 0;
            size_t argStart = j + 1, k = j;
            for (; k < text.size(); ++k) {
                if ((text[k] == '\'' || text[k] == '"') && depth == 1) {  // a quoted name: its commas and parentheses are text
                    const size_t close = text.find(text[k], k + 1);
                    if (close != std::string_view::npos) {
                        k = close;
                        continue;
                    }
                }
                if (text[k] == '(') ++depth;
                else if (text[k] == ')' && --depth == 0) break;
                else if (text[k] == ',' && depth == 1) {
                    m.args.push_back(text.substr(argStart, k - argStart));
                    argStart = k + 1;
                }
            }
            if (k >= text.size()) {
                m_sink.error(line, text.substr(j), "this '(' is never closed");
                return false;
            }
            std::string_view last = text.substr(argStart, k - argStart);
            if (!m.args.empty() || !trim(last).empty()) m.args.push_back(last);
            i = k + 1;
        }
        if (int(m.args.size()) > Alphabet::kMaxArity) {
            m_sink.error(line, m.name, "a module can have at most 32 parameters");
            return false;
        }
        out.push_back(m);
    }
    return true;
}

std::optional<SymbolId> Parser::symbolFor(const SourceLine& line, std::string_view name, int arity) {
    // A query module gets a point or a vector: three parameters (?E takes any number).
    if (const char q = queryKind(name); q && q != 'E' && arity != 3 && arity != 0) {
        m_sink.error(line, name, "the query module '" + std::string(name) + "' has 3 parameters (x, y, z) that the turtle fills in, not " +
                                     std::to_string(arity));
        return std::nullopt;
    }
    if (arity > 0 && (name == "[" || name == "]" || name == "%")) {
        m_sink.error(line, name, "'" + std::string(name) + "' takes no parameters");
        return std::nullopt;
    }
    auto id = m_g.alphabet.intern(name, arity);
    if (!id) m_sink.error(line, name, "too many different modules (the limit is 65535)");
    return id;
}

bool Parser::checkBrackets(const SourceLine& line, std::string_view text,
                           const std::vector<RawModule>& mods, int net) {
    // A rule that rewrites '[' or ']' (an interpretation such as '[ -> [+') must keep the
    // bracket it replaces; every other string must be balanced.
    std::vector<std::string_view> open;
    int closedOuter = 0;
    for (const auto& m : mods) {
        if (m.name == "[") open.push_back(m.name);
        else if (m.name == "]") {
            if (!open.empty()) open.pop_back();
            else if (net < 0 && closedOuter == 0) closedOuter = 1;
            else if (m_options.explorer) {  // that tool reads the string as written: the turtle and contexts allow it
                m_sink.warning(line, m.name, "']' closes a branch this successor did not open: read as written, as L-system "
                                             "Explorer reads it");
                return true;
            } else {
                m_sink.error(line, m.name, "']' closes a branch that was never opened with '['");
                return false;
            }
        }
    }
    int extra = net > 0 ? 1 : 0;
    if (int(open.size()) > extra && m_options.explorer) {
        m_sink.warning(line, open.back(), "this '[' is not closed in this successor: read as written, as L-system Explorer reads it");
        return true;
    }
    if (int(open.size()) > extra) {
        m_sink.error(line, open.back(), "this '[' is never closed with ']'");
        return false;
    }
    if (int(open.size()) != extra || closedOuter != (net < 0 ? 1 : 0)) {
        m_sink.error(line, trim(text), std::string("a rule for '") + (net > 0 ? "[" : "]") +
                                     "' must keep one unmatched '" + (net > 0 ? "[" : "]") + "'");
        return false;
    }
    return true;
}

// [SECTION] Constants and settings' numbers

std::optional<double> Parser::constant(const SourceLine& line, std::string_view text) {
    ExprScope scope{nullptr, &m_g.defines, &m_macros, nullptr, nullptr, m_options.curves.get()};
    scope.cpfg = m_options.tabContinues;
    auto e = compileExpr(text, line, scope, m_sink);
    if (!e) return std::nullopt;
    double v;
    if (e->isConstant()) {
        v = e->constantValue();
    } else {
        // rand() in the axiom, defines or settings: one stream for the whole file, seeded by
        // `seed:` (read before everything else), so each call gives a new value.
        if (!m_rng) m_rng = Rng::forStream(m_g.settings.seed, 0x5eed);
        v = e->eval(nullptr, *m_rng);
    }
    if (!std::isfinite(v)) {
        m_sink.error(line, text, std::string("this value is ") + (std::isnan(v) ? "not a number" : "infinite") +
                                     " (a division by zero, or a number too large?)");
        return std::nullopt;
    }
    return v;
}

std::optional<Jittered> Parser::jittered(const SourceLine& line, std::string_view text) {
    size_t tilde = findTopLevel(text, "~");
    auto mean = constant(line, tilde == std::string_view::npos ? text : text.substr(0, tilde));
    if (!mean) return std::nullopt;
    Jittered j{*mean, 0};
    if (tilde != std::string_view::npos) {
        auto sigma = constant(line, text.substr(tilde + 1));
        if (!sigma) return std::nullopt;
        if (*sigma < 0) {
            m_sink.error(line, text.substr(tilde + 1), "the spread after '~' cannot be negative");
            return std::nullopt;
        }
        j.sigma = *sigma;
    }
    return j;
}

std::optional<std::vector<double>> Parser::numbers(const SourceLine& line, std::string_view text,
                                                   size_t minCount, size_t maxCount, const char* example) {
    std::vector<std::string_view> parts;
    bool commas = findTopLevel(text, ",") != std::string_view::npos;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (commas ? text[i] == ',' : isSpace(text[i]))) ++i;
        size_t start = i;
        int depth = 0;
        while (i < text.size()) {
            char c = text[i];
            if (c == '(') ++depth;
            else if (c == ')') --depth;
            else if (depth == 0 && (commas ? c == ',' : isSpace(c))) break;
            ++i;
        }
        if (i > start) parts.push_back(trim(text.substr(start, i - start)));
    }
    if (parts.size() < minCount || parts.size() > maxCount) {
        m_sink.error(line, text.empty() ? line.text.substr(line.text.size()) : text,
                     std::string("expected ") + (minCount == maxCount ? std::to_string(minCount)
                                                   : std::to_string(minCount) + " to " + std::to_string(maxCount)) +
                         " values, as in '" + example + "'");
        return std::nullopt;
    }
    std::vector<double> out;
    for (auto part : parts) {
        auto v = constant(line, part);
        if (!v) return std::nullopt;
        out.push_back(*v);
    }
    return out;
}

// [SECTION] Declared names: modules and defines

void Parser::declareModules(const SourceLine& line, std::string_view names) {
    size_t i = 0;
    while (i < names.size()) {
        while (i < names.size() && (isSpace(names[i]) || names[i] == ',')) ++i;
        size_t start = i;
        while (i < names.size() && !isSpace(names[i]) && names[i] != ',') ++i;
        std::string_view name = names.substr(start, i - start);
        if (name.empty()) continue;
        if (name.find_first_of("()[]") != std::string_view::npos) {
            m_sink.error(line, name, "a module name cannot contain brackets or parentheses");
            continue;
        }
        if (std::find(m_moduleNames.begin(), m_moduleNames.end(), name) == m_moduleNames.end())
            m_moduleNames.emplace_back(name);
    }
    indexModuleNames();
}

void Parser::define(const SourceLine& line, std::string_view text) {
    text = trim(text);
    size_t nameEnd = 0;
    while (nameEnd < text.size() && !isSpace(text[nameEnd]) && text[nameEnd] != '=') ++nameEnd;
    std::string_view name = text.substr(0, nameEnd);
    std::string_view rest = trim(text.substr(nameEnd));
    if (rest.starts_with("=") && !rest.starts_with("==")) rest = trim(rest.substr(1));
    if (!isIdentifier(name)) {
        m_sink.error(line, name.empty() ? text : name,
                     "expected 'define: name = value', with a name made of letters, digits and _");
        return;
    }
    if (rest.empty()) {
        m_sink.error(line, text.substr(nameEnd), "'" + std::string(name) + "' needs a value: define: " +
                                                     std::string(name) + " = 1.5");
        return;
    }
    if (auto it = m_g.defines.find(std::string(name)); it != m_g.defines.end()) {
        if (!m_cpfg) {
            m_sink.error(line, name, "'" + std::string(name) + "' is defined twice");
            return;
        }
        // cpfg's #define is the C preprocessor's: the same value again is nothing; another
        // value replaces the first, with a warning.
        auto v = constant(line, rest);
        if (v && *v != it->second)
            m_sink.warning(line, name, "'" + std::string(name) + "' is defined again with another value: the last one is used");
        if (v) it->second = *v;
        return;
    }
    if (auto v = constant(line, rest)) {
        m_g.defines.emplace(std::string(name), *v);
        m_g.defineOrder.emplace_back(name);
    }
}

// [SECTION] The axiom, and quoted names as parameters

void Parser::setAxiom(const SourceLine& line, std::string_view text) {
    if (m_axiomSet) {
        m_sink.error(line, text, "a second axiom (the first is on line " + std::to_string(m_axiomLine) + ")");
        return;
    }
    m_axiomSet = true;
    m_axiomLine = line.number;
    if (text.find_first_of("()") == std::string_view::npos && setPlainAxiom(line, text)) return;
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods)) return;
    if (m_options.explorer) {
        // L-system Explorer draws an axiom whose branch is never closed: it ends at the end.
        std::vector<std::string_view> open;
        for (const auto& m : mods) {
            if (m.name == "[") open.push_back(m.name);
            else if (m.name == "]" && !open.empty()) open.pop_back();
        }
        if (!open.empty()) {
            m_sink.warning(line, open.front(), "this '[' is never closed with ']': the branch ends at the end of the axiom");
            for (size_t k = 0; k < open.size(); ++k) mods.push_back(RawModule{std::string_view("]"), {}, false});
        }
    }
    if (!checkBrackets(line, text, mods, 0)) return;
    ModuleString axiom;
    for (const auto& m : mods) {
        auto id = symbolFor(line, m.name, int(m.args.size()));
        if (!id) return;
        axiom.symbols.push_back(*id);
        for (size_t k = 0; k < m.args.size(); ++k) {
            if (auto name = quotedName(m.args[k])) {
                axiom.params.push_back(m_g.alphabet.internString(*name));
                m_g.alphabet.markNameArg(*id, int(k));
                continue;
            }
            auto v = constant(line, m.args[k]);
            if (!v) return;
            axiom.params.push_back(*v);
        }
    }
    if (axiom.size() == 0) {
        m_sink.error(line, text, "the axiom is empty: write the starting string, e.g. 'axiom: F'");
        return;
    }
    m_g.axiom = std::move(axiom);
}

// An axiom without parameters (a written-out curve of millions of modules): symbols straight
// from the text, without a token list (48 bytes a module) or a lookup per module. False when
// it has errors to report the usual way.
bool Parser::setPlainAxiom(const SourceLine& line, std::string_view text) {
    ModuleString axiom;
    axiom.symbols.reserve(text.size());
    std::array<std::int32_t, 256> byByte;
    byByte.fill(-1);
    std::vector<size_t> open;  // offsets of the '[' not closed yet
    for (size_t i = 0; i < text.size();) {
        if (isSpace(text[i])) {
            ++i;
            continue;
        }
        const size_t len = nameLength(text, i);
        std::string_view name = text.substr(i, len);
        if (name == "[") open.push_back(i);
        else if (name == "]") {
            if (open.empty()) return false;  // the usual path says where
            open.pop_back();
        }
        SymbolId id;
        const unsigned char b = static_cast<unsigned char>(text[i]);
        if (len == 1 && byByte[b] >= 0) {
            id = SymbolId(byByte[b]);
        } else {
            auto s = symbolFor(line, name, 0);
            if (!s) return true;  // reported
            id = *s;
            if (len == 1) byByte[b] = std::int32_t(id);
        }
        axiom.symbols.push_back(id);
        i += len;
    }
    if (!open.empty()) return false;
    if (axiom.size() == 0) return false;
    m_g.axiom = std::move(axiom);
    return true;
}

std::optional<std::string_view> Parser::quotedName(std::string_view arg) {
    arg = trim(arg);
    if (arg.size() < 2 || (arg.front() != '\'' && arg.front() != '"') || arg.back() != arg.front() ||
        arg.find(arg.front(), 1) != arg.size() - 1)
        return std::nullopt;
    return trim(arg.substr(1, arg.size() - 2));
}

// [SECTION] Modules contexts ignore

void Parser::setIgnore(const SourceLine& line, std::string_view text) {
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods)) return;
    for (const auto& m : mods) {
        if (m.hasParens) {
            m_sink.error(line, m.name, "list only module names after 'ignore:', without parameters");
            return;
        }
        if ((m.name == "[" || m.name == "]") && !m_options.tabContinues) {  // cpfg: its right context passes them
            // Written in other tools' files (L-system Explorer's `ignore: ]`): left out, not an error.
            m_sink.warning(line, m.name, "brackets are not ignored (left out of 'ignore:'): they define the branches contexts follow");
            continue;
        }
        auto id = symbolFor(line, m.name, 0);
        if (!id) return;
        NameId n = m_g.alphabet[*id].nameId;
        if (m_g.ignored.size() <= n) m_g.ignored.resize(n + 1, false);
        m_g.ignored[n] = true;
    }
}

}  // namespace detail
}  // namespace sprout
