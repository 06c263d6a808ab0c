// cpfg's curve files (a view file's `curve:` lines; core/language/vlab/curve_file.cpp): read as
// cpfg's CCurveXYZ reads them, curveX/Y/Z(id, t) and curveGAL(id) as cpfg computes them, in a
// grammar, and bad files.
//
// The expected numbers are cpfg's own, two ways that agree to the last digit: cpfg's
// curveXYZ.cpp (with point.cpp) compiled in /tmp with stand-ins for Message and
// Utils::Warning, and a driver printing CCurveXYZ(file, samples)'s _alength and
// calcAValue(0, t, 0, 0) with %.17g for the files below; and the reference cpfg
// (/work/cpfg-ref/bin/cpfg -g) run on an object whose view file names them and whose L-system's
// Start: block prints curveGAL(i), curveX(i, t), curveY(i, t), curveZ(i, t) with printf("%.17g").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "test_util.hpp"

namespace sprout {
namespace {

// [SECTION] Each kind of curve

// As cuspy writes a curve (`version: 1.4`, dimension 4: x y z multiplicity).
const char* kOpen =
    "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\nsize: 1\npoints: 5\nrange: 0.0 1.0\n"
    "dimension: 4\ntype: bspline\n0.100000 -0.500000 0 3\n0.400000 -0.200000 0.1 1\n0.300000 0.100000 0.2 2\n"
    "0.150000 0.300000 0 1\n0.000000 0.350000 0 3\n";

using P = std::array<double, 3>;

void expectPoint(const P& got, const P& want, const char* what) {
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-13) << what << ", coordinate " << c;
}

CurveXYZ curveOf(const std::string& text, int samples = 100) {
    CurveRead r = readCurve(text, "c.crv", samples);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].text());
    return r.curve;
}

TEST(VlabCurves, CuspysBSplineByItsLengthAsCpfg) {
    const CurveXYZ c = curveOf(kOpen);
    EXPECT_EQ(c.type(), CurveXYZ::Type::BSpline);
    EXPECT_EQ(c.points().size(), 10u);  // multiplicities 3, 1, 2, 1, 3
    EXPECT_NEAR(c.length(), 1.1747171881909684, 1e-13);
    expectPoint(c.at(0), {0.099999999999999992, -0.49999999999999994, 0}, "t 0");
    expectPoint(c.at(0.1), {0.18053039465359133, -0.41910226697997438, 0.026965911006675228}, "t 0.1");
    expectPoint(c.at(0.25), {0.28918777366879661, -0.2875766637110469, 0.070807778762984386}, "t 0.25");
    expectPoint(c.at(0.5), {0.33715786524041402, -0.020659522776242143, 0.15978015907458598}, "t 0.5");
    expectPoint(c.at(0.77), {0.20750058447372771, 0.21775491568265479, 0.084104297101470174}, "t 0.77");
    expectPoint(c.at(1), {2.5000000077096726e-20, 0.34999999999999998, 0}, "t 1");
    expectPoint(c.at(-3), c.at(0), "t -3 is 0");  // CurveCXS: "Parameter ... not defined, 0 used instead"
    expectPoint(c.at(7), c.at(1), "t 7 is 1");
    EXPECT_TRUE(std::isnan(c.at(std::nan(""))[0]));
    // Fewer samples measure it shorter and place t elsewhere (`curve: FILE 20`).
    const CurveXYZ twenty = curveOf(kOpen, 20);
    EXPECT_NEAR(twenty.length(), 1.1721241688297743, 1e-13);
    expectPoint(twenty.at(0.3), {0.31732697600782317, -0.23865102941562921, 0.08711632352812361}, "20 samples, t 0.3");
    expectPoint(twenty.at(0.6), {0.30397061944746567, 0.086525880426720048, 0.19384221482929853}, "20 samples, t 0.6");
}

