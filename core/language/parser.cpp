#include <cstdio>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "core/language/parser_impl.hpp"

namespace sprout {
namespace detail {
namespace {

size_t utf8Length(unsigned char c) {
    if (c < 0x80) return 1;
    if ((c & 0xE0) == 0xC0) return 2;
    if ((c & 0xF0) == 0xE0) return 3;
    if ((c & 0xF8) == 0xF0) return 4;
    return 1;
}

// Position of the first `token` outside parentheses (and, with `braces`, outside cpfg's
// statement blocks `{ }`), or npos.
size_t findTopLevel(std::string_view s, std::string_view token, size_t from = 0, bool braces = false) {
    int depth = 0;
    for (size_t i = from; i < s.size(); ++i) {
        char c = s[i];
        if (c == '(' || (braces && c == '{')) ++depth;
        else if (c == ')' || (braces && c == '}')) depth = std::max(0, depth - 1);
        else if (depth == 0 && s.substr(i, token.size()) == token) return i;
    }
    return std::string_view::npos;
}

size_t findLastTopLevel(std::string_view s, char token) {
    int depth = 0;
    size_t found = std::string_view::npos;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '(') ++depth;
        else if (c == ')') depth = std::max(0, depth - 1);
        else if (depth == 0 && c == token) found = i;
    }
    return found;
}

bool isIdentifier(std::string_view s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

// Text copied from PDFs and word processors: same byte length, so positions stay valid.
void normalize(std::string& text, std::vector<std::pair<size_t, const char*>>& replaced) {
    struct Sub { const char* from; const char* to; const char* what; };
    static const Sub subs[] = {
        {"\xE2\x86\x92", "-> ", nullptr},  // → is an accepted arrow, no warning
        {"\xE2\x88\x92", "-  ", "the Unicode minus sign '\xE2\x88\x92' was read as '-'"},
        {"\xC2\xA0", "  ", nullptr},       // no-break space
    };
    // Old Mac line ends (a lone CR) end a line too.
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
    for (const Sub& s : subs) {
        size_t len = std::strlen(s.from);
        for (size_t at = text.find(s.from); at != std::string::npos; at = text.find(s.from, at + len)) {
            text.replace(at, len, s.to);
            if (s.what) replaced.emplace_back(at, s.what);
        }
    }
}

}  // namespace

Parser::Parser(std::string_view text, const ParseOptions& options) : m_cpfg(options.cpfg), m_options(options) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
    m_text = std::string(text);
    m_original = m_text;
    // The turtle's multi-letter modules (cpfg's predefined surfaces, sphere, disc, moves,
    // generalized cylinders and query modules; the Lparser extensions).
    m_moduleNames = {"~leaf", "~petal", "@O", "@o", "~l", "~p", "~L", "~P", "@L", "@A", "@W", "@T",
                     "@M", "@R", "@v", "@c", "@b", "@Gs", "@Gc", "@Ge", "@Gt", "?P", "?H", "?U", "?L", "?E"};
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
            else {
                m_sink.error(line, m.name, "']' closes a branch that was never opened with '['");
                return false;
            }
        }
    }
    int extra = net > 0 ? 1 : 0;
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

std::optional<double> Parser::constant(const SourceLine& line, std::string_view text) {
    ExprScope scope{nullptr, &m_g.defines, &m_macros};
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
    if (m_g.defines.count(std::string(name))) {
        m_sink.error(line, name, "'" + std::string(name) + "' is defined twice");
        return;
    }
    if (auto v = constant(line, rest)) {
        m_g.defines.emplace(std::string(name), *v);
        m_g.defineOrder.emplace_back(name);
    }
}

void Parser::setAxiom(const SourceLine& line, std::string_view text) {
    if (m_axiomSet) {
        m_sink.error(line, text, "a second axiom (the first is on line " + std::to_string(m_axiomLine) + ")");
        return;
    }
    m_axiomSet = true;
    m_axiomLine = line.number;
    if (text.find_first_of("()") == std::string_view::npos && setPlainAxiom(line, text)) return;
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods) || !checkBrackets(line, text, mods, 0)) return;
    ModuleString axiom;
    for (const auto& m : mods) {
        auto id = symbolFor(line, m.name, int(m.args.size()));
        if (!id) return;
        axiom.symbols.push_back(*id);
        for (auto arg : m.args) {
            auto v = constant(line, arg);
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

void Parser::setIgnore(const SourceLine& line, std::string_view text) {
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods)) return;
    for (const auto& m : mods) {
        if (m.hasParens) {
            m_sink.error(line, m.name, "list only module names after 'ignore:', without parameters");
            return;
        }
        if (m.name == "[" || m.name == "]") {
            m_sink.error(line, m.name, "brackets cannot be ignored: they define the branches contexts follow");
            return;
        }
        auto id = symbolFor(line, m.name, 0);
        if (!id) return;
        NameId n = m_g.alphabet[*id].nameId;
        if (m_g.ignored.size() <= n) m_g.ignored.resize(n + 1, false);
        m_g.ignored[n] = true;
    }
}

