// Expressions: text compiled once to a stack program (ExprCompiler: text -> tree -> code),
// run (Expr::run) each time a rule is tried or applied.
//
// Index of this file:
//   [SECTION] The compiler: text to tree to code
//   [SECTION] compileExpr
// The built-in functions and the running of a compiled program are expr_run.cpp.

#include "core/language/expr.hpp"
#include "core/language/expr_builtins.hpp"
#include "core/language/vlab/curve_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace sprout {

using namespace expr_detail;

// [SECTION] The compiler: text to tree to code

class ExprCompiler {
public:
    ExprCompiler(std::string_view text, const SourceLine& line, const ExprScope& scope,
                 DiagnosticSink& sink)
        : m_text(text), m_line(line), m_scope(scope), m_sink(sink) {}

    // The body of a function-like #define, compiled where it is used: its errors are
    // reported at the use, naming the macro.
    NodePtr expandMacro(const std::string& name, const ExprMacro& macro, std::vector<NodePtr>& args, int depth) {
        ExprCompiler inner(macro.body, m_line, m_scope, m_sink);
        inner.m_parent = this;
        inner.m_macroName = name;
        inner.m_reportAt = m_callStart;
        inner.m_macroDepth = m_macroDepth + 1;
        for (size_t i = 0; i < macro.params.size(); ++i) inner.m_args.emplace(macro.params[i], args[i].get());
        inner.skipSpace();
        NodePtr root = inner.parseTernary(depth + 1);
        if (!inner.m_failed) {
            inner.skipSpace();
            if (inner.m_pos < inner.m_text.size()) inner.fail(inner.m_pos, "unexpected '" + inner.codePointAt(inner.m_pos) + "' in expression");
        }
        m_nodes += inner.m_nodes;
        if (inner.m_failed) m_failed = true;
        return root ? std::move(root) : makeConst(0);
    }

    std::optional<Expr> compile() {
        skipSpace();
        if (m_pos >= m_text.size()) {
            fail(m_pos, "expected an expression here");
            return std::nullopt;
        }
        NodePtr root = parseTernary(0);
        if (!m_failed) {
            skipSpace();
            if (m_pos < m_text.size()) {
                char c = m_text[m_pos];
                if (c == '=')
                    fail(m_pos, "'=' is not a comparison: write '==' to test equality");
                else
                    fail(m_pos, "unexpected '" + codePointAt(m_pos) + "' in expression");
            }
        }
        if (m_failed) return std::nullopt;
        Expr e;
        if (root->op == Op::Const) return Expr::constant(root->value);
        if (root->op == Op::Slot) {
            e.m_kind = Expr::Kind::Slot;
            e.m_slot = root->slot;
            return e;
        }
        if (root->op == Op::Add || root->op == Op::Sub || root->op == Op::Mul || root->op == Op::Div) {
            const Node& a = *root->a;
            const Node& b = *root->b;
            if ((a.op == Op::Slot && b.op == Op::Const) || (a.op == Op::Const && b.op == Op::Slot)) {
                e.m_kind = a.op == Op::Slot ? Expr::Kind::SlotOpConst : Expr::Kind::ConstOpSlot;
                e.m_op = root->op;
                e.m_slot = a.op == Op::Slot ? a.slot : b.slot;
                e.m_value = a.op == Op::Const ? a.value : b.value;
                return e;
            }
        }
        e.m_kind = Expr::Kind::Program;
        int depth = 0, maxDepth = 0;
        emit(*root, e, depth, maxDepth);
        if (maxDepth > kMaxStack) {
            fail(0, "expression is too complex to evaluate (more than 256 pending values)");
            return std::nullopt;
        }
        return e;
    }

private:
    void fail(size_t at, std::string msg) {
        if (m_failed) return;  // the first error in an expression is the useful one
        m_failed = true;
        if (m_parent) {  // inside a macro body: report at its use
            m_parent->fail(m_reportAt, "in '#define " + m_macroName + "': " + msg);
            return;
        }
        m_sink.error(m_line, m_text.substr(std::min(at, m_text.size())), std::move(msg));
    }
    // The whole UTF-8 character at `at`, for messages.
    std::string codePointAt(size_t at) const {
        unsigned char c = static_cast<unsigned char>(m_text[at]);
        size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 1;
        return std::string(m_text.substr(at, n));
    }
    // A Greek letter (U+0391..U+03C9) at `i`: its two bytes, else 0 (names such as α).
    size_t greekLetter(size_t i) const {
        if (i + 1 >= m_text.size()) return 0;
        const unsigned char a = static_cast<unsigned char>(m_text[i]), b = static_cast<unsigned char>(m_text[i + 1]);
        return (a == 0xCE && b >= 0x91) || (a == 0xCF && b <= 0x89) ? 2 : 0;
    }
    void skipSpace() {
        while (m_pos < m_text.size() && isSpace(m_text[m_pos])) ++m_pos;
    }
    bool peek(std::string_view tok) {
        skipSpace();
        return m_text.substr(m_pos, tok.size()) == tok;
    }
    bool accept(std::string_view tok) {
        if (!peek(tok)) return false;
        m_pos += tok.size();
        return true;
    }