TEST(VlabCurves, EveryTypeAsCpfg) {
    struct Case {
        const char* text;
        CurveXYZ::Type type;
        double length;
        P at25, at77;
    };
    const Case cases[] = {
        {"// a closed loop\npoints: 4\ndimension: 3\ntype: bspline-closed\n1 0 0\n0 1 0.5\n-1 0 0\n0 -1 -0.5\n",
         CurveXYZ::Type::Closed, 4.3770814752626181,
         {-0.66666666666575203, -9.5636804878229675e-07, -4.7818402439114838e-07},
         {0.66070709720446641, 0.078065282425158422, 0.039032641212579211}},
        {"points: 5\ndim: 2\ntype: bspline-endpoint\n0 0\n1 2\n2 -1\n3 1\n4 0\n", CurveXYZ::Type::Endpoint,
         4.9703198706623688, {0.74947219036877466, 0.96951926792779264, 0}, {2.9934940804363439, 0.4461823842690672, 0}},
        {"points: 4\ndimension: 3\ntype: bspline-phantom\n0 0 0\n1 1 0\n2 0 1\n3 1 1\n", CurveXYZ::Type::Phantom,
         3.7617476180017082, {0.71813201119840298, 0.59468186641070253, 0.061725072393850201},
         {2.3469345663322301, 0.43977749629969204, 0.95357853501626899}},
        {"points: 7\ndimension: 3\ntype: bezier\n0 0 0\n1 2 0\n2 2 0\n3 0 1\n4 -2 1\n5 -1 0\n6 0 0\n", CurveXYZ::Type::Bezier,
         8.7134031519140471, {1.4528484567775295, 1.498517821314493, 0.11357877625396171},
         {4.4768963576373606, -1.1305076511984802, 0.51155090768334022}},
        // A surface's row 0 at s = 0; curveX/Y/Z go through cpfg's scratch Bezier curves of 16
        // points (the rows, then 12 points of its grid), hence numbers far from the patch.
        {"points: 16\ndimension: 3\ntype: bezier-surface\n0 0 0\n0.5 0 0.252441\n1 0 0.272789\n1.5 0 0.042336\n"
         "0 0.4 -0.227041\n0.5 0.4 -0.287677\n1 0.4 -0.0838246\n1.5 0.4 0.197096\n0 0.8 0.296807\n0.5 0.8 0.123636\n"
         "1 0.8 -0.163206\n1.5 0.8 -0.299997\n0 1.2 -0.160972\n0.5 1.2 0.12605\n1 1.2 0.297182\n1.5 1.2 0.195086\n",
         CurveXYZ::Type::BezierSurface, 1.5569576979643178, {-0.212498419178488, -0.32457467240634824, 0.014853613338009688},
         {-1.4058260590492062, 1.4684964399031972, 0}},
    };
    for (const Case& k : cases) {
        SCOPED_TRACE(k.text);
        const CurveXYZ c = curveOf(k.text);
        EXPECT_EQ(c.type(), k.type);
        EXPECT_NEAR(c.length(), k.length, 1e-13);
        expectPoint(c.at(0.25), k.at25, "t 0.25");
        expectPoint(c.at(0.77), k.at77, "t 0.77");
    }
    // The end-point B-spline measured at 20 and at 2 samples.
    const char* endpoint = "points: 5\ndim: 2\ntype: bspline-endpoint\n0 0\n1 2\n2 -1\n3 1\n4 0\n";
    const CurveXYZ twenty = curveOf(endpoint, 20), two = curveOf(endpoint, 2);
    EXPECT_NEAR(twenty.length(), 4.9577398038755662, 1e-13);
    expectPoint(twenty.at(0.25), {0.75661304696663356, 0.97307670056060924, 0}, "20 samples");
    EXPECT_NEAR(two.length(), 3.9999970000026246, 1e-13);
    expectPoint(two.at(0.3), {1.3679994779999458, 0.84600044099982452, 0}, "2 samples");
}

// `points:` after a point begins that point's own curve (cpfg keeps it for its editor): the
// curve is the one without it.
TEST(VlabCurves, ThePointsOfAPointsCurveAreKeptAside) {
    const CurveXYZ nested = curveOf("points: 3\ndimension: 4\n0 0 0 2\npoints: 2\ndimension: 4\n5 5 0 1\n6 6 0 1\n1 1 0 1\n2 0 0 2\n");
    const CurveXYZ flat = curveOf("points: 3\ndimension: 4\n0 0 0 2\n1 1 0 1\n2 0 0 2\n");
    EXPECT_EQ(nested.points(), flat.points());
    EXPECT_NEAR(flat.length(), 1.9912036185060844, 1e-13);
    expectPoint(nested.at(0.5), {0.99999964649074791, 0.66666666666654173, 0}, "t 0.5");
}

// [SECTION] Files cut short, wrong or missing

std::string firstProblem(const CurveRead& r) { return r.diagnostics.empty() ? "" : r.diagnostics[0].text(); }

