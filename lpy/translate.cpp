#include "lpy/translate.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <initializer_list>

namespace sprout::lpy {
namespace {

// L-Py's predefined modules, each with its aliases (src/cpp/predefinedmodules.cpp). The
// first six keep the ids ModuleClasses names.
const std::vector<std::vector<const char*>>& predefined() {
    static const std::vector<std::vector<const char*>> table = {
        {"[", "SB"}, {"]", "EB"}, {"%", "Cut"}, {"*", "any"}, {"None"}, {"~", "surface"},
        {"F"}, {"f"}, {"nF"}, {"+", "Left"}, {"-", "Right"}, {"^", "Up"}, {"&", "Down"},
        {"/", "RollL"}, {"\\", "RollR"}, {"iRollL"}, {"iRollR"}, {"|", "TurnAround"},
        {"@v", "RollToVert"}, {"@h", "RollToHorizontal"}, {"@R", "SetHead"}, {"EulerAngles"},
        {"Pinpoint"}, {"PinpointRel"}, {"@M", "MoveTo"}, {"MoveRel"}, {"LineTo"}, {"LineRel"},
        {"OLineTo"}, {"OLineRel"}, {"_", "IncWidth"}, {"!", "DecWidth"}, {"SetWidth"},
        {";", "IncColor"}, {",", "DecColor"}, {"SetColor"}, {"InterpolateColors"},
        {"TextureBaseColor"}, {"InterpolateTextureBaseColors"}, {"@O", "Sphere"}, {"@o", "Circle"},
        {"@B", "Box"}, {"@b", "Quad"}, {"@L", "Label"}, {"@Gc", "StartGC"}, {"@Ge", "EndGC"},
        {"{", "BP"}, {".", "PP"}, {"}", "EP"}, {"SetContour"}, {"SectionResolution"},
        {"SetGuide"}, {"EndGuide"}, {"PositionOnGuide"}, {"Sweep"}, {"@g", "PglShape"},
        {"Frame"}, {"Arrow"}, {"@D", "SetScale"}, {"@Di", "MultScale"}, {"@Dd", "DivScale"},
        {"@Ts", "Elasticity"}, {"@Tp", "Tropism"}, {"LeftReflection"}, {"UpReflection"},
        {"HeadingReflection"}, {"@2D", "StartScreenProjection"}, {"@3D", "EndScreenProjection"},
        {"TextureScale"}, {"TextureUScale"}, {"TextureVScale", "TextureVCoeff"},
        {"TextureTranslation"}, {"TextureRotation"}, {"TextureTransformation"},
        {"?P", "GetPos"}, {"?H", "GetHead"}, {"?U", "GetUp"}, {"?L", "GetLeft"}, {"?R", "GetRight"},
        {"?F", "GetFrame"}, {"X", "MouseIns"}, {"x", "repexp", "all"}, {"or", "||"}, {"=]"},
        {"?I", "GetIterator"}, {"new", "newmodule"},
    };
    return table;
}

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool isIdentifier(std::string_view s) {
    if (s.empty() || !isIdentStart(s[0])) return false;
    return std::all_of(s.begin(), s.end(), isIdent);
}

// Skips a Python string literal starting at s[i] (a quote); returns the index after it.
size_t skipString(std::string_view s, size_t i) {
    const char q = s[i];
    const bool triple = i + 2 < s.size() && s[i + 1] == q && s[i + 2] == q;
    i += triple ? 3 : 1;
    while (i < s.size()) {
        if (s[i] == '\\') {
            i += 2;
            continue;
        }
        if (s[i] == q) {
            if (!triple) return i + 1;
            if (i + 2 < s.size() && s[i + 1] == q && s[i + 2] == q) return i + 3;
        }
        if (!triple && s[i] == '\n') return i;
        ++i;
    }
    return s.size();
}

// Splits the text inside a module's parentheses at top-level commas.
std::vector<std::string> splitArgs(std::string_view s) {
    std::vector<std::string> out;
    int depth = 0;
    size_t start = 0;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (c == '\'' || c == '"') {
            i = skipString(s, i);
            continue;
        }
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') --depth;
        else if (c == ',' && depth == 0) {
            out.emplace_back(trim(s.substr(start, i - start)));
            start = i + 1;
        }
        ++i;
    }
    std::string_view last = trim(s.substr(start));
    if (!last.empty() || !out.empty()) out.emplace_back(last);
    return out;
}

// The index of the ')' closing the '(' at s[open], or npos.
size_t closeParen(std::string_view s, size_t open) {
    int depth = 0;
    for (size_t i = open; i < s.size();) {
        const char c = s[i];
        if (c == '\'' || c == '"') {
            i = skipString(s, i);
            continue;
        }
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return c == ')' ? i : std::string_view::npos;
        }
        ++i;
    }
    return std::string_view::npos;
}

