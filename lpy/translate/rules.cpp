// The rules of an .lpy file: a rule's header (contexts and the predecessor, read into
// patterns, with their parameters), its body (a Python function) or its `-->` successor, and
// the `produce` statements that build a successor from Python. Its own file: what L-Py adds
// to Python inside `production:` and its sibling sections.
#include <algorithm>
#include <functional>
#include <initializer_list>

#include "lpy/translate/translate_impl.hpp"

namespace sprout::lpy::translate_detail {

// Replaces `produce S` / `nproduce S` (and `produce(S)`) in lines[i...] by calls building
// the successor; a successor in parentheses may run over several lines (they are joined
// and the lines it took are left blank, so the numbering holds).
void Translator::translateProduces(std::vector<std::string>& lines, size_t i) {
    for (const char* word : {"nproduce", "produce", "makestring"}) {
        size_t from = 0;
        for (;;) {
            std::string& line = lines[i];
            size_t at = findKeyword(line, word, from);
            if (at == std::string::npos) break;
            const bool n = word[0] == 'n', make = word[0] == 'm';
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
                    // Each line's comment ends at its line (`CA  # a comment` inside the parentheses).
                    if (extra == 0) joined.resize(commentStart(joined));
                    ++extra;
                    const std::string& next = lines[i + extra];
                    joined += ' ' + next.substr(0, commentStart(next));
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
            for (const WrittenModule& w : mods) m_out.writesCut |= w.cls == ModuleClasses::kCut;
            if (!n && !make) m_produced = mods, ++m_produces;
            // makestring(S): the Lstring S, a value (L-Py's AxialTree(...)).
            const std::string call = (make ? "Lstring(" : n ? "__lpy_nproduce(" : "return __lpy_produce(") + pythonLstring(mods) + ")";
            line = line.substr(0, at) + call + line.substr(end);
            from = at + call.size();
        }
    }
}

PatternModule Translator::pattern(const WrittenModule& w, int line) {
    PatternModule p;
    p.cls = w.cls;
    p.hasParens = w.hasParens;
    if (w.getModule) {
        p.moduleVariable = w.variable;
        return p;
    }
    if (!w.variable.empty()) {
        error(line, w.col, "'$" + w.variable + "' in a rule's header: write $A(m) to bind a module of class A to m");
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

std::vector<PatternModule> Translator::patterns(std::string_view text, int line, int col) {
    std::vector<PatternModule> out;
    for (const auto& w : readLstring(text, m_out.classes, line, col, m_out.diagnostics)) {
        const std::string& n = m_out.classes.name(size_t(w.cls) < m_out.classes.size() && w.cls >= 0 ? w.cls : 0);
        if (w.cls >= 0 && n == "or") {
            PatternModule p;
            p.cls = w.cls;
            for (const std::string& a : w.args) {
                const std::string_view alt = trim(a);
                // `None` as an alternative: nothing (L-Py's None module matches the empty string).
                p.alternatives.push_back(alt == "None" ? std::vector<PatternModule>() : patterns(alt, line, w.col));
            }
            if (p.alternatives.size() < 2) {
                error(line, w.col, "or(...) takes two alternatives or more, e.g. or(B(x), C)");
                continue;
            }
            out.push_back(std::move(p));
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
void Translator::parseHeader(Rule& r, std::string_view h, int line) {
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
    for (const auto& p : r.pred)
        if (p.isOr()) error(line, 1, "or(...) alternatives are read in a rule's contexts, not in its predecessor (yet)");
    if (!r.newLeft.empty() && !r.newRight.empty()) error(line, 1, "a rule may not have both '<<' and '>>' (L-Py)");
    // Parameters in binding order; a name used twice is an error, as in L-Py.
    for (auto* part : {&r.left, &r.newLeft, &r.pred, &r.newRight, &r.right}) bindNames(*part, r.params, line);
}

void Translator::bindNames(std::vector<PatternModule>& ps, std::vector<std::string>& names, int line) {
    auto add = [&](const std::string& n) {
        if (std::find(names.begin(), names.end(), n) != names.end()) {
            error(line, 1, "'" + n + "' is bound twice in this rule's header");
            return;
        }
        names.push_back(n);
    };
    std::function<void(PatternModule&)> bind = [&](PatternModule& pm) {
        const size_t before = names.size();
        for (auto& inner : pm.repeat) bind(inner);
        if (pm.isRepeat()) pm.repeatVariables = int(names.size() - before);
        for (auto& alt : pm.alternatives) {
            const size_t at = names.size();
            for (auto& inner : alt) bind(inner);
            pm.alternativeVariables.push_back(int(names.size() - at));
        }
        if (!pm.anyName.empty()) add(pm.anyName);
        if (!pm.moduleVariable.empty()) add(pm.moduleVariable);
        for (auto& a : pm.args)
            if (a.kind != PatternArg::Kind::Equal && a.kind != PatternArg::Kind::Skip) add(a.name);
    };
    for (auto& pm : ps) bind(pm);
}

// Whether the body in lines[i..last] (lines[i]: what follows the header's ':') is statements
// run one after the other, the last of them a `produce`: no compound statement, return,
// raise, yield, nproduce or second produce, no line continued on the next. Then the rule
// makes its produce's successor whenever its header matches (an exception ends the derivation).
bool Translator::plainBody(const std::vector<std::string>& lines, size_t i, size_t last) {
    // Statements that steer (at a statement's start), and words that leave a body anywhere.
    static const char* const kSteer[] = {"if", "elif", "else", "for", "while", "try", "except", "finally", "with", "def", "class",
                                         "break", "continue", "assert", "match", "async", "global", "nonlocal", "del"};
    static const char* const kLeave[] = {"return", "raise", "yield", "await", "nproduce"};
    std::vector<std::string_view> statements;
    int indent = -1;
    for (size_t k = i; k <= last; ++k) {
        std::string_view t = lines[k];
        t = t.substr(0, commentStart(t));
        if (trim(t).empty()) continue;
        if (k > i) {  // the lines under the header share one indentation
            if (indent < 0) indent = indentOf(t);
            if (indentOf(t) != indent) return false;
        }
        t = trim(t);
        const char end = t.back();
        if (end == ':' || end == '\\') return false;
        for (const char* w : kSteer)
            if (startsWithWord(t, w)) return false;
        for (const char* w : kLeave)
            if (findKeyword(t, w) != std::string_view::npos) return false;
        statements.push_back(t);
    }
    if (statements.empty() || !startsWithWord(statements.back(), "produce")) return false;
    for (size_t k = 0; k + 1 < statements.size(); ++k)  // (in a successor, ';' is a module)
        if (findKeyword(statements[k], "produce") != std::string_view::npos || statements[k].find(';') != std::string_view::npos)
            return false;
    // Parentheses closed on each line (a successor in parentheses over several lines is not plain).
    for (std::string_view t : statements) {
        int depth = 0;
        for (size_t c = 0; c < t.size(); ++c) {
            if (t[c] == '\'' || t[c] == '"') {
                c = skipString(t, c) - 1;
                continue;
            }
            depth += t[c] == '(' || t[c] == '[' || t[c] == '{';
            depth -= t[c] == ')' || t[c] == ']' || t[c] == '}';
        }
        if (depth != 0) return false;
    }
    return true;
}

// A rule starts at lines[i] (column 0). Returns the index of its last line.
size_t Translator::rule(std::vector<std::string>& lines, size_t i, Mode mode) {
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
        r.alwaysProduces = true;
        for (const WrittenModule& w : mods) m_out.writesCut |= w.cls == ModuleClasses::kCut;
        r.successor = mods;
        if (last > i) warning(lineNo, int(end) + 1, "indented lines after a '-->' rule are ignored");
        for (size_t k = i + 1; k <= last; ++k) m_outLines[k] = "";
    } else {
        std::string inlineBody = std::string(trim(std::string_view(line).substr(end + 1)));
        // `A : @static` (a body evaluated once in L-Py): run as an ordinary body here.
        if (inlineBody.rfind("@static", 0) == 0) inlineBody = std::string(trim(std::string_view(inlineBody).substr(7)));
        const std::string headerLine = lines[i];
        lines[i] = inlineBody;  // the body's first line is what follows ':' (columns from there)
        const bool plain = plainBody(lines, i, last);
        m_produces = 0;
        for (size_t k = i; k <= last; ++k) {
            if (lines[k].empty()) continue;
            translateProduces(lines, k);
            translateInContexts(lines[k], int(k) + 1);
        }
        if (plain && m_produces == 1) r.alwaysProduces = true, r.successor = std::move(m_produced);
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

}  // namespace sprout::lpy::translate_detail