TEST(VlabCurves, BadFilesSayWhereAndWhatWasExpected) {
    // Cut after 3 of its 5 points: cpfg's curve has the other two at 0, 0, 0.
    std::string cut = kOpen;
    cut.erase(cut.find("0.150000"));
    CurveRead r = readCurve(cut, "cut.crv", 100);
    EXPECT_EQ(firstProblem(r), "cut.crv:7:1: the file ends after 3 of the 5 points this line declares");
    EXPECT_NEAR(r.curve.length(), 1.0180334871169618, 1e-13);
    expectPoint(r.curve.at(0.25), {0.26750578017116505, -0.31854536931181737, 0.060484876896060885}, "cut, t 0.25");
    // A point of 3 numbers where the dimension is 4: reading stops there, as cpfg's does.
    std::string wrong = kOpen;
    wrong.replace(wrong.find("0.2 2\n"), 6, "0.2\n");
    r = readCurve(wrong, "w.crv", 100);
    EXPECT_EQ(firstProblem(r), "w.crv:13:1: expected a point of 4 numbers here (x y, x y z or x y z multiplicity, as "
                               "'dimension:' says)");
    EXPECT_NEAR(r.curve.length(), 0.72901011310651687, 1e-13);
    expectPoint(r.curve.at(0.77), {0.14537975408927753, -0.075167932297302439, 0.036207268786060287}, "stopped, t 0.77");

    auto problem = [](const std::string& text) { return firstProblem(readCurve(text, "c.crv", 100)); };
    EXPECT_EQ(problem(""), "c.crv: the file is empty (a curve file: 'points: N', 'dimension: 4', 'type: bspline', then "
                           "the points, as cuspy writes them)");
    EXPECT_EQ(problem("fver 1 1\nname: rho\n"), "c.crv:1:1: expected 'points: N' before the first point");
    EXPECT_EQ(problem("version: 1.4\nrange: 0 1\n"), "c.crv: the file has no 'points: N' line (a curve file: 'points: N', "
                                                     "'dimension: 4', 'type: bspline', then the points, as cuspy writes them)");
    EXPECT_EQ(problem("points: 4\n0 0\n1 x\n"), "c.crv:3:3: expected a number here, not 'x'");
    EXPECT_EQ(problem("points: 1\n0 0\n1 1\n"), "c.crv:3:1: more points than the 'points: N' of line 1 declares");
    EXPECT_EQ(problem("points: four\n"), "c.crv:1:9: expected the number of points after 'points:' (0 to 100000)");
    EXPECT_EQ(problem("points: 2\ndimension: 5\n"),
              "c.crv:2:12: expected the numbers a point has after 'dimension:' (2: x y, 3: x y z, 4: x y z multiplicity)");
    EXPECT_EQ(problem("type: bezier\npoints: 2\n"), "c.crv:1:1: expected 'points: N' before 'type:' (it concerns the curve read last)");
    EXPECT_EQ(problem("points: 2\ndimension: 4\n0 0 0 -1\n"),
              "c.crv:3:7: expected the point's multiplicity here (a whole number from 0 to 1000)");
    EXPECT_EQ(problem("contact: 0 0\n"), "c.crv:1:13: expected three numbers after 'contact:'");
    EXPECT_EQ(problem("points: 2\npoints: 2\n"),
              "c.crv:2:1: expected a point before a second 'points:' (cpfg makes it the curve of the point before it)");
    // What cpfg passes over: comments, other labels, lines of two characters; no newline at the end.
    EXPECT_EQ(problem("// c\nname: x\nxy\npoints: 4\n0 0\n\n1 1\r\n2 0\n3 1"), "");

    // A file that cannot be read: cpfg keeps the grid's Bezier surface it starts with.
    r = loadCurve("/nonexistent/c.crv", 100);
    EXPECT_EQ(firstProblem(r), "/nonexistent/c.crv: cannot read the file: No such file or directory");
    EXPECT_EQ(r.curve.type(), CurveXYZ::Type::BezierSurface);
    EXPECT_NEAR(r.curve.length(), 3, 1e-13);
    expectPoint(r.curve.at(0.25), {0.79040446277601484, -1.2557618992415744, 0}, "missing, t 0.25");
    expectPoint(r.curve.at(0.77), {-1.0625800562459471, 1.3515192024575076, 0}, "missing, t 0.77");
}

// [SECTION] In a grammar: curveX, curveY, curveZ, curveGAL

ParseResult parseWith(const std::string& text, std::shared_ptr<const CurveTables> tables) {
    ParseOptions o = parseOptionsFor(FileKind::Cpfg, "plant.l");
    o.curves = std::move(tables);
    return parse(text, o);
}

std::shared_ptr<const CurveTables> openTables() {
    auto t = std::make_shared<CurveTables>();
    t->curves.push_back(curveOf(kOpen));
    return t;
}