    NodePtr binary(Op op, NodePtr a, NodePtr b) {
        if (a->op == Op::Const && b->op == Op::Const) return makeConst(apply(op, a->value, b->value));
        // Code generation recurses over the tree: bound its size so no input overflows the stack.
        if (++m_nodes > kMaxNodes) {
            fail(m_pos, "expression is too long (more than 2000 operations): split it with define:");
            return makeConst(0);
        }
        auto n = std::make_unique<Node>();
        n->op = op;
        n->a = std::move(a);
        n->b = std::move(b);
        return n;
    }

    NodePtr guard(int depth) {
        if (depth > kMaxDepth) {
            fail(m_pos, "expression is nested too deeply (more than 100 levels)");
            return makeConst(0);
        }
        return nullptr;
    }

    NodePtr parseTernary(int depth) {
        if (auto g = guard(depth)) return g;
        NodePtr cond = parseOr(depth);
        if (m_failed || !accept("?")) return cond;
        NodePtr yes = parseTernary(depth + 1);
        if (m_failed) return cond;
        if (!accept(":")) {
            fail(m_pos, "expected ':' of 'condition ? a : b'");
            return cond;
        }
        NodePtr no = parseTernary(depth + 1);
        if (m_failed) return cond;
        if (cond->op == Op::Const) return cond->value != 0 ? std::move(yes) : std::move(no);
        auto n = std::make_unique<Node>();
        n->op = Op::Select;
        n->a = std::move(cond);
        n->b = std::move(yes);
        n->c = std::move(no);
        return n;
    }

