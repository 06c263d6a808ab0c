#pragma once
// The expressions' built-in functions and constants (internal to expr.cpp, which compiles
// calls to them and runs them): trigonometry in degrees like the grammar's `angle` and cpfg,
// C's and mathjs's names, and the binary operators' arithmetic for constant folding.
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/language/expr.hpp"

namespace sprout::expr_builtins {

inline constexpr double kDeg = 3.14159265358979323846 / 180.0;

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

inline const std::unordered_map<std::string, double>& builtinConstants() {
    static const std::unordered_map<std::string, double> k{
        {"pi", 3.14159265358979323846}, {"e", 2.71828182845904523536},
        {"golden", 137.50776405003785}};  // the golden angle in degrees (phyllotaxis)
    return k;
}

inline double apply(Op op, double x, double y) {
    switch (op) {
        case Op::Add: return x + y;
        case Op::Sub: return x - y;
        case Op::Mul: return x * y;
        case Op::Div: return x / y;
        case Op::Mod: return std::fmod(x, y);
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

}  // namespace sprout::expr_builtins