bool isNumberLiteral(std::string_view s) {
    if (s.empty()) return false;
    size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    bool digit = false;
    for (; i < s.size(); ++i) {
        const char c = s[i];
        if (std::isdigit(static_cast<unsigned char>(c))) digit = true;
        else if (c != '.' && c != 'e' && c != 'E' && c != '-' && c != '+' && c != '_') return false;
    }
    return digit;
}

bool isLiteral(std::string_view s) {
    return isNumberLiteral(s) || s == "None" || s == "True" || s == "False" ||
           (s.size() >= 2 && (s[0] == '\'' || s[0] == '"') && s.back() == s[0]);
}

// Finds `word` as a whole word in a line of Python, outside strings and comments.
size_t findKeyword(std::string_view line, std::string_view word, size_t from = 0) {
    for (size_t i = from; i < line.size();) {
        const char c = line[i];
        if (c == '#') return std::string_view::npos;
        if (c == '\'' || c == '"') {
            i = skipString(line, i);
            continue;
        }
        if (isIdentStart(c)) {
            size_t j = i;
            while (j < line.size() && isIdent(line[j])) ++j;
            if (line.substr(i, j - i) == word && (i == 0 || !isIdent(line[i - 1]))) return i;
            i = j;
            continue;
        }
        ++i;
    }
    return std::string_view::npos;
}

// Where a Python comment starts in a line (outside strings), or the line's end.
size_t commentStart(std::string_view line) {
    for (size_t i = 0; i < line.size();) {
        if (line[i] == '#') return i;
        if (line[i] == '\'' || line[i] == '"') {
            i = skipString(line, i);
            continue;
        }
        ++i;
    }
    return line.size();
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::string cur;
    for (char c : text) {
        if (c == '\r') continue;
        if (c == '\n') {
            lines.push_back(std::move(cur));
            cur.clear();
        } else {
            cur.push_back(c);
        }
    }
    lines.push_back(std::move(cur));
    return lines;
}

bool startsWithWord(std::string_view t, std::string_view w) {
    return t.substr(0, w.size()) == w && (t.size() == w.size() || !isIdent(t[w.size()]));
}

int indentOf(std::string_view line) {
    int n = 0;
    while (size_t(n) < line.size() && (line[size_t(n)] == ' ' || line[size_t(n)] == '\t')) ++n;
    return n;
}

// The Python expression for an lstring: a list of class ids, (id, (args,)) tuples, and
// Python objects for `$v`.
std::string pythonLstring(const std::vector<WrittenModule>& mods) {
    std::string out = "[";
    for (const auto& m : mods) {
        if (!m.variable.empty()) {
            out += m.variable;
        } else if (m.args.empty()) {
            out += std::to_string(m.cls);
        } else {
            out += "(" + std::to_string(m.cls) + ",(";
            for (const auto& a : m.args) out += a + ",";
            out += "))";
        }
        out += ",";
    }
    out += "]";
    return out;
}

class Translator {
public:
    explicit Translator(std::string_view text) : m_lines(splitLines(text)) {}

    Translation run() {
        // A UTF-8 byte order mark is not Python.
        if (!m_lines.empty() && m_lines[0].rfind("\xEF\xBB\xBF", 0) == 0) m_lines[0].erase(0, 3);
        size_t initAt = m_lines.size();
        for (size_t i = 0; i < m_lines.size(); ++i)
            if (m_lines[i].find("###### INITIALISATION ######") != std::string::npos) {
                initAt = i;
                break;
            }
        std::string& init = m_out.initCode;
        for (size_t i = 0; i < m_lines.size(); ++i) {
            if (i > initAt) init += m_lines[i];
            init += '\n';
        }
        std::vector<std::string> main(m_lines.begin(), m_lines.begin() + std::ptrdiff_t(initAt));
        translateMain(main);
        for (auto& l : m_outLines) m_out.mainCode += l + '\n';
        return std::move(m_out);
    }

private:
    enum class Mode { Python, Production, Decomposition, Interpretation };

