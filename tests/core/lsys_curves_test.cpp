// A .lsys grammar's own functions and contours (core/language/lsys_curves.cpp): func() and @#
// give what cpfg's function and contour of the same points give; bad lines are errors at
// their place.
#include <gtest/gtest.h>

#include "core/derive/draw.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "test_util.hpp"

namespace sprout {
namespace {

TEST(LsysCurves, AFunctionIsCpfgsFunctionOfTheSamePoints) {
    ParseResult r = parse("n: 3\nfunction: len 0,0.2 0.5,1 1,0.2\naxiom: A(0)\nA(t) -> B(func(len, t/4), func(1, t/4)) A(t+1)\n");
    ASSERT_TRUE(r.ok()) << formatDiagnostic(r.diagnostics[0], "a.lsys");
    DeriveResult d = derive(r.grammar, 3, {});
    ASSERT_TRUE(d.outcome.ok());
    // cpfg's function through the same points, each end given three times.
    const CurveFunction f("len", {{0, 0.2}, {0, 0.2}, {0, 0.2}, {0.5, 1}, {1, 0.2}, {1, 0.2}, {1, 0.2}}, 0);
    ASSERT_EQ(d.string->params.size(), 7u);
    for (int t = 0; t < 3; ++t) {
        EXPECT_DOUBLE_EQ(d.string->params[size_t(2 * t)], f(t / 4.0)) << t;
        EXPECT_DOUBLE_EQ(d.string->params[size_t(2 * t + 1)], f(t / 4.0)) << "by number too";
    }
    EXPECT_NEAR(f(0), 0.2, 1e-3);
    EXPECT_NEAR(f(0.5), 1.0, 0.35) << "the curve passes near its middle point";
}

TEST(LsysCurves, AContourIsTheTubesSection) {
    ParseResult r = parse("n: 0\ncontour: 1 closed 1,0.3 1,-0.3 -1,-0.3 -1,0.3\naxiom: #(1) @#(1) @Gs F(1) @Ge\n");
    ASSERT_TRUE(r.ok()) << formatDiagnostic(r.diagnostics[0], "a.lsys");
    ASSERT_TRUE(r.grammar->curves);
    const auto section = r.grammar->curves->section(1, 8);
    ASSERT_EQ(section.size(), 9u);
    float wide = 0, thin = 0;
    for (const auto& p : section) wide = std::max(wide, std::fabs(p[1])), thin = std::max(thin, std::fabs(p[0]));
    EXPECT_GT(wide, 2 * thin) << "a flat section: x of the contour along the turtle's up";
}

TEST(LsysCurves, BadLinesAreErrorsAtTheirPlace) {
    struct Case {
        const char* text;
        int line, col;
        const char* says;
    } cases[] = {
        {"n: 1\nfunction: f 0,0 0.5\naxiom: F\n", 2, 17, "expected a point 'x,y'"},
        {"n: 1\nfunction: f 0.1,0 1,1\naxiom: F\n", 2, 13, "from x = 0 to x = 1"},
        {"n: 1\nfunction: f 0,0 0.6,1 0.4,1 1,0\naxiom: F\n", 2, 13, "in order"},
        {"n: 1\nfunction: 2f 0,0 1,1\naxiom: F\n", 2, 11, "a name"},
        {"n: 1\nfunction: f 0,0 1,1\nfunction: f 0,1 1,0\naxiom: F\n", 3, 11, "there already"},
        {"n: 1\ncontour: 0 1,1 2,2 3,3\naxiom: F\n", 2, 10, "a whole number from 1"},
        {"n: 1\ncontour: 1 open 1,1 2,2 3,3\naxiom: F\n", 2, 17, "at least 4 points"},
    };
    for (const Case& c : cases) {
        ParseResult r = parse(c.text);
        ASSERT_FALSE(r.ok()) << c.text;
        const Diagnostic& d = r.diagnostics[0];
        EXPECT_EQ(d.line, c.line) << c.text;
        EXPECT_EQ(d.col, c.col) << c.text << formatDiagnostic(d, "a.lsys");
        EXPECT_NE(d.message.find(c.says), std::string::npos) << d.message;
    }
}

}  // namespace
}  // namespace sprout
