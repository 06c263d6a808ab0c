// The expression compiler and evaluator used in parameters, conditions and settings.
#include <gtest/gtest.h>

#include <cmath>

#include "core/language/expr.hpp"

namespace sprout::test {
namespace {

struct Compiled {
    std::optional<Expr> expr;
    std::vector<Diagnostic> diags;
};

Compiled compile(const std::string& text, std::vector<std::string> params = {},
                 std::unordered_map<std::string, double> defines = {}) {
    static std::string keep;
    keep = text;
    SourceLine line{1, keep, {}};
    DiagnosticSink sink;
    static std::vector<std::string> p;
    static std::unordered_map<std::string, double> d;
    p = std::move(params);
    d = std::move(defines);
    ExprScope scope{&p, &d};
    Compiled c;
    c.expr = compileExpr(keep, line, scope, sink);
    c.diags = sink.all();
    return c;
}

double eval(const std::string& text, std::vector<double> slots = {}, std::vector<std::string> params = {}) {
    Compiled c = compile(text, std::move(params));
    if (!c.expr) {
        ADD_FAILURE() << text << ": " << (c.diags.empty() ? "?" : c.diags[0].message);
        return NAN;
    }
    Rng rng(1);
    return c.expr->eval(slots.data(), rng);
}

TEST(Expr, ArithmeticAndPrecedence) {
    EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7);
    EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9);
    EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512);  // right-associative
    EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4);      // ^ binds tighter than unary minus
    EXPECT_DOUBLE_EQ(eval("7 % 4"), 3);
    EXPECT_DOUBLE_EQ(eval("10 / 4"), 2.5);
    EXPECT_DOUBLE_EQ(eval("1.5e2 + .5"), 150.5);
}

TEST(Expr, ComparisonsAndLogic) {
    EXPECT_EQ(eval("1 < 2 && 2 <= 2"), 1);
    EXPECT_EQ(eval("1 > 2 || 3 >= 4"), 0);
    EXPECT_EQ(eval("!(1 == 1)"), 0);
    EXPECT_EQ(eval("1 != 2"), 1);
    EXPECT_EQ(eval("2 > 1 & 1 > 0"), 1);  // ABOP writes a single &
    EXPECT_EQ(eval("0 ? 5 : 6"), 6);
}

TEST(Expr, FunctionsUseDegrees) {
    EXPECT_NEAR(eval("sin(30)"), 0.5, 1e-12);
    EXPECT_NEAR(eval("cos(60)"), 0.5, 1e-12);
    EXPECT_NEAR(eval("tan(45)"), 1, 1e-12);
    EXPECT_NEAR(eval("asin(1)"), 90, 1e-12);
    EXPECT_NEAR(eval("acos(0)"), 90, 1e-12);
    EXPECT_NEAR(eval("atan(1)"), 45, 1e-12);
    EXPECT_NEAR(eval("atan2(1, 1)"), 45, 1e-12);
    EXPECT_DOUBLE_EQ(eval("sqrt(16) + exp(0) + log(1)"), 5);
    EXPECT_DOUBLE_EQ(eval("abs(-3) + floor(2.7) + ceil(2.1)"), 8);
    EXPECT_DOUBLE_EQ(eval("min(3, 4) + max(3, 4)"), 7);
}

TEST(Expr, ParametersAndDefines) {
    EXPECT_DOUBLE_EQ(eval("x * 0.7 + y", {10, 1}, {"x", "y"}), 8);
    Compiled c = compile("r * 2", {}, {{"r", 1.5}});
    ASSERT_TRUE(c.expr);
    EXPECT_TRUE(c.expr->isConstant());  // defines fold at compile time
    EXPECT_DOUBLE_EQ(c.expr->constantValue(), 3);
}

TEST(Expr, ConstantSubtreesAreFolded) {
    Compiled c = compile("x * (2 + 3) * sin(90)", {"x"});
    ASSERT_TRUE(c.expr);
    EXPECT_EQ(c.expr->kind(), Expr::Kind::Program);
    EXPECT_EQ(compile("x", {"x"}).expr->kind(), Expr::Kind::Slot);
    EXPECT_EQ(compile("2 * 3 + 1").expr->kind(), Expr::Kind::Const);
}

TEST(Expr, RandomFunctionsAreSeeded) {
    Compiled c = compile("rand(2, 3)");
    ASSERT_TRUE(c.expr);
    EXPECT_FALSE(c.expr->isConstant());
    Rng a(42), b(42), other(43);
    double va = c.expr->eval(nullptr, a);
    EXPECT_EQ(va, c.expr->eval(nullptr, b));
    EXPECT_NE(va, c.expr->eval(nullptr, other));
    EXPECT_GE(va, 2);
    EXPECT_LT(va, 3);
    Compiled n = compile("normal(10, 2)");
    Rng r(7);
    double sum = 0, sq = 0;
    for (int i = 0; i < 20000; ++i) {
        double v = n.expr->eval(nullptr, r);
        sum += v;
        sq += v * v;
    }
    double mean = sum / 20000, sd = std::sqrt(sq / 20000 - mean * mean);
    EXPECT_NEAR(mean, 10, 0.1);
    EXPECT_NEAR(sd, 2, 0.1);
}

TEST(Expr, RngIsTheSameOnEveryMachine) {
    // SplitMix64 reference values: a standard library change cannot move them.
    Rng r(0);
    EXPECT_EQ(r.next(), 0xE220A8397B1DCDAFull);
    EXPECT_EQ(r.next(), 0x6E789E6AA1B965F4ull);
}

TEST(Expr, ErrorsHavePositionsAndSuggestions) {
    auto msg = [](const std::string& text, std::vector<std::string> params = {}) {
        Compiled c = compile(text, std::move(params));
        EXPECT_FALSE(c.expr) << text;
        return c.diags.empty() ? std::string("<none>")
                               : std::to_string(c.diags[0].col) + ": " + c.diags[0].message;
    };
    EXPECT_EQ(msg("sine(30)"), "1: unknown function 'sine' — did you mean 'sin'?");
    EXPECT_EQ(msg("x + lenght", {"x", "length"}), "5: unknown name 'lenght' — did you mean 'length'?");
    EXPECT_EQ(msg("1 +"), "4: expression ends too early: a value is missing");
    EXPECT_EQ(msg("(1 + 2"), "1: this '(' is never closed");
    EXPECT_EQ(msg("x = 1", {"x"}), "3: '=' is not a comparison: write '==' to test equality");
    EXPECT_EQ(msg("min(1)"), "1: 'min' takes 2 arguments, not 1");
    EXPECT_EQ(msg("1 $ 2"), "3: unexpected '$' in expression");
    EXPECT_EQ(msg(std::string(150, '(') + "1" + std::string(150, ')')).substr(0, 40),
              "102: expression is nested too deeply (mo");
}

}  // namespace
}  // namespace sprout::test