    void error(int line, int col, std::string msg) { m_out.diagnostics.push_back({line, col, std::move(msg), Severity::Error}); }
    void warning(int line, int col, std::string msg) {
        m_out.diagnostics.push_back({line, col, std::move(msg), Severity::Warning});
    }

    // Replaces `produce S` / `nproduce S` (and `produce(S)`) in lines[i...] by calls building
    // the successor; a successor in parentheses may run over several lines (they are joined
    // and the lines it took are left blank, so the numbering holds).
    void translateProduces(std::vector<std::string>& lines, size_t i) {
        for (const char* word : {"nproduce", "produce"}) {
            size_t from = 0;
            for (;;) {
                std::string& line = lines[i];
                size_t at = findKeyword(line, word, from);
                if (at == std::string::npos) break;
                const bool n = word[0] == 'n';
                size_t p = at + std::string_view(word).size();
                while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
                std::string successor;
                size_t end;
                int successorCol = int(p) + 1;
                if (p < line.size() && line[p] == '(') {
                    // Join following lines until the parenthesis closes.
                    std::string joined = line.substr(p);
                    size_t extra = 0, close;
                    while ((close = closeParen(joined, 0)) == std::string::npos && i + extra + 1 < lines.size() && extra < 200) {
                        ++extra;
                        joined += ' ' + lines[i + extra];
                    }
                    if (close == std::string::npos) {
                        error(int(i) + 1, int(p) + 1, std::string("the '(' after ") + word + " is never closed");
                        break;
                    }
                    successor = joined.substr(1, close - 1);
                    successorCol += 1;
                    std::string rest = joined.substr(close + 1);
                    for (size_t k = 1; k <= extra; ++k) lines[i + k].clear();
                    line = line.substr(0, p) + joined.substr(0, close + 1) + rest;
                    end = p + close + 1;
                } else {
                    end = commentStart(line);
                    // `if c: produce A` ... `; x = 1` is not written in L-Py files; a ';' is a module.
                    successor = line.substr(p, end - p);
                }
                auto mods = readLstring(successor, m_out.classes, int(i) + 1, successorCol, m_out.diagnostics);
                const std::string call = (n ? "__lpy_nproduce(" : "return __lpy_produce(") + pythonLstring(mods) + ")";
                line = line.substr(0, at) + call + line.substr(end);
                from = at + call.size();
            }
        }
    }

    void declareModules(std::string_view rest, int line, size_t index) {
        // `module A, B(x,y), C=D : scale = 2`; keys after ':' are not used by Sprout.
        int depth = 0;
        size_t colon = std::string_view::npos;
        for (size_t i = 0; i < rest.size(); ++i) {
            if (rest[i] == '(') ++depth;
            else if (rest[i] == ')') --depth;
            else if (rest[i] == ':' && depth == 0) {
                colon = i;
                break;
            }
        }
        std::string out;
        for (const auto& decl : splitArgs(rest.substr(0, colon))) {
            std::string_view d = trim(decl);
            if (d.empty()) continue;
            std::string_view name = d;
            std::vector<std::string> params;
            if (size_t eq = d.find('='); eq != std::string_view::npos && d.find('(') > eq) {
                // `C=D`: C is another name of D's class.
                m_out.classes.alias(trim(d.substr(0, eq)), m_out.classes.intern(trim(d.substr(eq + 1))));
                continue;
            }
            if (size_t open = name.find('('); open != std::string_view::npos) {
                size_t close = closeParen(name, open);
                if (close == std::string_view::npos) {
                    error(line, 1, "the '(' of module " + std::string(name.substr(0, open)) + " is never closed");
                    continue;
                }
                params = splitArgs(name.substr(open + 1, close - open - 1));
                name = trim(name.substr(0, open));
            }
            const int cls = m_out.classes.intern(name);
            if (params.size()) m_out.classes.parameterNames[size_t(cls)] = params;
            if (isIdentifier(name)) out += std::string(name) + " = __lpy_module_class(" + std::to_string(cls) + "); ";
        }
        m_outLines[index] = out.empty() ? "pass" : out;
    }

