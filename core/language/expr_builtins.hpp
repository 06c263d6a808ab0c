#pragma once
// The expressions' built-in functions and constants, which the compiler (expr.cpp) folds and
// names and the run (expr_run.cpp) calls, and the compiler's tree. Internal to core/language.
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include "core/language/expr.hpp"

namespace sprout::expr_detail {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr int kMaxStack = 256;     // evaluation stack of one program

using Fn1 = double (*)(double);
using Fn2 = double (*)(double, double);

struct Function1 { const char* name; Fn1 fn; };
struct Function2 { const char* name; Fn2 fn; };

inline const Function1 kFunctions1[] = {
    {"sin", [](double x) { return std::sin(x * kDeg); }},
    {"cos", [](double x) { return std::cos(x * kDeg); }},
    {"tan", [](double x) { return std::tan(x * kDeg); }},
    {"asin", [](double x) { return std::asin(x) / kDeg; }},
    {"acos", [](double x) { return std::acos(x) / kDeg; }},
    {"atan", [](double x) { return std::atan(x) / kDeg; }},
    {"sqrt", [](double x) { return std::sqrt(x); }},
    {"exp", [](double x) { return std::exp(x); }},
    {"log", [](double x) { return std::log(x); }},
    {"abs", [](double x) { return std::fabs(x); }},
    {"floor", [](double x) { return std::floor(x); }},
    {"ceil", [](double x) { return std::ceil(x); }},
    {"round", [](double x) { return std::round(x); }},
    {"sign", [](double x) { return double((x > 0) - (x < 0)); }},
    {"trunc", [](double x) { return std::trunc(x); }},
    {"fabs", [](double x) { return std::fabs(x); }},
    // mathjs's (L-system Explorer's expressions): fix rounds towards zero.
    {"fix", [](double x) { return std::trunc(x); }},
    {"cbrt", [](double x) { return std::cbrt(x); }},
    {"log10", [](double x) { return std::log10(x); }},
    {"log2", [](double x) { return std::log2(x); }},
    {"square", [](double x) { return x * x; }},
    {"cube", [](double x) { return x * x * x; }},
};
inline const Function2 kFunctions2[] = {
    {"atan2", [](double y, double x) { return std::atan2(y, x) / kDeg; }},
    {"min", [](double a, double b) { return std::fmin(a, b); }},
    {"max", [](double a, double b) { return std::fmax(a, b); }},
    {"pow", [](double a, double b) { return std::pow(a, b); }},
    {"mod", [](double a, double b) { return b == 0 ? a : a - b * std::floor(a / b); }},  // mathjs: the divisor's sign
    {"hypot", [](double a, double b) { return std::hypot(a, b); }},
};

const std::unordered_map<std::string, double>& builtinConstants();
// Binary operators, and cpfg's bran(a, b) and biran(n, p) (expr_run.cpp).
double apply(Op op, double x, double y);
double betaSample(double a, double b, Rng& rng);
double binomialSample(double n, double p, Rng& rng);

constexpr int kMaxDepth = 100;     // nesting bound: no input can overflow the parser's stack
constexpr int kMaxNodes = 2000;    // operations in one expression

// The tree an expression is parsed into, before its code is emitted (expr.cpp).
struct Node {
    Op op;
    std::uint8_t fn = 0;
    std::uint16_t slot = 0;
    double value = 0;
    // A constant folded from operators or a call: cpfg's Eval treats it as the operator it was
    // (its short-circuits look at whether an operand is one), not as a number written.
    bool compound = false;
    std::unique_ptr<Node> a, b, c;
};
using NodePtr = std::unique_ptr<Node>;

inline NodePtr clone(const Node* n) {
    if (!n) return nullptr;
    auto c = std::make_unique<Node>();
    c->op = n->op;
    c->fn = n->fn;
    c->slot = n->slot;
    c->value = n->value;
    c->compound = n->compound;
    c->a = clone(n->a.get());
    c->b = clone(n->b.get());
    c->c = clone(n->c.get());
    return c;
}

inline NodePtr makeConst(double v) {
    auto n = std::make_unique<Node>();
    n->op = Op::Const;
    n->value = v;
    return n;
}

// A constant computed from operators or a call (Node::compound).
inline NodePtr folded(double v) {
    NodePtr n = makeConst(v);
    n->compound = true;
    return n;
}

// cpfg's Eval (generate.c) on a tree: the value, with cpfg's short-circuits (expr_run.cpp).
double runCpfg(const Node& root, const double* slots, Rng& rng, const CurveTables* curves);

}  // namespace sprout::expr_detail