    // `and`, `or`, `not` as words (Python's and ABOP's notes), not the start of a longer name.
    bool acceptWord(std::string_view word) {
        if (!peek(word)) return false;
        const size_t end = m_pos + word.size();
        if (end < m_text.size() && (std::isalnum(static_cast<unsigned char>(m_text[end])) || m_text[end] == '_')) return false;
        m_pos = end;
        return true;
    }
    NodePtr parseOr(int depth) {
        NodePtr a = parseAnd(depth);
        while (!m_failed && (accept("||") || (peek("|") && accept("|")) || acceptWord("or")))
            a = binary(Op::Or, std::move(a), parseAnd(depth));
        return a;
    }
    NodePtr parseAnd(int depth) {
        NodePtr a = parseNot(depth);
        while (!m_failed && (accept("&&") || (peek("&") && accept("&")) || acceptWord("and")))
            a = binary(Op::And, std::move(a), parseNot(depth));
        return a;
    }
    // Python's `not` binds looser than comparisons: `not x > 1` is `!(x > 1)`.
    NodePtr parseNot(int depth) {
        if (auto g = guard(depth)) return g;
        if (acceptWord("not")) return unary(Op::Not, parseNot(depth + 1));
        return parseEquality(depth);
    }
    NodePtr parseEquality(int depth) {
        NodePtr a = parseRelational(depth);
        while (!m_failed) {
            if (accept("==")) a = binary(Op::Eq, std::move(a), parseRelational(depth));
            else if (accept("!=")) a = binary(Op::Ne, std::move(a), parseRelational(depth));
            else break;
        }
        return a;
    }
    NodePtr parseRelational(int depth) {
        NodePtr a = parseAdditive(depth);
        while (!m_failed) {
            if (accept("<=")) a = binary(Op::Le, std::move(a), parseAdditive(depth));
            else if (accept(">=")) a = binary(Op::Ge, std::move(a), parseAdditive(depth));
            else if (accept("<")) a = binary(Op::Lt, std::move(a), parseAdditive(depth));
            else if (accept(">")) a = binary(Op::Gt, std::move(a), parseAdditive(depth));
            else break;
        }
        return a;
    }
    NodePtr parseAdditive(int depth) {
        NodePtr a = parseMultiplicative(depth);
        while (!m_failed) {
            if (accept("+")) a = binary(Op::Add, std::move(a), parseMultiplicative(depth));
            else if (accept("-")) a = binary(Op::Sub, std::move(a), parseMultiplicative(depth));
            else break;
        }
        return a;
    }
    NodePtr parseMultiplicative(int depth) {
        NodePtr a = parseUnary(depth);
        while (!m_failed) {
            if (accept("*")) a = binary(Op::Mul, std::move(a), parseUnary(depth));
            else if (accept("/")) a = binary(Op::Div, std::move(a), parseUnary(depth));
            else if (accept("%")) a = binary(Op::Mod, std::move(a), parseUnary(depth));
            else break;
        }
        return a;
    }
    NodePtr parseUnary(int depth) {
        if (auto g = guard(depth)) return g;
        if (accept("-")) return unary(Op::Neg, parseUnary(depth + 1));
        if (accept("+")) return parseUnary(depth + 1);
        if (peek("!") && !peek("!=")) {
            accept("!");
            return unary(Op::Not, parseUnary(depth + 1));
        }
        return parsePower(depth);
    }
    NodePtr unary(Op op, NodePtr a) {
        if (a->op == Op::Const) return makeConst(op == Op::Neg ? -a->value : double(a->value == 0));
        auto n = std::make_unique<Node>();
        n->op = op;
        n->a = std::move(a);
        return n;
    }
    // ^ binds tighter than unary minus (-x^2 is -(x^2)) and is right-associative.
    NodePtr parsePower(int depth) {
        NodePtr base = parsePrimary(depth);
        if (!m_failed && (accept("^") || accept("**")))
            return binary(Op::Pow, std::move(base), parseUnary(depth + 1));
        return base;
    }