    PatternModule pattern(const WrittenModule& w, int line) {
        PatternModule p;
        p.cls = w.cls;
        p.hasParens = w.hasParens;
        if (!w.variable.empty()) {
            error(line, w.col, "'$" + w.variable + "' binds a whole module: Sprout does not match it yet");
            return p;
        }
        size_t k = 0;
        if (w.cls == ModuleClasses::kStar && !w.args.empty() && isIdentifier(w.args[0])) {
            p.anyName = w.args[0];
            k = 1;
        }
        for (; k < w.args.size(); ++k) {
            std::string_view a = trim(w.args[k]);
            PatternArg arg;
            if (a == "-") {
                arg.kind = PatternArg::Kind::Skip;
            } else if (a.substr(0, 2) == "**" && isIdentifier(a.substr(2))) {
                arg.kind = PatternArg::Kind::Keywords;
                arg.name = a.substr(2);
            } else if (a.substr(0, 1) == "*" && isIdentifier(a.substr(1))) {
                arg.kind = PatternArg::Kind::Rest;
                arg.name = a.substr(1);
            } else if (isIdentifier(a) && a != "None" && a != "True" && a != "False") {
                arg.name = a;
            } else if (isLiteral(a)) {
                arg.kind = PatternArg::Kind::Equal;
                arg.expr = a;
            } else {
                size_t j = 0;
                while (j < a.size() && isIdent(a[j])) ++j;
                if (j > 0 && isIdentStart(a[0])) {
                    arg.kind = PatternArg::Kind::Predicate;
                    arg.name = a.substr(0, j);
                    arg.expr = a;
                } else {
                    arg.kind = PatternArg::Kind::Equal;
                    arg.expr = a;
                }
            }
            p.args.push_back(std::move(arg));
        }
        return p;
    }

    std::vector<PatternModule> patterns(std::string_view text, int line, int col) {
        std::vector<PatternModule> out;
        for (const auto& w : readLstring(text, m_out.classes, line, col, m_out.diagnostics)) {
            const std::string& n = m_out.classes.name(size_t(w.cls) < m_out.classes.size() && w.cls >= 0 ? w.cls : 0);
            if (w.cls >= 0 && n == "or") {
                error(line, w.col, "the pattern 'or(...)' (alternatives) is not read by Sprout yet");
                continue;
            }
            if (w.cls >= 0 && n == "x") {
                PatternModule p;
                p.cls = w.cls;
                if (w.args.empty()) {
                    error(line, w.col, "x(...) repeats a pattern: write the pattern inside, e.g. x([I(c)])");
                    continue;
                }
                p.repeat = patterns(w.args[0], line, w.col);
                auto count = [&](const std::string& a, int& v) {
                    if (!isNumberLiteral(a) || a.find('.') != std::string::npos || a.size() > 5) {
                        error(line, w.col, "the counts of x(...) are whole numbers");
                        return;
                    }
                    v = std::stoi(a);
                };
                if (w.args.size() >= 2) {
                    count(w.args[1], p.repeatMin);
                    p.repeatMax = p.repeatMin;
                }
                if (w.args.size() >= 3) count(w.args[2], p.repeatMax);
                if (p.repeat.empty()) continue;
                out.push_back(std::move(p));
                continue;
            }
            if (w.cls >= 0 && n == "=]") {
                PatternModule p;
                p.cls = ModuleClasses::kPop;
                p.exactPop = true;
                out.push_back(p);
                continue;
            }
            out.push_back(pattern(w, line));
        }
        return out;
    }

