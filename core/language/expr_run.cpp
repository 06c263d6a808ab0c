// Expressions run: the built-in functions and constants, the binary operators, cpfg's random
// samples, and Expr::run, the stack machine a compiled expression is (expr.cpp compiles it).
#include <algorithm>
#include <cmath>

#include "core/language/expr.hpp"
#include "core/language/expr_builtins.hpp"
#include "core/language/vlab/curve_files.hpp"

namespace sprout {
namespace expr_detail {

const std::unordered_map<std::string, double>& builtinConstants() {
    static const std::unordered_map<std::string, double> k{
        {"pi", 3.14159265358979323846}, {"e", 2.71828182845904523536},
        {"golden", 137.50776405003785}};  // the golden angle in degrees (phyllotaxis)
    return k;
}

// cpfg's bran(a, b): a sample of the beta distribution (cpfg's utility.c, Cheng's algorithm BA).
double betaSample(double a, double b, Rng& rng) {
    const double s = a + b;
    const double lambda = std::min(a, b) <= 1 ? std::min(a, b) : std::sqrt((2 * a * b - s) / (s - 2));
    const double u = a + lambda;
    if (!(s > 0) || !(lambda > 0) || !std::isfinite(s)) return std::nan("");
    double u1, u2, v, y;
    for (int tries = 0; tries < 10'000; ++tries) {
        do u1 = rng.exprUniform(); while (u1 == 0);
        do u2 = rng.exprUniform(); while (u2 == 0);
        v = (1 / lambda) * std::log(u1 / (1 - u1));
        y = a * std::exp(v);
        if (!(s * std::log(s / (b + y)) + u * v - std::log(4.0) < std::log(u1 * u1 * u2))) return y / (b + y);
    }
    return y / (b + y);
}

// cpfg's biran(n, p): the number of n coins that fall below p.
double binomialSample(double n, double p, Rng& rng) {
    int count = 0;
    if (!(n > 0)) return 0;  // also NaN
    const int trials = int(std::min(n, 1e6));
    for (int i = 0; i < trials; ++i) count += rng.exprUniform() <= p;
    return count;
}

double apply(Op op, double x, double y) {
    switch (op) {
        case Op::Add: return x + y;
        case Op::Sub: return x - y;
        case Op::Mul: return x * y;
        case Op::Div: return x / y;
        case Op::Mod: return std::fmod(x, y);
        case Op::DivC: return x / (y == 0 ? 1 : y);  // cpfg warns and divides by 1
        case Op::ModC: {  // cpfg: (double)((int)x % (int)y); x86 makes an int of what none holds INT_MIN
            auto asInt = [](double v) { return v > -2147483649.0 && v < 2147483648.0 ? std::int64_t(v) : std::int64_t(INT32_MIN); };
            const std::int64_t a = asInt(x), b = asInt(y);
            return b == 0 ? std::nan("") : double(a % b);  // cpfg stops (SIGFPE) at a divisor 0
        }
        case Op::Pow: return std::pow(x, y);
        case Op::Lt: return x < y;
        case Op::Le: return x <= y;
        case Op::Gt: return x > y;
        case Op::Ge: return x >= y;
        case Op::Eq: return x == y;
        case Op::Ne: return x != y;
        case Op::And: return (x != 0) && (y != 0);
        case Op::Or: return (x != 0) || (y != 0);
        default: return 0;
    }
}

namespace {

// One instruction on the stack `st` of `sp` values.
inline void step(const Instr& in, double* st, int& sp, const double* slots, Rng& rng, const CurveTables* curves) {
        switch (in.op) {
            case Op::Const: st[sp++] = in.value; break;
            case Op::Slot: st[sp++] = slots[in.slot]; break;
            case Op::Neg: st[sp - 1] = -st[sp - 1]; break;
            case Op::Not: st[sp - 1] = st[sp - 1] == 0; break;
            case Op::Call1: st[sp - 1] = kFunctions1[in.fn].fn(st[sp - 1]); break;
            case Op::Call2: --sp; st[sp - 1] = kFunctions2[in.fn].fn(st[sp - 1], st[sp]); break;
            case Op::Rand: --sp; st[sp - 1] = st[sp - 1] + (st[sp] - st[sp - 1]) * rng.exprUniform(); break;
            case Op::Normal: --sp; st[sp - 1] = rng.exprNormal(st[sp - 1], st[sp]); break;
            case Op::Beta: --sp; st[sp - 1] = betaSample(st[sp - 1], st[sp], rng); break;
            case Op::Binomial: --sp; st[sp - 1] = binomialSample(st[sp - 1], st[sp], rng); break;
            case Op::Func: --sp; st[sp - 1] = curves->call(CurveCall(in.fn), st[sp - 1], st[sp]); break;
            case Op::Clamp: st[sp - 1] = st[sp - 1] < 0 ? 0 : st[sp - 1] >= in.value ? in.value - 1 : st[sp - 1]; break;
            case Op::Index: st[sp - 1] = slots[in.slot + arrayOffset(st[sp - 1], in.value)]; break;
            case Op::Srand:  // cpfg casts to a long: out of range or NaN is 0 here, never UB
                rng.exprSeed(std::fabs(st[sp - 1]) < 9e18 ? std::int64_t(st[sp - 1]) : 0);
                st[sp - 1] = 0;
                break;
            case Op::Select: sp -= 2; st[sp - 1] = st[sp - 1] != 0 ? st[sp] : st[sp + 1]; break;
            case Op::Add: --sp; st[sp - 1] += st[sp]; break;
            case Op::Sub: --sp; st[sp - 1] -= st[sp]; break;
            case Op::Mul: --sp; st[sp - 1] *= st[sp]; break;
            case Op::Div: --sp; st[sp - 1] /= st[sp]; break;
            default: --sp; st[sp - 1] = apply(in.op, st[sp - 1], st[sp]); break;
        }
}

// cpfg's Eval (generate.c) walks an expression as a postfix list with a stack. After an
// operand that is itself an operation (not a name nor a number) and is not its operator's
// last, it looks at the operator: `||` with a true operand and `&&` with a false one are
// skipped (not applied; the operand's value is the result), a `?:` whose condition is false
// skips its second operand (a 0 in its place), one whose second operand is 0 skips its third,
// and one whose condition is true ends after its second (not applied: the condition's value
// stays on the stack, under the result, where an operator above takes it as its operand). A
// skipped operator is looked at so by the operator above it, whichever operand it is.
class CpfgEval {
public:
    CpfgEval(const double* slots, Rng& rng, const CurveTables* curves) : m_slots(slots), m_rng(rng), m_curves(curves) {}
    double value(const Node& root) {
        run(root);
        return m_st[m_sp - 1];
    }

private:
    static bool operation(const Node& n) { return n.op == Op::Const ? n.compound : n.op != Op::Slot; }
    void push(double v) { m_st[m_sp++] = v; }
    // `n` evaluated onto the stack; true when it ended in a skip.
    bool run(const Node& n) {
        const Node* operands[3] = {n.a.get(), n.b.get(), n.c.get()};
        const int count = (n.a ? 1 : 0) + (n.b ? 1 : 0) + (n.c ? 1 : 0);
        int jumped = -1;
        for (int i = 0; i < count; ++i) {
            if (i == jumped) continue;
            const bool skipped = run(*operands[i]);
            if (!operation(*operands[i]) || !(i < count - 1 || skipped)) continue;
            const double top = m_st[m_sp - 1];
            if (n.op == Op::Or && top != 0) return true;
            if (n.op == Op::And && top == 0) return true;
            if (n.op == Op::Select && i < count - 1) {
                if (top == 0) {
                    push(0);
                    jumped = i + 1;
                }
                if (i + 1 == count - 1 && m_st[m_sp - 2] != 0) return true;
            }
        }
        Instr in{n.op};
        in.fn = n.fn;
        in.slot = n.slot;
        in.value = n.value;
        step(in, m_st, m_sp, m_slots, m_rng, m_curves);
        return false;
    }

    double m_st[2 * kMaxStack];
    int m_sp = 0;
    const double* m_slots;
    Rng& m_rng;
    const CurveTables* m_curves;
};

}  // namespace

double runCpfg(const Node& root, const double* slots, Rng& rng, const CurveTables* curves) {
    return CpfgEval(slots, rng, curves).value(root);
}

}  // namespace expr_detail

using namespace expr_detail;

double Expr::run(const double* slots, Rng& rng) const {
    double st[kMaxStack];
    int sp = 0;
    for (const Instr& in : m_code) step(in, st, sp, slots, rng, m_curves);
    return st[0];
}

double Expr::runCpfgTree(const double* slots, Rng& rng) const { return runCpfg(*m_tree, slots, rng, m_curves); }

std::vector<std::string> builtinFunctionNames() {
    std::vector<std::string> names{"rand", "uniform", "normal", "gauss", "ran", "nran", "random", "bran", "biran", "srand", "func",
                                   "curveX", "curveY", "curveZ", "curveGAL"};
    for (auto& f : kFunctions1) names.push_back(f.name);
    for (auto& f : kFunctions2) names.push_back(f.name);
    return names;
}

}  // namespace sprout