bool Parser::parsePattern(const SourceLine& line, std::string_view text, bool allowBrackets,
                          bool allowWildcard, std::vector<std::string>& params,
                          std::vector<PatternModule>& out) {
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods)) return false;
    for (const auto& m : mods) {
        PatternModule p;
        if (m.name == "*" && !m.hasParens) {
            if (!allowWildcard) {
                m_sink.error(line, m.name, "'*' (any module) can only be used in a context");
                return false;
            }
            p.wildcard = true;
            out.push_back(p);
            continue;
        }
        if ((m.name == "[" || m.name == "]") && !allowBrackets) {
            m_sink.error(line, m.name, "brackets are not allowed here: a left context is followed "
                                       "back through parent branches automatically");
            return false;
        }
        p.arity = m.hasParens ? int(m.args.size()) : -1;
        p.firstSlot = std::uint16_t(params.size());
        for (auto arg : m.args) {
            std::string_view name = trim(arg);
            if (!isIdentifier(name)) {
                m_sink.error(line, name.empty() ? arg : name,
                             "a rule's left side names its parameters, e.g. A(x, y); "
                             "compute values on the right side or in the condition");
                return false;
            }
            if (std::find(params.begin(), params.end(), name) != params.end()) {
                m_sink.error(line, name, "parameter '" + std::string(name) + "' is named twice in this rule");
                return false;
            }
            params.emplace_back(name);
        }
        auto id = symbolFor(line, m.name, std::max(p.arity, 0));
        if (!id) return false;
        p.symbol = *id;
        p.name = m_g.alphabet[*id].nameId;
        out.push_back(p);
    }
    return true;
}

bool Parser::parseSuccessor(const SourceLine& line, std::string_view text,
                            const std::vector<std::string>& params, Successor& out, int net) {
    std::vector<RawModule> mods;
    if (!tokenize(line, text, mods) || !checkBrackets(line, text, mods, net)) return false;
    ExprScope scope{&params, &m_g.defines, &m_macros};
    bool ok = true;
    for (const auto& m : mods) {
        auto id = symbolFor(line, m.name, int(m.args.size()));
        if (!id) return false;
        out.symbols.push_back(*id);
        for (auto arg : m.args) {
            auto e = compileExpr(arg, line, scope, m_sink);
            if (e) out.args.push_back(std::move(*e));
            else ok = false;
        }
    }
    return ok;
}