    // `lc < nlc << pred >> nrc > rc` at the top level of the header.
    void parseHeader(Rule& r, std::string_view h, int line) {
        struct Cut {
            size_t at, len;
            int kind;  // 0 '<', 1 '<<', 2 '>>', 3 '>'
        };
        std::vector<Cut> cuts;
        int depth = 0;
        for (size_t i = 0; i < h.size();) {
            const char c = h[i];
            if (c == '\'' || c == '"') {
                i = skipString(h, i);
                continue;
            }
            if (c == '(') ++depth;
            else if (c == ')') --depth;
            else if (depth == 0 && (c == '<' || c == '>')) {
                const bool twice = i + 1 < h.size() && h[i + 1] == c;
                cuts.push_back({i, twice ? 2u : 1u, c == '<' ? (twice ? 1 : 0) : (twice ? 2 : 3)});
                i += twice ? 2 : 1;
                continue;
            }
            ++i;
        }
        size_t start = 0;
        std::vector<std::pair<std::string_view, size_t>> pieces;
        std::vector<int> kinds;
        for (const auto& c : cuts) {
            pieces.push_back({h.substr(start, c.at - start), start});
            kinds.push_back(c.kind);
            start = c.at + c.len;
        }
        pieces.push_back({h.substr(start), start});
        // Assign pieces: everything before the last '<'/'<<' is left context(s); after the
        // first '>'/'>>' is right context(s).
        size_t predIndex = 0;
        for (size_t k = 0; k < kinds.size(); ++k)
            if (kinds[k] <= 1) predIndex = k + 1;
        for (size_t k = 0; k < pieces.size(); ++k) {
            auto mods = patterns(pieces[k].first, line, int(pieces[k].second) + 1);
            if (k == predIndex) {
                r.pred = std::move(mods);
            } else if (k < predIndex) {
                (kinds[k] == 1 ? r.newLeft : r.left) = std::move(mods);
                if (k + 1 < predIndex && kinds[k] == 1) error(line, 1, "'<<' must come just before the predecessor");
            } else {
                (kinds[k - 1] == 2 ? r.newRight : r.right) = std::move(mods);
            }
        }
        if (r.pred.empty()) error(line, 1, "this rule has no predecessor before its ':' or '-->'");
        if (!r.newLeft.empty() && !r.newRight.empty()) error(line, 1, "a rule may not have both '<<' and '>>' (L-Py)");
        // Parameters in binding order; a name used twice is an error, as in L-Py.
        auto add = [&](const std::string& n) {
            if (std::find(r.params.begin(), r.params.end(), n) != r.params.end()) {
                error(line, 1, "'" + n + "' is bound twice in this rule's header");
                return;
            }
            r.params.push_back(n);
        };
        std::function<void(PatternModule&)> bind = [&](PatternModule& pm) {
            const size_t before = r.params.size();
            for (auto& inner : pm.repeat) bind(inner);
            if (pm.isRepeat()) pm.repeatVariables = int(r.params.size() - before);
            if (!pm.anyName.empty()) add(pm.anyName);
            for (auto& a : pm.args)
                if (a.kind != PatternArg::Kind::Equal && a.kind != PatternArg::Kind::Skip) add(a.name);
        };
        for (auto* part2 : {&r.left, &r.newLeft, &r.pred, &r.newRight, &r.right})
            for (auto& pm : *part2) bind(pm);
    }

