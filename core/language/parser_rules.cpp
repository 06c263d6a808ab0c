// The .lsys parser's rules: predecessor patterns with their contexts and parameters,
// successors, and one rule line whole (condition, probability, its checks).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/base/bounded.hpp"
#include "core/language/cpfg/user_files.hpp"
#include "core/language/parser_impl.hpp"

namespace sprout {
namespace detail {

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
    ExprScope scope{&params, &m_g.defines, &m_macros, &m_g.globals, &m_g.arrays, m_options.curves.get()};
    scope.cpfg = m_options.tabContinues;
    bool ok = true;
    for (const auto& m : mods) {
        auto id = symbolFor(line, m.name, int(m.args.size()));
        if (!id) return false;
        out.symbols.push_back(*id);
        for (size_t k = 0; k < m.args.size(); ++k) {
            std::string_view arg = m.args[k];
            std::string number;
            if (auto name = quotedName(arg)) {  // `SetContour("leaf")`: the name's number, printed back as the name
                appendNumber(number, m_g.alphabet.internString(*name));
                m_g.alphabet.markNameArg(*id, int(k));
                arg = number;
            }
            auto e = compileExpr(arg, line, scope, m_sink);
            if (e) out.args.push_back(std::move(*e));
            else ok = false;
        }
    }
    return ok;
}

// Tutorials' "Production: 'F' -> 'F-F++F-F'": the word before the rule, and quotes around
// both sides (a quote alone is ABOP's colour step, so both sides must have them).
void Parser::unwrapTutorialRule(std::string_view& head, std::string_view& tail) {
    const size_t c = findTopLevel(head, ":");
    if (c != std::string_view::npos) {
        std::string word(trim(head.substr(0, c)));
        std::transform(word.begin(), word.end(), word.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        if (word == "production" || word == "productions" || word == "rule" || word == "rules") {
            head = head.substr(c + 1);
            m_notation = true;
        }
    }
    auto quoted = [](std::string_view s) {
        s = trim(s);
        return s.size() >= 3 && (s.front() == '\'' || s.front() == '"') && s.back() == s.front() &&
               s.find(s.front(), 1) == s.size() - 1;
    };
    const size_t lc = findTopLevel(head, ":");
    std::string_view headRule = lc == std::string_view::npos ? head : head.substr(lc + 1);
    if (quoted(headRule) && quoted(tail) && lc == std::string_view::npos) {
        head = trim(head);
        head = head.substr(1, head.size() - 2);
        tail = trim(tail);
        tail = tail.substr(1, tail.size() - 2);
        m_notation = true;
    }
}

// ABOP labels its productions p1, p2, ...: accept "p1: F -> FF", "P2 :", "p₃:". The label as
// typed, taken off `head` (`colon` then the condition's, in what is left), or "".
std::string Parser::ruleLabel(const SourceLine& line, std::string_view& head, size_t& colon) {
    std::string label;
    if (colon != std::string_view::npos) {
        std::string_view written = trim(head.substr(0, colon));
        // A lone `P :` is a module P with a condition when what follows is one, as in cpfg's
        // `P : * {z = z+1} -> ...` (`*` no condition, `{` a statement block).
        std::string_view after = trim(head.substr(colon + 1));
        const bool condition = written.size() == 1 && !after.empty() &&
                               (after[0] == '{' || (after[0] == '*' && !trim(after.substr(1)).starts_with("<")));
        if (isRuleLabel(written) && !condition) {
            // The label as typed (p₃ with its subscript), up to the colon.
            const size_t from = size_t(written.data() - line.text.data());
            const size_t to = size_t(head.data() - line.text.data()) + colon;
            const std::string_view typed = line.original.size() == line.text.size() ? line.original : line.text;
            label = std::string(trim(typed.substr(from, to - from)));
            label.erase(std::remove(label.begin(), label.end(), '$'), label.end());  // LaTeX's $p1$
            head = head.substr(colon + 1);
            colon = findTopLevel(head, ":", 0, m_cpfg);
            m_notation = true;
        }
    }
    return label;
}

// The predecessor with its contexts, `left < pred > right`, into `prod`, their parameters
// named in `params`; false when an error was given.
bool Parser::parseRulePatterns(const SourceLine& line, std::string_view patterns, std::vector<std::string>& params,
                               Production& prod) {
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
        return false;
    }
    if (findTopLevel(predText, "<") != std::string_view::npos) {
        m_sink.error(line, predText.substr(findTopLevel(predText, "<")),
                     "a second '<': write contexts as 'left < module > right'");
        return false;
    }
    std::vector<PatternModule> pred;
    if (lt != std::string_view::npos && trim(leftText).empty()) {
        m_sink.error(line, patterns.substr(lt), "'<' needs a left context before it (or '*' for any)");
        return false;
    }
    if (!parsePattern(line, leftText, false, true, params, prod.left)) return false;
    if (!parsePattern(line, predText, true, false, params, pred)) return false;
    if (gt != std::string_view::npos && trim(rightText).empty()) {
        m_sink.error(line, predText.substr(gt), "'>' needs a right context after it (or '*' for any)");
        return false;
    }
    if (!parsePattern(line, rightText, true, true, params, prod.right)) return false;
    if (pred.size() > 1 && m_options.tabContinues) {  // cpfg: a strict predecessor of several modules
        prod.predRest.assign(pred.begin() + 1, pred.end());
        for (PatternModule& m : prod.predRest) m.arity = std::max(m.arity, 0);
        pred.resize(1);
    }
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
        return false;
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
    return true;
}

// The names a production's statement blocks assign become its locals, after its parameters in
// `params`; L-system Explorer's variables among them go in `globalsAssigned` with their values.
// False when an error was given.
bool Parser::collectBlockLocals(const SourceLine& line, std::string_view preBlock, std::string_view postBlock,
                                std::vector<std::string>& params,
                                std::vector<std::pair<std::string, double>>& globalsAssigned) {
    std::vector<std::string> assigned;
    collectAssigned(preBlock, assigned);
    collectAssigned(postBlock, assigned);
    const std::string_view block = preBlock.empty() ? postBlock : preBlock;
    for (const auto& name : assigned) {
        if (std::find(m_g.globals.begin(), m_g.globals.end(), name) != m_g.globals.end() &&
            std::find(params.begin(), params.end(), name) == params.end())
            continue;  // cpfg: a global variable (assigned in a Start: block before), not a local
        if (auto global = m_g.defines.find(name); global != m_g.defines.end()) {
            if (!m_options.explorer || std::find(params.begin(), params.end(), name) != params.end()) {
                m_sink.error(line, block, "'" + name + "' is a constant (#define) and cannot be assigned in a block: use another name");
                return false;
            }
            // L-system Explorer's `zpos = 0` is a variable its blocks change for the rest
            // of the derivation; here the change stays in the production, from that value.
            m_sink.warning(line, block, "the block changes the variable '" + name + "': in Sprout the change is seen by this "
                                        "production only (each time from " + formatNumber(global->second) + "), not by the next ones");
            globalsAssigned.emplace_back(name, global->second);
        }
        if (std::find(params.begin(), params.end(), name) == params.end()) params.push_back(name);
    }
    if (params.size() > 255) {
        m_sink.error(line, preBlock, "too many parameters and local variables in one production (the limit is 255)");
        return false;
    }
    return true;
}

// After the arrow: the successor's text in `succText`, and a probability (`: 0.33`, or
// "{0.33}" at the end outside cpfg) into `prod`. False when an error was given.
bool Parser::splitRuleProbability(const SourceLine& line, std::string_view tail, std::string_view& succText,
                                  Production& prod, const ExprScope* scope) {
    if (size_t second = findTopLevel(tail, "->"); second != std::string_view::npos) {
        m_sink.error(line, tail.substr(second), "a second '->': a rule has one arrow, one rule per line");
        return false;
    }
    size_t probColon = findLastTopLevel(tail, ':');
    succText = tail;
    std::string_view probText;
    if (probColon != std::string_view::npos) {
        succText = tail.substr(0, probColon);
        probText = trim(tail.substr(probColon + 1));
    } else if (!m_cpfg) {
        // "F -> F+F {0.33}": a probability in braces at the end (a polygon holds turtle moves).
        std::string_view t = trim(tail);
        const size_t open = t.rfind('{');
        if (!t.empty() && t.back() == '}' && open != std::string_view::npos) {
            std::string_view inside = trim(t.substr(open + 1, t.size() - open - 2));
            if (!inside.empty() && inside.find_first_not_of("0123456789.eE+-") == std::string_view::npos) {
                probText = inside;
                succText = t.substr(0, open);
                m_notation = true;
            }
        }
    }
    if (m_options.tabContinues && !probText.empty() && scope) {
        // cpfg: `--> succ : x` is evaluated as the production applies, with its parameters.
        auto e = compileExpr(probText, line, *scope, m_sink);
        if (!e) return false;
        prod.probability = e->isConstant() ? e->constantValue() : 1;
        if (!e->isConstant()) prod.probabilityExpr = std::move(*e);
        probText = {};
        probColon = std::string_view::npos;
    }
    if (!probText.empty() || probColon != std::string_view::npos) {
        auto p = constant(line, probText);
        if (!p) return false;
        if (!(*p >= 0)) {
            m_sink.error(line, probText, "a probability cannot be negative");
            return false;
        }
        prod.probability = *p;
    }
    if (size_t extra = findTopLevel(succText, ":"); extra != std::string_view::npos) {
        m_sink.error(line, succText.substr(extra), "a second ':' after '->': a rule has at most one probability");
        return false;
    }
    return true;
}

void Parser::parseRule(const SourceLine& line, Section section, size_t equalsArrow) {
    std::string_view text = line.text;
    size_t arrow = equalsArrow != std::string_view::npos ? equalsArrow : findTopLevel(text, "->", 0, m_cpfg);
    if (arrow == std::string_view::npos) {  // its '->' inside a bracket or block never closed
        m_sink.error(line, text, "this rule's '->' is inside a '(' or '{' that is not closed before it");
        return;
    }
    size_t arrowEnd = arrow + (equalsArrow != std::string_view::npos ? 1 : 2);
    if (equalsArrow == std::string_view::npos && arrow > 0 && text[arrow - 1] == '-') --arrow;  // L-Py's and ABOP's -->
    std::string_view head = text.substr(0, arrow);
    std::string_view tail = text.substr(arrowEnd);
    if (!m_cpfg) unwrapTutorialRule(head, tail);

    size_t colon = findTopLevel(head, ":", 0, m_cpfg);
    std::string label = ruleLabel(line, head, colon);
    std::string_view patterns = colon == std::string_view::npos ? head : head.substr(0, colon);
    std::string_view condition = colon == std::string_view::npos ? std::string_view() : head.substr(colon + 1);

    Production prod;
    prod.line = line.number;
    prod.lsystem = m_ruleLsystem;
    prod.label = std::move(label);
    std::vector<std::string> params;
    if (!parseRulePatterns(line, patterns, params, prod)) return;
    // cpfg: `pred : {pre} condition {post} --> succ`, `*` for no condition. Names assigned
    // in the blocks are the production's locals, in slots after its formal parameters.
    std::string_view preBlock, postBlock;
    if (!m_cpfg && colon != std::string_view::npos && trim(condition) == "*") colon = std::string_view::npos;  // ABOP's "A(l) : * -> ..."
    if (m_cpfg && colon != std::string_view::npos) {
        if (!splitCpfgCondition(m_sink, line, condition, preBlock, condition, postBlock)) return;
        if (trim(condition) == "*" || (trim(condition).empty() && (!preBlock.empty() || !postBlock.empty())))
            condition = {};
        if (condition.empty()) colon = std::string_view::npos;
    }
    prod.firstLocal = std::uint16_t(params.size());
    std::vector<std::pair<std::string, double>> globalsAssigned;  // L-system Explorer's variables a block changes
    if ((!preBlock.empty() || !postBlock.empty()) && !collectBlockLocals(line, preBlock, postBlock, params, globalsAssigned))
        return;
    prod.slotCount = int(params.size());

    ExprScope scope{&params, &m_g.defines, &m_macros, &m_g.globals, &m_g.arrays, m_options.curves.get()};
    scope.cpfg = m_options.tabContinues;
    bool ok = true;
    for (const auto& [name, value] : globalsAssigned) {  // the local starts at the variable's value
        Statement init;
        init.slot = std::uint16_t(std::find(params.begin(), params.end(), name) - params.begin());
        std::string number;
        appendNumber(number, value);
        auto e = compileExpr(number, line, scope, m_sink);
        if (!e) return;
        init.expr = std::move(*e);
        prod.pre.push_back(std::move(init));
    }
    FileCalls files{m_g, m_options.include};
    if (!preBlock.empty() && !parseStatements(m_sink, line, preBlock, params, scope, prod.pre, &files)) return;
    if (!postBlock.empty() && !parseStatements(m_sink, line, postBlock, params, scope, prod.post, &files)) return;
    if (colon != std::string_view::npos) {
        if (trim(condition).empty()) {
            m_sink.error(line, condition, "expected a condition after ':' (e.g. 'A(t) : t > 1 -> F')");
            return;
        }
        prod.condition = compileExpr(condition, line, scope, m_sink);
        ok = prod.condition.has_value();
    }
    std::string_view succText;
    if (!splitRuleProbability(line, tail, succText, prod, &scope)) return;
    if (m_cpfg && trim(succText) == "*") succText = {};  // cpfg's empty successor
    if (section == Section::Decomposition && (!prod.left.empty() || !prod.right.empty())) {
        m_sink.error(line, patterns, "decomposition rules are context-free: move the context to a production");
        return;
    }
    int net = prod.pred.symbol == Alphabet::kPush ? 1 : prod.pred.symbol == Alphabet::kPop ? -1 : 0;
    for (const PatternModule& m : prod.predRest)  // cpfg's `[f(y)P(r)] --> *`: the brackets it rewrites
        net += m.symbol == Alphabet::kPush ? 1 : m.symbol == Alphabet::kPop ? -1 : 0;
    if (!parseSuccessor(line, succText, params, prod.successor, net) || !ok) return;
    RuleSet& target = section == Section::Interpretation   ? m_g.interpretation
                      : section == Section::Decomposition ? m_g.decomposition
                                                          : m_g.rules;
    target.productions.push_back(std::move(prod));
}

}  // namespace detail
}  // namespace sprout