void Parser::parseRule(const SourceLine& line, Section section) {
    std::string_view text = line.text;
    size_t arrow = findTopLevel(text, "->", 0, m_cpfg);
    size_t arrowEnd = arrow + 2;
    if (arrow > 0 && text[arrow - 1] == '-') --arrow;  // L-Py's -->
    std::string_view head = text.substr(0, arrow);
    std::string_view tail = text.substr(arrowEnd);

    // ABOP labels its productions p1, p2, ...: accept "p1: F -> FF".
    size_t colon = findTopLevel(head, ":", 0, m_cpfg);
    if (colon != std::string_view::npos) {
        std::string_view label = trim(head.substr(0, colon));
        if (label.size() >= 2 && label[0] == 'p' &&
            std::all_of(label.begin() + 1, label.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
            head = head.substr(colon + 1);
            colon = findTopLevel(head, ":", 0, m_cpfg);
        }
    }
    std::string_view patterns = colon == std::string_view::npos ? head : head.substr(0, colon);
    std::string_view condition = colon == std::string_view::npos ? std::string_view() : head.substr(colon + 1);

    Production prod;
    prod.line = line.number;
    std::vector<std::string> params;
    size_t lt = findTopLevel(patterns, "<");
    size_t gt = findTopLevel(patterns, ">", lt == std::string_view::npos ? 0 : lt + 1);
    std::string_view leftText, rightText, predText = patterns;
    if (lt != std::string_view::npos) {
        leftText = patterns.substr(0, lt);
        predText = patterns.substr(lt + 1);
        gt = findTopLevel(predText, ">");
    }
    if (gt != std::string_view::npos) {
        rightText = predText.substr(gt + 1);
        predText = predText.substr(0, gt);
    }
    if (gt != std::string_view::npos && findTopLevel(rightText, ">") != std::string_view::npos) {
        m_sink.error(line, rightText.substr(findTopLevel(rightText, ">")),
                     "a second '>': write contexts as 'left < module > right'");
        return;
    }
    if (findTopLevel(predText, "<") != std::string_view::npos) {
        m_sink.error(line, predText.substr(findTopLevel(predText, "<")),
                     "a second '<': write contexts as 'left < module > right'");
        return;
    }
    std::vector<PatternModule> pred;
    if (lt != std::string_view::npos && trim(leftText).empty()) {
        m_sink.error(line, patterns.substr(lt), "'<' needs a left context before it (or '*' for any)");
        return;
    }
    if (!parsePattern(line, leftText, false, true, params, prod.left)) return;
    if (!parsePattern(line, predText, true, false, params, pred)) return;
    if (gt != std::string_view::npos && trim(rightText).empty()) {
        m_sink.error(line, predText.substr(gt), "'>' needs a right context after it (or '*' for any)");
        return;
    }
    if (!parsePattern(line, rightText, true, true, params, prod.right)) return;
    if (pred.size() != 1) {
        std::string_view p = trim(predText);
        if (pred.empty()) {
            m_sink.error(line, p.empty() ? line.text : p, "the rule has no module to rewrite before '->'");
        } else {
            std::string msg = "a rule rewrites one module, but '" + std::string(p) + "' is " +
                              std::to_string(pred.size()) + " modules";
            if (isIdentifier(p)) msg += "; declare it first with 'module: " + std::string(p) + "'";
            else msg += "; use contexts for neighbours, as in 'A < B > C -> ...'";
            m_sink.error(line, p, msg);
        }
        return;
    }
    prod.pred = pred[0];
    if (prod.pred.arity < 0) {  // a predecessor without parentheses has no parameters
        prod.pred.arity = 0;
    }
    // Contexts of only '*' mean "any": ABOP's `* < + > * -> -`.
    auto onlyWildcards = [](const std::vector<PatternModule>& v) {
        return std::all_of(v.begin(), v.end(), [](const PatternModule& p) { return p.wildcard; });
    };
    if (onlyWildcards(prod.left)) prod.left.clear();
    if (onlyWildcards(prod.right)) prod.right.clear();
    // cpfg: `pred : {pre} condition {post} --> succ`, `*` for no condition. Names assigned
    // in the blocks are the production's locals, in slots after its formal parameters.
    std::string_view preBlock, postBlock;
    if (m_cpfg && colon != std::string_view::npos) {
        if (!splitCpfgCondition(line, condition, preBlock, condition, postBlock)) return;
        if (trim(condition) == "*" || (trim(condition).empty() && (!preBlock.empty() || !postBlock.empty())))
            condition = {};
        if (condition.empty()) colon = std::string_view::npos;
    }
    prod.firstLocal = std::uint16_t(params.size());
    if (!preBlock.empty() || !postBlock.empty()) {
        std::vector<std::string> assigned;
        collectAssigned(preBlock, assigned);
        collectAssigned(postBlock, assigned);
        for (const auto& name : assigned) {
            if (m_g.defines.count(name)) {
                m_sink.error(line, line.text.substr(size_t(preBlock.data() - line.text.data())),
                             "'" + name + "' is a constant (#define) and cannot be assigned in a block: use another name");
                return;
            }
            if (std::find(params.begin(), params.end(), name) == params.end()) params.push_back(name);
        }
        if (params.size() > 255) {
            m_sink.error(line, preBlock, "too many parameters and local variables in one production (the limit is 255)");
            return;
        }
    }
    prod.slotCount = int(params.size());

    ExprScope scope{&params, &m_g.defines, &m_macros};
    bool ok = true;
    if (!preBlock.empty() && !parseBlock(line, preBlock, params, prod.pre)) return;
    if (!postBlock.empty() && !parseBlock(line, postBlock, params, prod.post)) return;
    if (colon != std::string_view::npos) {
        if (trim(condition).empty()) {
            m_sink.error(line, condition, "expected a condition after ':' (e.g. 'A(t) : t > 1 -> F')");
            return;
        }
        prod.condition = compileExpr(condition, line, scope, m_sink);
        ok = prod.condition.has_value();
    }
    if (size_t second = findTopLevel(tail, "->"); second != std::string_view::npos) {
        m_sink.error(line, tail.substr(second), "a second '->': a rule has one arrow, one rule per line");
        return;
    }
    size_t probColon = findLastTopLevel(tail, ':');
    std::string_view succText = tail;
    if (probColon != std::string_view::npos) {
        succText = tail.substr(0, probColon);
        std::string_view probText = trim(tail.substr(probColon + 1));
        auto p = constant(line, probText);
        if (!p) return;
        if (!(*p >= 0)) {
            m_sink.error(line, probText, "a probability cannot be negative");
            return;
        }
        prod.probability = *p;
    }
    if (size_t extra = findTopLevel(succText, ":"); extra != std::string_view::npos) {
        m_sink.error(line, succText.substr(extra), "a second ':' after '->': a rule has at most one probability");
        return;
    }
    if (m_cpfg && trim(succText) == "*") succText = {};  // cpfg's empty successor
    if (section == Section::Decomposition && prod.hasContext()) {
        m_sink.error(line, patterns, "decomposition rules are context-free: move the context to a production");
        return;
    }
    int net = prod.pred.symbol == Alphabet::kPush ? 1 : prod.pred.symbol == Alphabet::kPop ? -1 : 0;
    if (!parseSuccessor(line, succText, params, prod.successor, net) || !ok) return;
    RuleSet& target = section == Section::Interpretation   ? m_g.interpretation
                      : section == Section::Decomposition ? m_g.decomposition
                                                          : m_g.rules;
    target.productions.push_back(std::move(prod));
}

void Parser::classify(Line& l, Section& section) {
    std::string_view t = trim(l.src.text);
    if (t.empty()) return;
    // cpfg's preprocessor-style directives, before '#' comments.
    for (const char* word : {"#define", "#ignore"}) {
        std::string_view w(word);
        if (t.starts_with(w) && (t.size() == w.size() || isSpace(t[w.size()]) || t[w.size()] == ':')) {
            for (const auto& d : directives())
                if (w.substr(1) == d.name) l.directive = &d;
            l.kind = Line::DirectiveLine;
            l.value = t.substr(w.size());
            if (l.value.starts_with(":")) l.value.remove_prefix(1);  // "#ignore: + -" as well
            l.value = trim(l.value);
            return;
        }
    }
    if (t.starts_with("#") || t.starts_with("//")) return;
    l.section = section;
    if (size_t arrow = findTopLevel(t, "->"); arrow != std::string_view::npos) {
        // "axiom: F -> FF": a setting and a rule run together on one line.
        size_t colon = t.find(':');
        if (colon != std::string_view::npos && colon < arrow) {
            std::string k(trim(t.substr(0, colon)));
            std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
            for (const auto& d : directives())
                if (k == d.name || (k == "iterations" && std::string_view(d.name) == "n")) {
                    m_sink.error(l.src, t.substr(arrow), "'" + k + ":' is a setting and '->' makes a rule: put the rule on a line of its own");
                    return;
                }
        }
        l.kind = Line::Rule;
        return;
    }
    size_t colon = t.find(':');
    std::string_view key = trim(t.substr(0, colon));
    if (colon == std::string_view::npos || key.empty() ||
        !(isIdentifier(key) || key == "\xCF\x89" /* ω */)) {
        m_sink.error(l.src, t, "expected a rule such as 'F -> F+F' or a setting such as 'angle: 90'");
        return;
    }
    std::string_view value = trim(t.substr(colon + 1));
    std::string k(key);
    std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
    if (k == "interpretation" || k == "homomorphism" || k == "productions" || k == "rules" ||
        k == "derivation") {
        if (!value.empty()) m_sink.error(l.src, value, "'" + k + ":' starts a section; put its rules on the next lines");
        section = k == "interpretation" || k == "homomorphism" ? Section::Interpretation : Section::Productions;
        return;
    }
    if (key == "\xCF\x89") k = "axiom";
    for (const auto& d : directives())
        if (k == d.name) l.directive = &d;
    if (!l.directive) {
        std::vector<std::string> names;
        for (const auto& d : directives()) names.emplace_back(d.name);
        std::string msg = "unknown setting '" + std::string(key) + "'";
        std::string guess = closestMatch(k, names);
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        else msg += " (a rule needs '->')";
        m_sink.error(l.src, key, msg);
        return;
    }
    l.kind = Line::DirectiveLine;
    l.value = value;
}

void Parser::lint() {
    // A deterministic context-free rule without a condition always applies, so later rules
    // for the same module are dead: say so rather than leave the user wondering.
    for (const RuleSet* rs : {&m_g.rules, &m_g.interpretation, &m_g.decomposition}) {
        for (const auto& list : rs->bySymbol) {
            const Production* total = nullptr;
            double probSum = 0;
            int probCount = 0;
            bool guarded = false;
            for (auto idx : list) {
                const Production& p = rs->productions[idx];
                if (total) {
                    Diagnostic d{p.line, 1,
                                 "this rule never applies: the rule on line " + std::to_string(total->line) +
                                     " always rewrites '" + m_g.alphabet[p.pred.symbol].name +
                                     "' first (put rules with conditions or contexts before it)",
                                 Severity::Warning};
                    m_sink.add(d);
                    continue;
                }
                bool unconditional = !p.condition && !p.hasContext();
                if (unconditional && p.stochastic()) {
                    probSum += p.probability;
                    ++probCount;
                } else if (p.stochastic()) {
                    guarded = true;  // the applicable set varies: the sum says nothing
                } else if (unconditional) {
                    total = &p;
                }
            }
            if (probCount > 0 && !guarded && std::abs(probSum - 1.0) > 1e-6) {
                const Production& p = rs->productions[list.front()];
                std::string sum, rest;
                appendNumber(sum, probSum);
                appendNumber(rest, std::round((1 - probSum) * 1e6) / 1e4);
                m_sink.add({p.line, 1,
                            "the probabilities of the rules for '" + m_g.alphabet[p.pred.symbol].name +
                                "' add up to " + sum +
                                (probSum > 1 ? ", not 1: they are used as weights"
                                             : ": the module stays unchanged the other " + rest + "% of the time"),
                            Severity::Warning});
            }
        }
    }
}

ParseResult Parser::run() {
    std::vector<std::pair<size_t, const char*>> replaced;
    normalize(m_text, replaced);
    if (m_cpfg) {
        m_original = m_text;  // normalising keeps byte positions; comments are blanked in m_text
        m_g.cutInNextStep = true;
        buildCpfgLines();
    }
    // Split into lines; `original` keeps the typed text for column numbers.
    size_t start = 0;
    int number = 1;
    while (!m_cpfg && start <= m_text.size()) {
        size_t end = m_text.find('\n', start);
        if (end == std::string::npos) end = m_text.size();
        Line l;
        l.src.number = number++;
        l.src.text = std::string_view(m_text).substr(start, end - start);
        l.src.original = std::string_view(m_original).substr(start, end - start);
        if (l.src.text.ends_with('\r')) l.src.text.remove_suffix(1);
        m_lines.push_back(l);
        start = end + 1;
    }
    for (auto [offset, what] : replaced) {
        for (const auto& l : m_lines) {
            if (l.src.text.data() < m_text.data() || l.src.text.data() > m_text.data() + m_text.size()) continue;
            size_t ls = size_t(l.src.text.data() - m_text.data());
            if (offset >= ls && offset <= ls + l.src.text.size()) {
                m_sink.warning(l.src, l.src.text.substr(offset - ls), what);
                break;
            }
        }
    }
    // Control characters (a binary file, or a paste gone wrong): one error per line, at the
    // first one, and the line is not read further.
    int binaryLines = 0;
    for (auto& l : m_lines) {
        // A comment may hold anything but control characters (old files in Latin-1 included).
        const std::string_view t = trim(l.src.text);
        const bool comment = t.starts_with("//") || (t.starts_with("#") && !t.starts_with("#define") && !t.starts_with("#ignore"));
        for (size_t i = 0; i < l.src.text.size(); ++i) {
            unsigned char c = static_cast<unsigned char>(l.src.text[i]);
            if (c >= 0x80 && !comment) {  // a UTF-8 sequence: lead byte and the right number of continuations
                const int len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
                bool valid = len > 0 && i + size_t(len) <= l.src.text.size();
                for (int k = 1; valid && k < len; ++k) valid = (static_cast<unsigned char>(l.src.text[i + size_t(k)]) & 0xC0) == 0x80;
                if (!valid) {
                    char msg[120];
                    std::snprintf(msg, sizeof msg, "this text is not UTF-8 (byte 0x%02x): save the file as UTF-8", c);
                    if (++binaryLines <= 5) m_sink.error(l.src, l.src.text.substr(i), msg);
                    l.src.text = l.src.text.substr(0, 0);
                    break;
                }
                i += size_t(len) - 1;
                continue;
            }
            if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
                char msg[96];
                std::snprintf(msg, sizeof msg, "unexpected control character (byte 0x%02x): is this a text file?", c);
                if (++binaryLines <= 5) m_sink.error(l.src, l.src.text.substr(i), msg);
                l.src.text = l.src.text.substr(0, 0);
                break;
            }
        }
    }
    Section section = Section::Productions;
    bool ended = false;
    for (auto& l : m_lines) {
        if (m_cpfg) classifyCpfg(l, section, ended);
        else classify(l, section);
    }
    for (int phase = 0; phase <= 2; ++phase) {
        for (auto& l : m_lines) {
            if (l.kind == Line::DirectiveLine && l.directive->phase == phase) {
                if (m_cpfg) m_depthSection = l.section;
                l.directive->handler(*this, l.src, l.value);
            } else if (l.kind == Line::Rule && phase == 2) {
                parseRule(l.src, l.section);
            }
        }
    }
    if (!m_axiomSet && m_sink.errorCount() == 0)
        m_sink.add({1, 1, "the grammar has no axiom: add a line such as 'axiom: F'", Severity::Error});

    m_g.rules.index(m_g.alphabet.size());
    m_g.interpretation.index(m_g.alphabet.size());
    m_g.decomposition.index(m_g.alphabet.size());
    m_g.ignored.resize(m_g.alphabet.nameCount(), false);
    if (m_considerSet) {  // cpfg `consider:`: only the listed modules count for contexts
        m_g.ignored.assign(m_g.alphabet.nameCount(), true);
        for (NameId n : m_considered) m_g.ignored[n] = false;
        for (size_t s = 0; s < m_g.alphabet.size(); ++s) {
            const auto& sym = m_g.alphabet[SymbolId(s)];
            if (sym.name == "[" || sym.name == "]") m_g.ignored[sym.nameId] = false;
        }
    }
    if (m_cpfg) loadSurfaceFiles();
    if (m_g.environment.empty() && m_g.alphabet.findName("?E")) {
        // Where it is first written, for the message.
        for (const auto& l : m_lines) {
            if (size_t at = l.src.text.find("?E"); at != std::string_view::npos && l.kind != Line::Skip) {
                m_sink.error(l.src, l.src.text.substr(at), "?E asks the environment, but the grammar declares none: add a line "
                                                            "such as 'environment: sphere 0 10 0 8'");
                break;
            }
        }
    }
    lint();

    ParseResult result;
    result.diagnostics = std::move(m_sink.all());
    if (m_cpfg) finishCpfg(result.diagnostics);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                         return a.line != b.line ? a.line < b.line : a.col < b.col;
                     });
    if (!hasErrors(result.diagnostics)) result.grammar = std::make_shared<const Grammar>(std::move(m_g));
    return result;
}

}  // namespace detail