    // A rule starts at lines[i] (column 0). Returns the index of its last line.
    size_t rule(std::vector<std::string>& lines, size_t i, Mode mode) {
        const std::string& line = lines[i];
        const int lineNo = int(i) + 1;
        // The header ends at the first ':' or '-->' outside parentheses and strings.
        size_t end = std::string::npos;
        bool arrow = false;
        int depth = 0;
        for (size_t k = 0; k < line.size();) {
            const char c = line[k];
            if (c == '\'' || c == '"') {
                k = skipString(line, k);
                continue;
            }
            if (c == '(') ++depth;
            else if (c == ')') --depth;
            else if (depth == 0 && c == '-' && line.compare(k, 3, "-->") == 0) {
                end = k;
                arrow = true;
                break;
            } else if (depth == 0 && c == ':') {
                end = k;
                break;
            }
            ++k;
        }
        if (end == std::string::npos) {
            error(lineNo, 1, "a rule's header ends with ':' (then a Python body) or '-->' (then a successor); neither is on this line");
            m_outLines[i] = "";
            return i;
        }
        Rule r;
        r.kind = mode == Mode::Production ? RuleKind::Production : mode == Mode::Decomposition ? RuleKind::Decomposition : RuleKind::Interpretation;
        r.group = m_group;
        r.line = lineNo;
        r.header = std::string(trim(std::string_view(line).substr(0, end)));
        r.filter = m_filter;
        parseHeader(r, std::string_view(line).substr(0, end), lineNo);
        r.function = "__lpy_rule_" + std::to_string(m_out.rules.size());
        std::string def = "def " + r.function + "(";
        for (size_t k = 0; k < r.params.size(); ++k) def += (k ? "," : "") + r.params[k];
        def += "):";
        // The body: following lines that are indented or blank (up to the next column-0 line).
        size_t last = i;
        for (size_t k = i + 1; k < lines.size(); ++k) {
            std::string_view t = trim(lines[k]);
            if (t.empty()) continue;
            if (indentOf(lines[k]) == 0) break;
            last = k;
        }
        if (arrow) {
            std::string successor = line.substr(end + 3);
            successor = successor.substr(0, commentStart(successor));
            auto mods = readLstring(successor, m_out.classes, lineNo, int(end) + 4, m_out.diagnostics);
            m_outLines[i] = def + " return __lpy_produce(" + pythonLstring(mods) + ")";
            r.arrow = true;
            r.successor = mods;
            if (last > i) warning(lineNo, int(end) + 1, "indented lines after a '-->' rule are ignored");
            for (size_t k = i + 1; k <= last; ++k) m_outLines[k] = "";
        } else {
            std::string inlineBody = std::string(trim(std::string_view(line).substr(end + 1)));
            // `A : @static` (a body evaluated once in L-Py): run as an ordinary body here.
            if (inlineBody.rfind("@static", 0) == 0) inlineBody = std::string(trim(std::string_view(inlineBody).substr(7)));
            const std::string headerLine = lines[i];
            lines[i] = inlineBody;  // the body's first line is what follows ':' (columns from there)
            for (size_t k = i; k <= last; ++k)
                if (!lines[k].empty()) translateProduces(lines, k);
            std::vector<std::string> body(lines.begin() + std::ptrdiff_t(i), lines.begin() + std::ptrdiff_t(last) + 1);
            lines[i] = headerLine;
            bool anyStatement = !trim(body[0]).empty() && trim(body[0])[0] != '#';
            for (size_t k = 1; k < body.size(); ++k)
                if (!trim(body[k]).empty() && trim(body[k])[0] != '#') anyStatement = true;
            if (!trim(body[0]).empty() && body[0][0] != '#') {
                m_outLines[i] = def + " " + body[0];
                if (last > i) {
                    // `A : x = 1` followed by an indented block: Python cannot have both on
                    // one def; the inline part goes first on its own line of the block.
                    m_outLines[i] = def + " pass";
                    warning(lineNo, int(end) + 2, "code after ':' on the rule's line and an indented block under it: the code on the line is not run");
                }
            } else {
                m_outLines[i] = def + (anyStatement ? "" : " pass");
            }
            for (size_t k = 1; k < body.size(); ++k) m_outLines[i + k] = body[k];
        }
        m_out.rules.push_back(std::move(r));
        return last;
    }

    void filterLine(std::string_view rest, bool consider, int line, int col) {
        ContextFilter f;
        f.consider = consider;
        for (const auto& w : readLstring(rest, m_out.classes, line, col, m_out.diagnostics))
            if (w.cls >= 0) f.classes.push_back(w.cls);
        if (f.classes.empty()) {
            m_filter = -1;
            return;
        }
        m_filter = int(m_out.filters.size());
        m_out.filters.push_back(std::move(f));
    }

    // Keywords that end with ':' and a value: `derivation length: e`.
    static bool keyword(std::string_view t, std::string_view word, std::string_view& rest) {
        if (t.substr(0, word.size()) != word) return false;
        std::string_view r = trim(t.substr(word.size()));
        if (r.empty() || r[0] != ':') return false;
        rest = trim(r.substr(1));
        return true;
    }