    NodePtr parsePrimary(int depth) {
        if (auto g = guard(depth)) return g;
        skipSpace();
        if (m_pos >= m_text.size()) {
            fail(m_pos, "expression ends too early: a value is missing");
            return makeConst(0);
        }
        char c = m_text[m_pos];
        if (c == '(') {
            size_t open = m_pos++;
            NodePtr inner = parseTernary(depth + 1);
            if (!m_failed && !accept(")")) fail(open, "this '(' is never closed");
            return inner;
        }
        if ((c >= '0' && c <= '9') || c == '.') return parseNumber();
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || greekLetter(m_pos)) return parseName(depth);
        fail(m_pos, "expected a number, a name or '(' but found '" + codePointAt(m_pos) + "'");
        return makeConst(0);
    }

    NodePtr parseNumber() {
        size_t start = m_pos;
        // from_chars: the whole number however long, and independent of the C locale.
        double v = 0;
        const char* first = m_text.data() + m_pos;
        auto r = std::from_chars(first, m_text.data() + m_text.size(), v);
        if (r.ec == std::errc::result_out_of_range) {
            fail(start, "number is too large");
            return makeConst(0);
        }
        if (r.ec != std::errc() || r.ptr == first) {
            fail(start, "malformed number");
            return makeConst(0);
        }
        m_pos += size_t(r.ptr - first);
        return makeConst(v);
    }

    NodePtr parseName(int depth) {
        size_t start = m_pos;
        while (m_pos < m_text.size()) {
            if (const size_t g = greekLetter(m_pos)) m_pos += g;  // α, β, θ ...
            else if (std::isalnum(static_cast<unsigned char>(m_text[m_pos])) || m_text[m_pos] == '_') ++m_pos;
            else break;
        }
        std::string name(m_text.substr(start, m_pos - start));
        if (peek("(")) return parseCall(name, start, depth);
        if (m_scope.arrays) {
            for (const GlobalArray& a : *m_scope.arrays)
                if (a.name == name) return parseArrayElement(a, start, depth);
        }
        if (auto arg = m_args.find(name); arg != m_args.end()) return clone(arg->second);
        if (m_scope.params) {
            for (size_t i = 0; i < m_scope.params->size(); ++i) {
                if ((*m_scope.params)[i] == name) {
                    auto n = std::make_unique<Node>();
                    n->op = Op::Slot;
                    n->slot = std::uint16_t(i);
                    return n;
                }
            }
        }
        if (m_scope.globals) {
            for (size_t i = 0; i < m_scope.globals->size(); ++i) {
                if ((*m_scope.globals)[i] == name) {
                    auto n = std::make_unique<Node>();
                    n->op = Op::Slot;
                    n->slot = std::uint16_t(kGlobalSlot + i);
                    return n;
                }
            }
        }
        if (m_scope.defines) {
            auto it = m_scope.defines->find(name);
            if (it != m_scope.defines->end()) return makeConst(it->second);
        }
        // A function set's function by its name (cpfg defines it: -DNAME=id).
        if (m_scope.curves)
            if (const int id = m_scope.curves->functionId(name)) return makeConst(id);
        auto k = builtinConstants().find(name);
        if (k != builtinConstants().end()) return makeConst(k->second);
        if (m_funcArg) {  // func(NAME, x): NAME should be a function of the set
            std::vector<std::string> names = m_scope.curves ? m_scope.curves->functionNames() : std::vector<std::string>{};
            std::string msg = "unknown function '" + name + "' in func()";
            std::string guess = closestMatch(name, names);
            if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
            else if (names.empty()) msg += ": no function set names its functions (func's first argument is then a function's number, 1 for the first)";
            else msg += ": the function set does not name one so";
            fail(start, msg);
            return makeConst(0);
        }

        std::vector<std::string> known;
        if (m_scope.params) known = *m_scope.params;
        if (m_scope.globals) known.insert(known.end(), m_scope.globals->begin(), m_scope.globals->end());
        if (m_scope.defines)
            for (auto& [d, _] : *m_scope.defines) known.push_back(d);
        for (auto& [d, _] : builtinConstants()) known.push_back(d);
        std::string msg = "unknown name '" + name + "'";
        std::string guess = closestMatch(name, known);
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        else if (!m_scope.params || m_scope.params->empty())
            msg += ": only defined constants can be used here";
        else msg += ": not a parameter of this rule or a defined constant";
        fail(start, msg);
        return makeConst(0);
    }

    // `a[i][j]`: the element's slot, from the indices in row-major order.
    NodePtr parseArrayElement(const GlobalArray& a, size_t start, int depth) {
        NodePtr index;
        for (size_t k = 0; k < a.dims.size(); ++k) {
            if (!accept("[")) {
                fail(m_pos < m_text.size() ? m_pos : start, "'" + a.name + "' is an array of " +
                     std::to_string(a.dims.size()) + " dimension" + (a.dims.size() == 1 ? "" : "s") +
                     ": give each index in brackets, as in " + a.name + "[0]");
                return makeConst(0);
            }
            NodePtr i = parseTernary(depth + 1);
            if (m_failed) return makeConst(0);
            if (!accept("]")) {
                fail(m_pos < m_text.size() ? m_pos : start, "expected ']' after the index of '" + a.name + "'");
                return makeConst(0);
            }
            auto floorOf = std::make_unique<Node>();  // cpfg truncates an index to an integer
            floorOf->op = Op::Call1;
            floorOf->fn = truncIndex();
            floorOf->a = std::move(i);
            if (!index) {
                index = std::move(floorOf);
            } else {
                auto mul = std::make_unique<Node>();
                mul->op = Op::Mul;
                mul->a = std::move(index);
                mul->b = makeConst(a.dims[k]);
                auto add = std::make_unique<Node>();
                add->op = Op::Add;
                add->a = std::move(mul);
                add->b = std::move(floorOf);
                index = std::move(add);
            }
        }
        auto n = std::make_unique<Node>();
        n->op = Op::Index;
        n->slot = std::uint16_t(kGlobalSlot + a.first);
        n->value = a.size();
        n->a = std::move(index);
        return n;
    }

    static std::uint8_t truncIndex() {
        for (size_t i = 0; i < std::size(kFunctions1); ++i)
            if (std::string_view(kFunctions1[i].name) == "trunc") return std::uint8_t(i);
        return 0;
    }

    NodePtr parseCall(const std::string& name, size_t start, int depth) {
        size_t open = m_pos;
        accept("(");
        std::vector<NodePtr> args;
        if (!accept(")")) {
            do {
                m_funcArg = name == "func" && args.empty();
                args.push_back(parseTernary(depth + 1));
                m_funcArg = false;
                if (m_failed) return makeConst(0);
            } while (accept(","));
            if (!accept(")")) {
                fail(m_pos < m_text.size() ? m_pos : open,
                     m_pos < m_text.size() ? "expected ',' or ')' in the arguments of '" + name + "'"
                                           : "the '(' of '" + name + "(' is never closed");
                return makeConst(0);
            }
        }
        auto arity = [&](size_t want) {
            if (args.size() == want) return true;
            fail(start, "'" + name + "' takes " + std::to_string(want) + " argument" +
                            (want == 1 ? "" : "s") + ", not " + std::to_string(args.size()));
            return false;
        };
        if (m_scope.macros) {
            if (auto it = m_scope.macros->find(name); it != m_scope.macros->end()) {
                if (!arity(it->second.params.size())) return makeConst(0);
                if (m_macroDepth >= 16) {
                    fail(start, "'#define " + name + "' expands into itself too deeply (more than 16 levels)");
                    return makeConst(0);
                }
                m_callStart = start;
                return expandMacro(name, it->second, args, depth);
            }
        }
        if (name == "bran" || name == "biran") {  // cpfg: beta and binomial samples
            if (!arity(2)) return makeConst(0);
            auto n = std::make_unique<Node>();
            n->op = name == "bran" ? Op::Beta : Op::Binomial;
            n->a = std::move(args[0]);
            n->b = std::move(args[1]);
            return n;
        }
        if (name == "srand") {  // cpfg: starts the random numbers again from this seed
            if (!arity(1)) return makeConst(0);
            auto n = std::make_unique<Node>();
            n->op = Op::Srand;
            n->a = std::move(args[0]);
            return n;
        }
        if (const std::optional<CurveCall> c = curveCallNamed(name)) return funcCall(*c, name, start, std::move(args));
        // cpfg's names: ran(x) is uniform in [0, x), nran(mean, sigma) normal, random(a, b) uniform.
        if (name == "rand" || name == "uniform" || name == "normal" || name == "gauss" || name == "ran" ||
            name == "nran" || name == "random") {
            bool isNormal = name == "normal" || name == "gauss" || name == "nran";
            if (!isNormal && args.empty()) {
                args.push_back(makeConst(0));
                args.push_back(makeConst(1));
            } else if (!isNormal && args.size() == 1) {
                args.insert(args.begin(), makeConst(0));
            }
            if (!arity(2)) return makeConst(0);
            auto n = std::make_unique<Node>();
            n->op = isNormal ? Op::Normal : Op::Rand;
            n->a = std::move(args[0]);
            n->b = std::move(args[1]);
            return n;
        }
        for (size_t i = 0; i < std::size(kFunctions1); ++i) {
            if (name != kFunctions1[i].name) continue;
            if (!arity(1)) return makeConst(0);
            if (args[0]->op == Op::Const) return makeConst(kFunctions1[i].fn(args[0]->value));
            auto n = std::make_unique<Node>();
            n->op = Op::Call1;
            n->fn = std::uint8_t(i);
            n->a = std::move(args[0]);
            return n;
        }
        for (size_t i = 0; i < std::size(kFunctions2); ++i) {
            if (name != kFunctions2[i].name) continue;
            if (!arity(2)) return makeConst(0);
            if (args[0]->op == Op::Const && args[1]->op == Op::Const)
                return makeConst(kFunctions2[i].fn(args[0]->value, args[1]->value));
            auto n = std::make_unique<Node>();
            n->op = Op::Call2;
            n->fn = std::uint8_t(i);
            n->a = std::move(args[0]);
            n->b = std::move(args[1]);
            return n;
        }
        std::string msg = "unknown function '" + name + "'";
        std::string guess = closestMatch(name, builtinFunctionNames());
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        fail(start, msg);
        return makeConst(0);
    }

    // cpfg's func(id, x), curveX/Y/Z(id, t) and curveGAL(id): the id-th function (a number, or
    // a function set's name) or curve of the view file; an id with none gives 0 there, as in
    // cpfg, and a warning here.
    NodePtr funcCall(CurveCall c, const std::string& name, size_t start, std::vector<NodePtr> args) {
        const bool func = c == CurveCall::Func;
        if (!m_scope.curves) {
            fail(start, name + "() needs cpfg's " + (func ? "functions: the view file's 'function:' or 'function set:' lines" :
                                                            "curves: the view file's 'curve:' lines") + " (open the VLab object's folder)");
            return makeConst(0);
        }
        const size_t want = c == CurveCall::CurveLength ? 1 : 2;
        if (args.size() != want) {
            fail(start, "'" + name + "' takes " + (want == 1 ? "1 argument (a curve)" : func ? "2 arguments (a function and x)" :
                                                   "2 arguments (a curve and t in [0, 1])") + ", not " + std::to_string(args.size()));
            return makeConst(0);
        }
        if (want == 1) args.push_back(makeConst(0));  // curveGAL(id): the second is not used
        const CurveTables& t = *m_scope.curves;
        if (args[0]->op == Op::Const)
            if (std::string problem = t.idProblem(c, args[0]->value); !problem.empty()) warn(start, std::move(problem));
        if (args[0]->op == Op::Const && args[1]->op == Op::Const) return makeConst(t.call(c, args[0]->value, args[1]->value));
        auto n = std::make_unique<Node>();
        n->op = Op::Func;
        n->fn = std::uint8_t(c);
        n->a = std::move(args[0]);
        n->b = std::move(args[1]);
        return n;
    }
    // A warning at `at` (inside a #define's body: at its use).
    void warn(size_t at, std::string msg) {
        ExprCompiler* root = this;
        while (root->m_parent) {
            at = root->m_reportAt;
            msg = "in '#define " + root->m_macroName + "': " + msg;
            root = root->m_parent;
        }
        root->m_sink.warning(root->m_line, root->m_text.substr(std::min(at, root->m_text.size())), std::move(msg));
    }

    void emit(const Node& n, Expr& e, int& depth, int& maxDepth) {
        for (const Node* child : {n.a.get(), n.b.get(), n.c.get()})
            if (child) emit(*child, e, depth, maxDepth);
        Instr in{n.op};
        in.fn = n.fn;
        in.slot = n.slot;
        in.value = n.value;
        int arity = (n.a ? 1 : 0) + (n.b ? 1 : 0) + (n.c ? 1 : 0);
        depth += 1 - arity;
        maxDepth = std::max(maxDepth, depth);
        if (n.op == Op::Rand || n.op == Op::Normal || n.op == Op::Beta || n.op == Op::Binomial || n.op == Op::Srand)
            e.m_usesRandom = true;
        if (n.op == Op::Func) e.m_curves = m_scope.curves;
        e.m_code.push_back(in);
    }

    std::string_view m_text;
    const SourceLine& m_line;
    const ExprScope& m_scope;
    DiagnosticSink& m_sink;
    ExprCompiler* m_parent = nullptr;  // set while compiling a macro body
    std::string m_macroName;
    size_t m_reportAt = 0, m_callStart = 0;
    int m_macroDepth = 0;
    std::unordered_map<std::string, const Node*> m_args;  // macro parameters -> argument trees
    size_t m_pos = 0;
    bool m_failed = false;
    bool m_funcArg = false;     // compiling func()'s first argument
    int m_nodes = 0;
};

// [SECTION] compileExpr

std::optional<Expr> compileExpr(std::string_view text, const SourceLine& line, const ExprScope& scope,
                                DiagnosticSink& sink) {
    return ExprCompiler(text, line, scope, sink).compile();
}


}  // namespace sprout