ParseResult parse(std::string_view text) { return detail::Parser(text).run(); }
ParseResult parse(std::string_view text, const ParseOptions& options) { return detail::Parser(text, options).run(); }

void RuleSet::index(size_t alphabetSize) {
    bySymbol.assign(alphabetSize, {});
    for (size_t i = 0; i < productions.size(); ++i)
        bySymbol[productions[i].pred.symbol].push_back(std::uint32_t(i));
}


bool Grammar::parametric() const {
    if (!axiom.params.empty()) return true;
    for (const RuleSet* rs : {&rules, &interpretation})
        for (const auto& p : rs->productions)
            if (p.slotCount > 0 || !p.successor.args.empty()) return true;
    return false;
}

bool Grammar::hasContext() const {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.hasContext(); });
}

bool Grammar::stochastic() const {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.stochastic(); });
}

bool Grammar::hasQueries() const {
    for (size_t s = 0; s < alphabet.size(); ++s)
        if (queryKind(alphabet[SymbolId(s)].name)) return true;
    return false;
}

bool Grammar::needsGeneralEngine() const {
    if (!decomposition.productions.empty() || hasQueries()) return true;
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const Production& p) { return p.hasBlocks(); });
}

bool Grammar::usesCut() const {
    auto hasCut = [](const auto& symbols) {
        return std::find(symbols.begin(), symbols.end(), Alphabet::kCut) != symbols.end();
    };
    if (hasCut(axiom.symbols)) return true;
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [&](const Production& p) { return hasCut(p.successor.symbols); });
}

}  // namespace sprout