    void translateMain(std::vector<std::string>& lines) {
        m_outLines.assign(lines.size(), std::string());
        Mode mode = Mode::Python;
        bool sawProduction = false;
        for (size_t i = 0; i < lines.size(); ++i) {
            const int lineNo = int(i) + 1;
            std::string& line = lines[i];
            std::string_view t = trim(line);
            const int ind = indentOf(line);
            std::string_view rest;
            m_outLines[i] = line;
            if (t.empty() || t[0] == '#') continue;
            if (keyword(t, "derivation length", rest)) {
                m_outLines[i] = std::string(size_t(mode == Mode::Python ? ind : 0), ' ') + "__derivation_length__ = " + std::string(rest);
                continue;
            }
            if (ind == 0 && (startsWithWord(t, "production") && keyword(t, "production", rest))) {
                mode = Mode::Production;
                sawProduction = true;
                m_group = 0;
                m_outLines[i] = "# " + line;
                if (!rest.empty()) error(lineNo, 13, "nothing may follow 'production:' on its line");
                continue;
            }
            if (mode != Mode::Python) {
                if (keyword(t, "interpretation", rest) || keyword(t, "homomorphism", rest)) {
                    mode = Mode::Interpretation;
                    m_outLines[i] = "# " + line;
                    continue;
                }
                if (keyword(t, "decomposition", rest)) {
                    mode = Mode::Decomposition;
                    m_outLines[i] = "# " + line;
                    continue;
                }
                if (keyword(t, "maximum depth", rest)) {
                    if (mode == Mode::Production) error(lineNo, 1, "'maximum depth:' belongs to a decomposition or interpretation section");
                    m_outLines[i] = std::string(mode == Mode::Decomposition ? "__decomposition_max_depth__ = " : "__homomorphism_max_depth__ = ") + std::string(rest);
                    continue;
                }
                if (startsWithWord(t, "group")) {
                    std::string_view g = trim(t.substr(5, commentStart(t) - 5));
                    if (!g.empty() && g.back() == ':') g = trim(g.substr(0, g.size() - 1));
                    int n = 0;
                    bool okNumber = !g.empty() && std::all_of(g.begin(), g.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
                    if (okNumber && g.size() < 6) n = std::stoi(std::string(g));
                    else error(lineNo, 7, "a group is a whole number from 0 (`group 1:`)");
                    m_group = n;
                    m_outLines[i] = "# " + line;
                    continue;
                }
                if (t == "endgroup") {
                    m_group = 0;
                    m_outLines[i] = "# " + line;
                    continue;
                }
                if (t == "endlsystem") {
                    mode = Mode::Python;
                    m_outLines[i] = "# " + line;
                    continue;
                }
            } else if (t == "endlsystem" || startsWithWord(t, "interpretation") || startsWithWord(t, "homomorphism") || startsWithWord(t, "decomposition")) {
                std::string_view r2;
                if (t == "endlsystem" || keyword(t, "interpretation", r2) || keyword(t, "homomorphism", r2) || keyword(t, "decomposition", r2)) {
                    error(lineNo, ind + 1, "'" + std::string(t) + "' comes after 'production:' (L-Py)");
                    m_outLines[i] = "# " + line;
                    continue;
                }
            }
            if (keyword(t, "consider", rest) || keyword(t, "ignore", rest)) {
                filterLine(rest, t[0] == 'c', lineNo, int(line.find(rest.empty() ? ":" : std::string(rest))) + 1);
                m_outLines[i] = "# " + line;
                continue;
            }
            if (mode == Mode::Python) {
                if (ind == 0 && (keyword(t, "Axiom", rest) || keyword(t, "axiom", rest))) {
                    m_out.hasAxiom = true;
                    if (rest.empty() && i + 1 < lines.size() && indentOf(lines[i + 1]) > 0) {
                        m_out.axiomIsBlock = true;
                        m_outLines[i] = "def __axiom_block__():";
                        continue;
                    }
                    const size_t col = line.find(':') + 2;
                    std::string text(rest.substr(0, commentStart(rest)));
                    auto mods = readLstring(text, m_out.classes, lineNo, int(col), m_out.diagnostics);
                    m_outLines[i] = "__axiom__ = " + pythonLstring(mods);
                    continue;
                }
                if (startsWithWord(t, "module") && t.size() > 7 && std::isspace(static_cast<unsigned char>(t[6]))) {
                    declareModules(t.substr(7), lineNo, i);
                    m_outLines[i] = std::string(size_t(ind), ' ') + m_outLines[i];
                    continue;
                }
                if (startsWithWord(t, "undeclare")) {
                    m_outLines[i] = std::string(size_t(ind), ' ') + "pass";
                    continue;
                }
                if (findKeyword(line, "produce") != std::string::npos || findKeyword(line, "nproduce") != std::string::npos) {
                    translateProduces(lines, i);
                    m_outLines[i] = lines[i];
                }
                continue;
            }
            // Rule mode.
            if (ind > 0) {
                error(lineNo, 1, "unexpected indent: an indented line belongs under a rule's header");
                m_outLines[i] = "";
                continue;
            }
            if (startsWithWord(t, "def") || startsWithWord(t, "class") || startsWithWord(t, "import") || startsWithWord(t, "from")) {
                warning(lineNo, 1, "Python at the start of a line in a rule section: read as Python, after it the rules end (write 'endlsystem' first)");
                mode = Mode::Python;
                --i;
                continue;
            }
            i = rule(lines, i, mode);
        }
        if (!sawProduction && !m_out.hasAxiom) warning(0, 0, "no 'Axiom:' and no 'production:': nothing to derive");
    }

    std::vector<std::string> m_lines, m_outLines;
    Translation m_out;
    int m_group = 0;
    int m_filter = -1;
};

}  // namespace

