// Every error path of the parser: position (line:col) and a message a student can act on.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace sprout::test {
namespace {

// The first diagnostic of `text`, as "line:col: message".
std::string firstError(const std::string& text) {
    auto r = parse(text);
    EXPECT_FALSE(r.ok()) << text;
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error)
            return std::to_string(d.line) + ":" + std::to_string(d.col) + ": " + d.message;
    return "<no error>";
}

struct Case {
    const char* text;
    const char* expected;
};

TEST(Errors, EachMistakeHasAPositionAndAMessage) {
    const Case cases[] = {
        {"axiom: F\nF -> F(\n", "2:7: this '(' is never closed"},
        {"axiom: F\nF -> F)\n", "2:7: ')' has no matching '('"},
        {"anlge: 30\naxiom: F\n", "1:1: unknown setting 'anlge' — did you mean 'angle'?"},
        {"F -> FF\n", "1:1: the grammar has no axiom: add a line such as 'axiom: F'"},
        {"axiom: F\nF FF\n", "2:1: expected a rule such as 'F -> F+F' or a setting such as 'angle: 90'"},
        {"axiom: F\nAB -> C\n", "2:1: a rule rewrites one module, but 'AB' is 2 modules; declare it first with 'module: AB'"},
        {"axiom: F\nA+ -> C\n", "2:1: a rule rewrites one module, but 'A+' is 2 modules; use contexts for neighbours, as in 'A < B > C -> ...'"},
        {"axiom: F\n -> F\n", "2:1: the rule has no module to rewrite before '->'"},
        {"axiom: F\nA(x,x) -> B\n", "2:5: parameter 'x' is named twice in this rule"},
        {"axiom: F\nA(1) -> B\n", "2:3: a rule's left side names its parameters, e.g. A(x, y); compute values on the right side or in the condition"},
        {"axiom: F\nA(x) -> F(sine(x))\n", "2:11: unknown function 'sine' — did you mean 'sin'?"},
        {"axiom: F\nA(len) -> F(lne)\n", "2:13: unknown name 'lne' — did you mean 'len'?"},
        {"axiom: F\nA(x) -> F(y)\n", "2:11: unknown name 'y': not a parameter of this rule or a defined constant"},
        {"axiom: F\nA(x) : -> F\n", "2:7: expected a condition after ':' (e.g. 'A(t) : t > 1 -> F')"},
        {"axiom: F]\n", "1:9: ']' closes a branch that was never opened with '['"},
        {"axiom: F\nF -> [F[+F]\n", "2:6: this '[' is never closed with ']'"},
        {"n: -1\naxiom: F\n", "1:4: n must be a whole number from 0 to 10000"},
        {"n: 2.5\naxiom: F\n", "1:4: n must be a whole number from 0 to 10000"},
        {"iterations: 100000\naxiom: F\n", "1:13: iterations must be a whole number from 0 to 10000"},
        {"define: 3x = 2\naxiom: F\n", "1:9: expected 'define: name = value', with a name made of letters, digits and _"},
        {"define: x\naxiom: F\n", "1:10: 'x' needs a value: define: x = 1.5"},
        {"define: x = 1\ndefine: x = 2\naxiom: F\n", "2:9: 'x' is defined twice"},
        {"axiom: F\naxiom: G\n", "2:8: a second axiom (the first is on line 1)"},
        {"axiom: F\nF -> [(2)F]\n", "2:6: '[' takes no parameters"},
        {"seed: abc\naxiom: F\n", "1:7: the seed must be a whole number such as 'seed: 42'"},
        {"axiom: F\n< F -> G\n", "2:1: '<' needs a left context before it (or '*' for any)"},
        {"axiom: F\nF > -> G\n", "2:3: '>' needs a right context after it (or '*' for any)"},
        {"axiom: F\nF -> F : -0.5\n", "2:10: a probability cannot be negative"},
        {"axiom: F\ninterpretation: F\n", "2:17: 'interpretation:' starts a section; put its rules on the next lines"},
        {"axiom: F\n* -> F\n", "2:1: '*' (any module) can only be used in a context"},
        {"axiom: F\n[A < B -> C\n", "2:1: brackets are not allowed here: a left context is followed back through parent branches automatically"},
        {"angle: 20 ~ -1\naxiom: F\n", "1:12: the spread after '~' cannot be negative"},
        {"axiom:\n", "1:7: the axiom is empty: write the starting string, e.g. 'axiom: F'"},
        {"axiom: F\nF(x) : x > 1 -> F(x = 1)\n", "2:21: '=' is not a comparison: write '==' to test equality"},
        {"axiom: F\nignore: F(1)\n", "2:9: list only module names after 'ignore:', without parameters"},
        {"axiom: F\ninterpretation:\n[ -> +F\n", "3:6: a rule for '[' must keep one unmatched '['"},
        {"axiom: A(1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,26,27,28,29,30,31,32,33)\n",
         "1:8: a module can have at most 32 parameters"},
        {"axiom: F\nF -> F\n\nG(x) -> G(max(x, 1)\n", "4:10: this '(' is never closed"},
    };
    for (const Case& c : cases) EXPECT_EQ(firstError(c.text), c.expected) << c.text;
}

TEST(Errors, DeepNestingIsAnErrorNotAStackOverflow) {
    std::string deep = "axiom: F\nA(x) -> F(" + std::string(100000, '(') + "x" + std::string(100000, ')') + ")\n";
    EXPECT_EQ(firstError(deep), "2:112: expression is nested too deeply (more than 100 levels)");
}

TEST(Errors, AllErrorsOfAFileAreReported) {
    auto r = parse("anlge: 30\naxiom: F\nF -> F(sine(2))\nG -> [G\n");
    ASSERT_FALSE(r.ok());
    std::vector<std::string> got;
    for (const auto& d : r.diagnostics) got.push_back(std::to_string(d.line) + ":" + std::to_string(d.col));
    EXPECT_EQ(got, (std::vector<std::string>{"1:1", "3:8", "4:6"}));
}

TEST(Errors, ColumnsCountCharactersNotBytes) {
    // '→' is three bytes but one column.
    EXPECT_EQ(firstError("axiom: F\nF \xE2\x86\x92 F(sine(2))\n"), "2:7: unknown function 'sine' — did you mean 'sin'?");
}

TEST(Errors, FormattedLikeACompiler) {
    Diagnostic d{4, 12, "unknown function 'sine' — did you mean 'sin'?"};
    EXPECT_EQ(formatDiagnostic(d, "plant.lsys"), "plant.lsys:4:12: unknown function 'sine' — did you mean 'sin'?");
    d.severity = Severity::Warning;
    EXPECT_EQ(formatDiagnostic(d, "plant.lsys"), "plant.lsys:4:12: warning: unknown function 'sine' — did you mean 'sin'?");
}

TEST(Errors, BinaryGarbageIsAnErrorNotACrash) {
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage += char((i * 7919) % 256);
    auto r = parse(garbage);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.diagnostics.empty());
}

}  // namespace
}  // namespace sprout::test