TEST(VlabCurves, CurveCallsInAGrammarGiveCpfgsNumbers) {
    const std::shared_ptr<const CurveTables> t = openTables();
    EXPECT_EQ(t->call(CurveCall::CurveLength, 1.7, 0), t->curves[0].length());  // (int)id, as cpfg
    EXPECT_EQ(t->call(CurveCall::CurveX, 2, 0.5), 0.0);                        // no curve 2: 0, as cpfg
    EXPECT_EQ(t->call(CurveCall::CurveY, 0, 0.5), 0.0);
    ParseResult r = parseWith("Lsystem: 1\nStart: {L = curveGAL(1);}\nderivation length: 2\nAxiom: A(0.25)\n"
                              "A(t) --> B(curveX(1, t), curveY(1, t), curveZ(1, t), L) A(t + 0.5)\nendlsystem\n",
                              t);
    ASSERT_TRUE(r.ok()) << formatDiagnostic(r.diagnostics[0], "plant.l");
    DeriveResult d = derive(r.grammar, 2, {});
    ASSERT_TRUE(d.outcome.ok());
    ASSERT_EQ(d.string->params.size(), 9u);
    const double want[2][3] = {{0.28918777366879661, -0.2875766637110469, 0.070807778762984386},
                               {0.21997157237832343, 0.20330086057981761, 0.09783370928098839}};  // t 0.75
    for (size_t i = 0; i < 2; ++i) {  // cpfg's string keeps them as floats
        for (size_t c = 0; c < 3; ++c) EXPECT_EQ(d.string->params[4 * i + c], double(float(want[i][c]))) << i << " " << c;
        EXPECT_EQ(d.string->params[4 * i + 3], double(float(1.1747171881909684)));
    }
}

TEST(VlabCurves, CurveCallMistakesAreNamedAtTheirColumn) {
    auto first = [](const ParseResult& r) { return r.diagnostics.empty() ? "" : formatDiagnostic(r.diagnostics[0], "plant.l"); };
    const char* calls = "Lsystem: 1\nAxiom: A(0)\nA(t) --> B(CALL) A(t+1)\nendlsystem\n";
    auto with = [&](const std::string& call, std::shared_ptr<const CurveTables> t) {
        std::string text = calls;
        text.replace(text.find("CALL"), 4, call);
        return parseWith(text, std::move(t));
    };
    EXPECT_EQ(first(with("curveX(1, t)", nullptr)),
              "plant.l:3:12: curveX() needs cpfg's curves: the view file's 'curve:' lines (open the VLab object's folder)");
    EXPECT_EQ(first(with("curveY(1)", openTables())), "plant.l:3:12: 'curveY' takes 2 arguments (a curve and t in [0, 1]), not 1");
    EXPECT_EQ(first(with("curveGAL(1, t)", openTables())), "plant.l:3:12: 'curveGAL' takes 1 argument (a curve), not 2");
    const ParseResult far = with("curveZ(2, t)", openTables());
    EXPECT_TRUE(far.ok());
    EXPECT_EQ(first(far), "plant.l:3:12: warning: curveZ(2, ...): there is 1 curve (numbered from 1): it gives 0, as in cpfg");
    EXPECT_EQ(first(with("curveGAL(0)", std::make_shared<CurveTables>())),
              "plant.l:3:12: warning: curveGAL(0): there are 0 curves (numbered from 1): it gives 0, as in cpfg");
    EXPECT_EQ(first(with("curvX(1, t)", openTables())), "plant.l:3:12: unknown function 'curvX' — did you mean 'curveX'?");
}

// [SECTION] The corpus: Ridley's receptacle (11-CPFG/Ridley/profile.con, cuspy's curve)

TEST(VlabCurves, RidleysProfileAsCpfg) {
    const std::filesystem::path file =
        std::filesystem::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals" / "11-CPFG" / "Ridley" / "profile.con";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not here";
    const CurveRead r = loadCurve(file, 100);
    ASSERT_TRUE(r.ok()) << firstProblem(r);
    EXPECT_NEAR(r.curve.length(), 0.77942911923303348, 1e-13);
    expectPoint(r.curve.at(0.25), {0.26886004930157281, -0.25293667413432896, 0}, "t 0.25");
    expectPoint(r.curve.at(0.5), {0.24338786696744849, -0.060037718458706701, 0}, "t 0.5");
    expectPoint(r.curve.at(1), {-0.0014779999999999997, 0.20247499999999996, 0}, "t 1");
}

}  // namespace
}  // namespace sprout