ModuleClasses::ModuleClasses() {
    for (const auto& names : predefined()) {
        const int id = int(m_names.size());
        m_names.emplace_back(names[0]);
        for (const char* n : names) {
            m_ids.emplace(n, id);
            m_longest = std::max(m_longest, std::string_view(n).size());
        }
    }
    parameterNames.resize(m_names.size());
    m_predefined = m_names.size();
}

int ModuleClasses::find(std::string_view name) const {
    auto it = m_ids.find(std::string(name));
    return it == m_ids.end() ? -1 : it->second;
}

void ModuleClasses::alias(std::string_view name, int cls) {
    if (name.empty() || find(name) >= 0) return;
    m_ids.emplace(std::string(name), cls);
    m_longest = std::max(m_longest, name.size());
}

int ModuleClasses::intern(std::string_view name) {
    if (int id = find(name); id >= 0) return id;
    const int id = int(m_names.size());
    m_names.emplace_back(name);
    m_ids.emplace(std::string(name), id);
    m_longest = std::max(m_longest, name.size());
    parameterNames.emplace_back();
    return id;
}

std::vector<WrittenModule> readLstring(std::string_view s, ModuleClasses& classes, int line, int col0, std::vector<Diagnostic>& diags) {
    std::vector<WrittenModule> out;
    for (size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        WrittenModule m;
        m.col = col0 + int(i);
        if (c == ')') {
            diags.push_back({line, m.col, "a ')' with no module before it", Severity::Error});
            ++i;
            continue;
        }
        if (c == '$' && i + 1 < s.size() && isIdentStart(s[i + 1])) {
            size_t j = i + 1;
            while (j < s.size() && isIdent(s[j])) ++j;
            m.cls = -1;
            m.variable = std::string(s.substr(i + 1, j - i - 1));
            out.push_back(std::move(m));
            i = j;
            continue;
        }
        if (c == '~' && i + 1 < s.size() && !std::isspace(static_cast<unsigned char>(s[i + 1])) && s[i + 1] != '(') {
            // `~l(2)`: the surface named l.
            m.cls = ModuleClasses::kSurface;
            m.args.push_back(std::string("'") + s[i + 1] + "'");
            i += 2;
        } else {
            size_t len = std::min(classes.longest() + 1, s.size() - i);
            int cls = -1;
            for (; len > 0; --len)
                if ((cls = classes.find(s.substr(i, len))) >= 0) break;
            if (cls < 0) {
                // An unknown character is a class of its own; a UTF-8 sequence stays whole.
                len = 1;
                while (i + len < s.size() && (static_cast<unsigned char>(s[i + len]) & 0xC0) == 0x80) ++len;
                cls = classes.intern(s.substr(i, len));
            }
            m.cls = cls;
            i += len;
        }
        size_t j = i;
        while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
        if (j < s.size() && s[j] == '(') {
            size_t close = closeParen(s, j);
            if (close == std::string_view::npos) {
                diags.push_back({line, col0 + int(j), "this '(' is never closed", Severity::Error});
                break;
            }
            m.hasParens = true;
            for (auto& a : splitArgs(s.substr(j + 1, close - j - 1))) m.args.push_back(std::move(a));
            if (m.args.size() == 1 && m.args[0].empty()) m.args.clear();
            i = close + 1;
        }
        out.push_back(std::move(m));
    }
    return out;
}

Translation translate(std::string_view text) { return Translator(text).run(); }

}  // namespace sprout::lpy
