// Expressions: text compiled once to a stack program (ExprCompiler: text -> tree -> code),
// run (Expr::run) each time a rule is tried or applied: the operators and numbers here, the
// names and calls in expr_names.cpp, the built-in functions and the running in expr_run.cpp.

#include "core/language/expr_compiler.hpp"
#include "core/language/vlab/curve_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace sprout {

using namespace expr_detail;

// The body of a function-like #define, compiled where it is used: its errors are
// reported at the use, naming the macro.
NodePtr ExprCompiler::expandMacro(const std::string& name, const ExprMacro& macro, std::vector<NodePtr>& args, int depth) {
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

std::optional<Expr> ExprCompiler::compile() {
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
    // cpfg's x / c with c not 0 is x / c.
    if (root->op == Op::DivC && root->b->op == Op::Const && root->b->value != 0) root->op = Op::Div;
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
    int depth = 0, maxDepth = 0, shortCircuits = 0;
    emit(*root, e, depth, maxDepth, shortCircuits);
    // cpfg's skips each leave at most one value on the stack (runCpfg).
    if (maxDepth + (m_scope.cpfg ? shortCircuits : 0) > kMaxStack) {
        fail(0, "expression is too complex to evaluate (more than 256 pending values)");
        return std::nullopt;
    }
    if (m_scope.cpfg && shortCircuits) {
        e.m_kind = Expr::Kind::CpfgTree;
        e.m_code.clear();
        e.m_tree = std::shared_ptr<const Node>(std::move(root));
    }
    return e;
}

void ExprCompiler::fail(size_t at, std::string msg) {
    if (m_failed) return;  // the first error in an expression is the useful one
    m_failed = true;
    if (m_parent) {  // inside a macro body: report at its use
        m_parent->fail(m_reportAt, "in '#define " + m_macroName + "': " + msg);
        return;
    }
    m_sink.error(m_line, m_text.substr(std::min(at, m_text.size())), std::move(msg));
}

// The whole UTF-8 character at `at`, for messages.
std::string ExprCompiler::codePointAt(size_t at) const {
    unsigned char c = static_cast<unsigned char>(m_text[at]);
    size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 1;
    return std::string(m_text.substr(at, n));
}

// A Greek letter (U+0391..U+03C9) at `i`: its two bytes, else 0 (names such as α).
size_t ExprCompiler::greekLetter(size_t i) const {
    if (i + 1 >= m_text.size()) return 0;
    const unsigned char a = static_cast<unsigned char>(m_text[i]), b = static_cast<unsigned char>(m_text[i + 1]);
    return (a == 0xCE && b >= 0x91) || (a == 0xCF && b <= 0x89) ? 2 : 0;
}

void ExprCompiler::skipSpace() {
    while (m_pos < m_text.size() && isSpace(m_text[m_pos])) ++m_pos;
}

bool ExprCompiler::peek(std::string_view tok) {
    skipSpace();
    return m_text.substr(m_pos, tok.size()) == tok;
}

bool ExprCompiler::accept(std::string_view tok) {
    if (!peek(tok)) return false;
    m_pos += tok.size();
    return true;
}

NodePtr ExprCompiler::binary(Op op, NodePtr a, NodePtr b) {
    // cpfg's || and && are not folded: their short-circuits depend on their operands' shapes.
    if (a->op == Op::Const && b->op == Op::Const && !(m_scope.cpfg && (op == Op::Or || op == Op::And)))
        return folded(apply(op, a->value, b->value));
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

NodePtr ExprCompiler::guard(int depth) {
    if (depth > kMaxDepth) {
        fail(m_pos, "expression is nested too deeply (more than 100 levels)");
        return makeConst(0);
    }
    return nullptr;
}

NodePtr ExprCompiler::parseTernary(int depth) {
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
    if (cond->op == Op::Const && !m_scope.cpfg) return cond->value != 0 ? std::move(yes) : std::move(no);
    auto n = std::make_unique<Node>();
    n->op = Op::Select;
    n->a = std::move(cond);
    n->b = std::move(yes);
    n->c = std::move(no);
    return n;
}

// `and`, `or`, `not` as words (Python's and ABOP's notes), not the start of a longer name.
bool ExprCompiler::acceptWord(std::string_view word) {
    if (!peek(word)) return false;
    const size_t end = m_pos + word.size();
    if (end < m_text.size() && (std::isalnum(static_cast<unsigned char>(m_text[end])) || m_text[end] == '_')) return false;
    m_pos = end;
    return true;
}

NodePtr ExprCompiler::parseOr(int depth) {
    NodePtr a = parseAnd(depth);
    while (!m_failed && (accept("||") || (peek("|") && accept("|")) || acceptWord("or")))
        a = binary(Op::Or, std::move(a), parseAnd(depth));
    return a;
}

NodePtr ExprCompiler::parseAnd(int depth) {
    NodePtr a = parseNot(depth);
    while (!m_failed && (accept("&&") || (peek("&") && accept("&")) || acceptWord("and")))
        a = binary(Op::And, std::move(a), parseNot(depth));
    return a;
}

// Python's `not` binds looser than comparisons: `not x > 1` is `!(x > 1)`.
NodePtr ExprCompiler::parseNot(int depth) {
    if (auto g = guard(depth)) return g;
    if (acceptWord("not")) return unary(Op::Not, parseNot(depth + 1));
    return parseEquality(depth);
}

NodePtr ExprCompiler::parseEquality(int depth) {
    NodePtr a = parseRelational(depth);
    while (!m_failed) {
        if (accept("==")) a = binary(Op::Eq, std::move(a), parseRelational(depth));
        else if (accept("!=") || (m_scope.cpfg && accept("<>"))) a = binary(Op::Ne, std::move(a), parseRelational(depth));
        else break;
    }
    return a;
}

NodePtr ExprCompiler::parseRelational(int depth) {
    NodePtr a = parseAdditive(depth);
    while (!m_failed) {
        if (m_scope.cpfg && peek("<>")) break;  // cpfg's `!=`
        if (accept("<=")) a = binary(Op::Le, std::move(a), parseAdditive(depth));
        else if (accept(">=")) a = binary(Op::Ge, std::move(a), parseAdditive(depth));
        else if (accept("<")) a = binary(Op::Lt, std::move(a), parseAdditive(depth));
        else if (accept(">")) a = binary(Op::Gt, std::move(a), parseAdditive(depth));
        else break;
    }
    return a;
}

NodePtr ExprCompiler::parseAdditive(int depth) {
    NodePtr a = parseMultiplicative(depth);
    while (!m_failed) {
        if (accept("+")) a = binary(Op::Add, std::move(a), parseMultiplicative(depth));
        else if (accept("-")) a = binary(Op::Sub, std::move(a), parseMultiplicative(depth));
        else break;
    }
    return a;
}

NodePtr ExprCompiler::parseMultiplicative(int depth) {
    const bool c = m_scope.cpfg;
    NodePtr a = c ? parseCpfgPower(depth) : parseUnary(depth);
    while (!m_failed) {
        if (accept("*")) a = binary(Op::Mul, std::move(a), c ? parseCpfgPower(depth) : parseUnary(depth));
        else if (accept("/")) a = binary(c ? Op::DivC : Op::Div, std::move(a), c ? parseCpfgPower(depth) : parseUnary(depth));
        else if (accept("%")) a = binary(c ? Op::ModC : Op::Mod, std::move(a), c ? parseCpfgPower(depth) : parseUnary(depth));
        else break;
    }
    return a;
}

// cpfg's grammar (lsys_input.y): `^` is left-associative, and unary minus and `!` bind tighter
// than it: -x^2 is (-x)^2, 2^3^2 is 64.
NodePtr ExprCompiler::parseCpfgPower(int depth) {
    NodePtr a = parseCpfgUnary(depth);
    while (!m_failed && accept("^")) a = binary(Op::Pow, std::move(a), parseCpfgUnary(depth));
    return a;
}

NodePtr ExprCompiler::parseCpfgUnary(int depth) {
    if (auto g = guard(depth)) return g;
    if (accept("-")) return unary(Op::Neg, parseCpfgUnary(depth + 1));
    if (accept("+")) return parseCpfgUnary(depth + 1);
    if (peek("!") && !peek("!=")) {
        accept("!");
        return unary(Op::Not, parseCpfgUnary(depth + 1));
    }
    return parsePrimary(depth);
}

NodePtr ExprCompiler::parseUnary(int depth) {
    if (auto g = guard(depth)) return g;
    if (accept("-")) return unary(Op::Neg, parseUnary(depth + 1));
    if (accept("+")) return parseUnary(depth + 1);
    if (peek("!") && !peek("!=")) {
        accept("!");
        return unary(Op::Not, parseUnary(depth + 1));
    }
    return parsePower(depth);
}

NodePtr ExprCompiler::unary(Op op, NodePtr a) {
    if (a->op == Op::Const) return folded(op == Op::Neg ? -a->value : double(a->value == 0));
    auto n = std::make_unique<Node>();
    n->op = op;
    n->a = std::move(a);
    return n;
}

// ^ binds tighter than unary minus (-x^2 is -(x^2)) and is right-associative.
NodePtr ExprCompiler::parsePower(int depth) {
    NodePtr base = parsePrimary(depth);
    if (!m_failed && (accept("^") || accept("**")))
        return binary(Op::Pow, std::move(base), parseUnary(depth + 1));
    return base;
}

NodePtr ExprCompiler::parsePrimary(int depth) {
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

NodePtr ExprCompiler::parseNumber() {
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

void ExprCompiler::emit(const Node& n, Expr& e, int& depth, int& maxDepth, int& shortCircuits) {
    for (const Node* child : {n.a.get(), n.b.get(), n.c.get()})
        if (child) emit(*child, e, depth, maxDepth, shortCircuits);
    if (n.op == Op::Or || n.op == Op::And || n.op == Op::Select) ++shortCircuits;
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

std::optional<Expr> compileExpr(std::string_view text, const SourceLine& line, const ExprScope& scope,
                                DiagnosticSink& sink) {
    return ExprCompiler(text, line, scope, sink).compile();
}

std::optional<Expr> compileArrayIndex(std::string_view text, const GlobalArray& array, const SourceLine& line,
                                      const ExprScope& scope, DiagnosticSink& sink, int* cpfgMisread) {
    ExprCompiler c(text, line, scope, sink);
    auto e = c.compileIndex(array);
    if (cpfgMisread) *cpfgMisread = scope.cpfg ? c.misreadSlot() : -1;
    return e;
}

std::optional<Expr> ExprCompiler::compileIndex(const GlobalArray& array) {
    skipSpace();
    if (!accept(array.name)) {
        fail(m_pos, "expected an element of '" + array.name + "'");
        return std::nullopt;
    }
    NodePtr index = arrayIndex(array, 0, 0);
    skipSpace();
    if (!m_failed && m_pos < m_text.size()) fail(m_pos, "unexpected '" + codePointAt(m_pos) + "' after the element");
    if (m_failed) return std::nullopt;
    if (index->op == Op::Const) return Expr::constant(index->value);
    Expr e;
    e.m_kind = Expr::Kind::Program;
    int depth = 0, maxDepth = 0, shortCircuits = 0;
    emit(*index, e, depth, maxDepth, shortCircuits);
    if (m_scope.cpfg && shortCircuits) {
        e.m_kind = Expr::Kind::CpfgTree;
        e.m_code.clear();
        e.m_tree = std::shared_ptr<const Node>(std::move(index));
    }
    return e;
}

}  // namespace sprout
