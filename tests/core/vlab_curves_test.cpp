// cpfg's function and contour files (core/language/vlab/): read in every format, evaluated and
// sampled as cpfg does, func() in a grammar, a contour drawn by @#, bad files, the corpus.
//
// The expected numbers come from cpfg's own code: SplineFunction's evaluation (GetValue, _Value,
// _Precompute, P, N, Nk1, Nkt, Uk, copied by sed from cpfg/splinefun.cpp) and MakeContour with
// evaluate_spline (from cpfg/general.c), compiled in /tmp with minimal stand-ins for their
// globals and run on the points of the files below (printed with %.17g and %.9g).
#include <gtest/gtest.h>

#include <filesystem>
#include <glm/geometric.hpp>

#include "core/derive/draw.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "test_util.hpp"

namespace sprout {
namespace {

const char* kGrowth =
    "fver 1 1\nname: growth\nsamples: 100\nflip: off\npoints: 5\n"
    "0.000000 0.100000 2\n0.300000 0.800000 1\n0.700000 0.900000 1\n0.900000 0.300000 1\n1.000000 0.500000 2\n";
const double kXs[] = {-0.5, 0, 0.1, 0.25, 0.333, 0.5, 0.77, 0.999, 1, 2};

void expectValues(const CurveFunction& f, const double (&want)[10]) {
    for (size_t i = 0; i < 10; ++i) EXPECT_NEAR(f(kXs[i]), want[i], 1e-12) << "x = " << kXs[i];
}

TEST(VlabFunctions, TableOfSamplesAsCpfg) {
    FunctionRead r = readFunction(kGrowth, "growth.func", 7);  // fver 1 1: its own samples, not the view's
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].text();
    EXPECT_EQ(r.function.name(), "growth");
    EXPECT_EQ(r.function.samples(), 100);
    EXPECT_EQ(r.function.points().size(), 7u);  // multiplicities 2, 1, 1, 1, 2
    expectValues(r.function, {0.10100987902776146, 0.10100987902776146, 0.31268034598129602, 0.58014805231323263,
                              0.69294556360502146, 0.8172656445635138, 0.6476871222914401, 0.49720043809411291,
                              0.49888916022246121, 0.49888916022246121});
}

TEST(VlabFunctions, NoTableIsTheCurveByBisection) {
    std::string text = kGrowth;
    text.replace(text.find("samples: 100"), 12, "samples: 0");
    FunctionRead r = readFunction(text, "growth.func", 100);
    ASSERT_TRUE(r.ok());
    expectValues(r.function, {0.10100987902776146, 0.10100987902776146, 0.3147835491353369, 0.5814577963252151,
                              0.69332786466546448, 0.81757522632915669, 0.64816588584727708, 0.49888916022246121,
                              0.49888916022246121, 0.49888916022246121});
}

TEST(VlabFunctions, FirstFormatTakesTheViewFilesSamples) {
    const char* text = "range: 0.0 1.0\npoints: 4\n0 0\n0.2 1\n0.8 1\n1 0\n";
    FunctionRead ten = readFunction(text, "dir/bump.func", 10), none = readFunction(text, "bump.func", -1);
    ASSERT_TRUE(ten.ok() && none.ok());
    EXPECT_EQ(ten.function.name(), "bump");
    expectValues(ten.function, {0.0029268264770507812, 0.0029268264770507812, 0.33786478042602541, 0.60531520843505859,
                                0.69033239364624022, 0.743408203125, 0.5848291397094727, 0.0062762060165406537,
                                0.0029268264770507812, 0.0029268264770507812});
    expectValues(none.function, {0.0029268264770507812, 0.0029268264770507812, 0.34981155395507812, 0.6115264892578125,
                                 0.690673828125, 0.75, 0.585205078125, 0.005847930908203125, 0.0029268264770507812,
                                 0.0029268264770507812});
}

TEST(VlabFunctions, SetNamesItsFunctions) {
    const std::string set = std::string("funcgalleryver 1 1\nitems: 2\n") + kGrowth +
                            "fver 1 1\nname: flat\nsamples: 10\nbackground: x.png\nbackgroundXY: 0 0\nflip: on\n"
                            "points: 4\n0 2\n0.3 2\n0.6 2\n1 2\n";
    FunctionSetRead r = readFunctionSet(set, "functions.fset");
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].text();
    ASSERT_EQ(r.functions.size(), 2u);
    CurveTables t;
    t.addFunction(readFunction(kGrowth, "growth.func", 100).function);
    t.setFunctionSet(r.functions);  // cpfg: a function set replaces the functions before it
    EXPECT_EQ(t.functionId("flat"), 2);
    EXPECT_EQ(t.functionId("growth"), 1);
    EXPECT_EQ(t.functionId("other"), 0);
    EXPECT_NEAR(t.func(2, 0.4), 2.0, 1e-12);
    EXPECT_NEAR(t.func(1.9, 0.5), 0.8172656445635138, 1e-12);  // (int)id, as cpfg
    EXPECT_EQ(t.func(3, 0.5), 0.0);                              // out of range: 0, as cpfg
    EXPECT_EQ(t.func(0, 0.5), 0.0);
    t.addFunction(CurveFunction());  // a later `function:` line: the names are no longer defined
    EXPECT_EQ(t.functionId("flat"), 0);
}

// [SECTION] Contours

void expectPoints(const std::vector<std::array<float, 3>>& got, const std::vector<std::array<float, 3>>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i)
        for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(got[i][c], want[i][c], 2e-6f) << "point " << i << " coordinate " << c;
}

TEST(VlabContours, OpenContourSampledAsCpfg) {
    ContourRead r = readContour("cver 1 3\nname: blade\npoints: 5 9\ntype: or\nsamples: 8\n-2.0 3.0 0.0 3\n"
                                "-1.0 4.0 0.0 1\n0.0 4.5 0.5 1\n1.5 4.0 0.0 1\n2.0 3.0 0.0 3\n",
                                "blade.con");
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].text();
    EXPECT_FALSE(r.contour->closed);
    EXPECT_EQ(r.contour->points.size(), 9u);
    expectPoints(r.contour->sampled(8), {{-2, 3, 0}, {-1.55332446f, 3.44080687f, 0.00586862676f},
                                         {-1.08061802f, 3.85464096f, 0.0647414923f}, {-0.552359164f, 4.19141674f, 0.220605284f},
                                         {0.0543442369f, 4.33306313f, 0.333065063f}, {0.673276842f, 4.23979807f, 0.254954755f},
                                         {1.24304867f, 3.97975135f, 0.106721744f}, {1.69328856f, 3.54635787f, 0.013413094f},
                                         {1.99991667f, 3.00016665f, 0}});
}

TEST(VlabContours, ClosedContourTurnedToTheXAxis) {
    ContourRead r = readContour("cver 1 1\nname: c\npoints: 5 5\ntype: closed\n1 0 0 1\n0 1 0 1\n-1 0 0 1\n0 -2 0 1\n"
                                "0.5 -1 0.3 1\n",
                                "c.con");
    ASSERT_TRUE(r.ok());
    expectPoints(r.contour->sampled(8), {{0.666666687f, 0, 0}, {0.288419247f, 0.559261739f, 0},
                                         {-0.402508289f, 0.645259917f, 0.000172651649f}, {-1.07132816f, 0.413379937f, 0.00963205658f},
                                         {-1.54269803f, -0.0706470981f, 0.0887203217f}, {-1.0036962f, -0.498151898f, 0.19999592f},
                                         {-0.346082032f, -0.757053792f, 0.113660544f}, {0.321333617f, -0.592333019f, 0.0147888809f},
                                         {0.666666687f, 0, 0}});
    // The first format, 2D: `points dimension closed`, the numbers read across lines.
    ContourRead old = readContour("4 2 closed\n1 0\n0 1 -1\n0\n0 -1\n", "old.con");
    ASSERT_TRUE(old.ok()) << old.diagnostics[0].text();
    EXPECT_EQ(old.contour->name, "old");
    expectPoints(old.contour->sampled(5), {{0.666666687f, 0, 0}, {0.201655447f, 0.627694786f, 0},
                                           {-0.526375175f, 0.380791694f, 0}, {-0.526374698f, -0.38079226f, 0},
                                           {0.201656073f, -0.627694607f, 0}, {0.666666687f, 0, 0}});
}

TEST(VlabContours, SetReadsEachContour) {
    ContourSetRead r = readContourSet("contourgalleryver 1 1\nitems: 2\n cver 1 1\nname: square\npoints: 4 4\ntype: closed\n"
                                      "0.4 0.4 0.0 1\n0.4 -0.4 0.0 1\n-0.4 -0.4 0.0 1\n-0.4 0.4 0.0 1\n"
                                      "cver 1 2\nname: edge\npoints: 2 4\ntype: or\n0 0 0 2\n1 0 0 2\n",
                                      "shapes.cset");
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].text();
    ASSERT_EQ(r.contours.size(), 2u);
    EXPECT_EQ(r.contours[0].name, "square");
    EXPECT_TRUE(r.contours[0].closed);
    EXPECT_EQ(r.contours[1].name, "edge");
    EXPECT_FALSE(r.contours[1].closed);
    // cpfg's MakeContour on the square at 6 sides: its first point turned onto the x axis.
    expectPoints(r.contours[0].sampled(6), {{0.377123624f, 0, 0}, {0.183429345f, -0.320089698f, 0},
                                            {-0.183429152f, -0.320089787f, 0}, {-0.377123624f, -1.1920929e-07f, 0},
                                            {-0.183429077f, 0.320089817f, 0}, {0.183429182f, 0.320089757f, 0},
                                            {0.377123624f, 0, 0}});
}

// [SECTION] Bad files

std::string firstProblem(const std::vector<CurveFileDiagnostic>& d) { return d.empty() ? "" : d[0].text(); }

TEST(VlabFiles, BadFilesSayWhereAndWhatWasExpected) {
    EXPECT_EQ(firstProblem(readFunction("fver 1 1\nname: f\nsamples: 10\nflip: off\npoints: 5\n0 0\n0.5 1\n", "f.func", 1).diagnostics),
              "f.func:8:1: the file ends after 2 of its 5 points (expected 'x y [multiplicity]')");
    EXPECT_EQ(firstProblem(readFunction("fver 1 1\nname: f\nsamples: ten\n", "f.func", 1).diagnostics),
              "f.func:3:10: expected SAMPLES after 'samples:' (a whole number from -1000000 to 10000)");
    EXPECT_EQ(firstProblem(readFunction("fver 2 0\n", "f.func", 1).diagnostics),
              "f.func:1:6: unsupported function format 2.0 (cpfg reads 'fver 1 1')");
    EXPECT_EQ(firstProblem(readFunction("\x7f" "ELF\x01\x02", "f.func", 1).diagnostics),
              "f.func:1:1: expected 'fver 1 1' or 'range: 0 1' (the first line of a function)");
    EXPECT_EQ(firstProblem(readFunction("fver 1 1\nname: f\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.5 x\n", "f.func", 1).diagnostics),
              "f.func:7:5: expected a number here, not 'x'");
    EXPECT_EQ(firstProblem(readFunction("range: 0 1\npoints: 3\n0 0\n0.5 1\n1 0\n", "f.func", 1).diagnostics),
              "f.func:2:1: a function needs at least 4 points (cpfg: 'not enough points specified')");
    // A file that cannot be read gives cpfg's default: 0 everywhere.
    FunctionRead missing = loadFunction("/nonexistent/f.func", 10);
    EXPECT_FALSE(missing.ok());
    EXPECT_EQ(firstProblem(missing.diagnostics), "/nonexistent/f.func: cannot read the file: No such file or directory");
    EXPECT_EQ(missing.function(0.5), 0.0);
    EXPECT_EQ(firstProblem(readFunctionSet("funcgalleryver 1 1\nitems: 2\nfver 1 1\n", "s.fset").diagnostics),
              "s.fset:4:1: the file ends where 'name: NAME' was expected");

    EXPECT_EQ(firstProblem(readContour("cver 1 3\nname: c\npoints: 2 2\ntype: xr\n", "c.con").diagnostics),
              "c.con:4:7: expected the contour's type after 'type:': or, oe, cr or ce (open or closed, regular or end-point "
              "interpolating)");
    EXPECT_EQ(firstProblem(readContour("cver 1 2\nname: c\npoints: 4 4\ntype: cr\n0 0 0 1\n1 0 0 1\n1 1\n", "c.con").diagnostics),
              "c.con:8:1: the file ends where z of point 3 ('x y z multiplicity') was expected");
    EXPECT_EQ(firstProblem(readContour("cver 1 2\nname: c\npoints: 2 2\ntype: or\n0 0 0 1\n1 0 0 1\n", "c.con").diagnostics),
              "c.con:3:1: an open contour needs at least 4 points");
    EXPECT_EQ(firstProblem(readContour("version: 1.4\ncontact: 0 0 0\n", "p.con").diagnostics),
              "p.con:1:1: this is a curve file ('version:'; cpfg reads it for a view file's 'curve:' line and curveX/Y/Z), "
              "not a contour ('cver 1 3')");
    EXPECT_EQ(firstProblem(readContour("", "e.con").diagnostics),
              "e.con:1:1: the file ends where a contour ('cver 1 3') was expected");
    // Multiplicities that do not add up: read as they add up, with a warning.
    ContourRead loose = readContour("cver 1 2\nname: c\npoints: 3 5\ntype: cr\n0 0 0 1\n1 0 0 1\n1 1 0 1\n", "c.con");
    EXPECT_TRUE(loose.ok());
    EXPECT_EQ(firstProblem(loose.diagnostics),
              "c.con:3:11: warning: the multiplicities add up to 3, not 5 (the points are used as they add up)");
}

// [SECTION] The language: func() and @#

std::shared_ptr<const CurveTables> growthTables() {
    auto t = std::make_shared<CurveTables>();
    FunctionSetRead set = readFunctionSet(std::string("funcgalleryver 1 1\nitems: 1\n") + kGrowth, "f.fset");
    t->setFunctionSet(set.functions);
    ContourRead c = readContour("cver 1 1\nname: c\npoints: 5 5\ntype: closed\n1 0 0 1\n0 1 0 1\n-1 0 0 1\n0 -2 0 1\n"
                                "0.5 -1 0.3 1\n",
                                "c.con");
    t->contours.emplace(1, *c.contour);
    return t;
}

ParseResult parseWith(const std::string& text, std::shared_ptr<const CurveTables> tables) {
    ParseOptions o = parseOptionsFor(FileKind::Cpfg, "plant.l");
    o.curves = std::move(tables);
    return parse(text, o);
}

TEST(VlabLanguage, FuncInAGrammarGivesCpfgsNumbers) {
    ParseResult r = parseWith("#define SCALE 2\nLsystem: 1\nderivation length: 4\nAxiom: A(0)\n"
                              "A(t) --> B(SCALE*func(growth, t/4), func(1, 0.1)) A(t+1)\nendlsystem\n",
                              growthTables());
    ASSERT_TRUE(r.ok()) << formatDiagnostic(r.diagnostics[0], "plant.l");
    DeriveResult d = derive(r.grammar, 4, {});
    ASSERT_TRUE(d.outcome.ok());
    const double want[] = {0.10100987902776146, 0.58014805231323263, 0.8172656445635138, 0.68142352778135584};
    ASSERT_EQ(d.string->params.size(), 9u);
    for (size_t i = 0; i < 4; ++i) {  // cpfg's string keeps them as floats
        EXPECT_EQ(d.string->params[2 * i], double(float(2 * want[i]))) << i;
        EXPECT_EQ(d.string->params[2 * i + 1], double(float(0.31268034598129602))) << i;
    }
}

TEST(VlabLanguage, FuncMistakesAreNamedAtTheirColumn) {
    ParseResult r = parseWith("Lsystem: 1\nAxiom: A(0)\nA(t) --> B(func(growht, t)) A(t+1)\nendlsystem\n", growthTables());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(formatDiagnostic(r.diagnostics[0], "plant.l"), "plant.l:3:17: unknown function 'growht' in func() — did you mean 'growth'?");
    ParseResult none = parseWith("Lsystem: 1\nAxiom: A(0)\nA(t) --> B(func(1, t)) A(t+1)\nendlsystem\n", nullptr);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(formatDiagnostic(none.diagnostics[0], "plant.l"),
              "plant.l:3:12: func() needs cpfg's functions: the view file's 'function:' or 'function set:' lines (open the "
              "VLab object's folder)");
    ParseResult far = parseWith("Lsystem: 1\nAxiom: A(0)\nA(t) --> B(func(3, t)) A(t+1)\nendlsystem\n", growthTables());
    ASSERT_TRUE(far.ok());
    EXPECT_EQ(formatDiagnostic(far.diagnostics[0], "plant.l"),
              "plant.l:3:12: warning: func(3, ...): there is 1 function (numbered from 1): it gives 0, as in cpfg");
}

// @#(1) selects the view file's contour 1 for the tube: its first ring is cpfg's contour points,
// x along the turtle's up and y along its right (cpfg/general.c's make_contour), at the radius.
TEST(VlabLanguage, ContourIsTheTubesCrossSection) {
    ParseResult r = parseWith("Lsystem: 1\nderivation length: 0\nAxiom: #(2) @#(1) @Gs F(1) @Ge\nendlsystem\n", growthTables());
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    EXPECT_EQ(g.cylinders.size(), 0u);
    const std::array<float, 2> cpfg[8] = {{0.666666687f, 0}, {0.288419247f, 0.559261739f}, {-0.402508289f, 0.645259917f},
                                          {-1.07132816f, 0.413379937f}, {-1.54269803f, -0.0706470981f},
                                          {-1.0036962f, -0.498151898f}, {-0.346082032f, -0.757053792f},
                                          {0.321333617f, -0.592333019f}};
    ASSERT_GE(g.polygons.positions.size(), 16u);
    // The turtle starts at the origin heading up +y with its up +z and its left -x: up * x - left * y.
    for (size_t k = 0; k < 8; ++k) {
        const glm::vec3 want(cpfg[k][1], 0, cpfg[k][0]);
        EXPECT_NEAR(glm::length(g.polygons.positions[k] - want), 0.0f, 1e-5f) << "ring point " << k;
    }
    // @!(5): the turtle's sides for the contours chosen after it (cpfg's MakeContour at 5 sides);
    // in a branch only: after it, `contour sides:` (8) again.
    ParseResult five = parseWith("Lsystem: 1\nderivation length: 0\nAxiom: [@!(5) @#(1) #(2) @Gs F(1) @Ge] @#(1) #(2) @Gs F(1) @Ge\nendlsystem\n",
                                 growthTables());
    ASSERT_TRUE(five.ok());
    Geometry g5;
    interpret(five.grammar->axiom, *five.grammar, {0, 1, nullptr}, g5);
    const std::array<float, 2> cpfg5[5] = {{0.666666687f, 0}, {-0.119877189f, 0.665683091f}, {-1.19523215f, 0.343314618f},
                                           {-1.1305275f, -0.433975369f}, {-0.0642294884f, -0.763029575f}};
    for (size_t k = 0; k < 5; ++k)
        EXPECT_NEAR(glm::length(g5.polygons.positions[k] - glm::vec3(cpfg5[k][1], 0, cpfg5[k][0])), 0.0f, 1e-5f) << k;
    // The second tube: 8 sides again (2 rings of 5 and two caps of 6 before it).
    ASSERT_GE(g5.polygons.positions.size(), 22u + 8);
    for (size_t k = 0; k < 8; ++k)
        EXPECT_NEAR(glm::length(g5.polygons.positions[22 + k] - glm::vec3(cpfg[k][1], 0, cpfg[k][0])), 0.0f, 1e-5f) << k;
    // No contour 2: cpfg's circle (Sprout's round tube).
    ParseResult round = parseWith("Lsystem: 1\nderivation length: 0\nAxiom: #(2) @#(2) @Gs F(1) @Ge\nendlsystem\n", growthTables());
    Geometry c;
    interpret(round.grammar->axiom, *round.grammar, {0, 1, nullptr}, c);
    ASSERT_GE(c.polygons.positions.size(), 12u);
    for (size_t k = 0; k < 12; ++k) EXPECT_NEAR(glm::length(c.polygons.positions[k]), 1.0f, 1e-5f);
}

// [SECTION] The corpus: every function, contour and curve file of the VLab manuals' objects reads cleanly.

TEST(VlabFiles, CorpusFilesReadWithoutProblems) {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals";
    if (!fs::is_directory(root)) GTEST_SKIP() << root << " is not here";
    int read = 0, curves = 0;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        const std::string ext = e.path().extension().string();
        std::vector<CurveFileDiagnostic> diags;
        if (ext == ".func") {
            FunctionRead f = loadFunction(e.path(), 100);
            diags = f.diagnostics;
            EXPECT_TRUE(std::isfinite(f.function(0.5))) << e.path();
        } else if (ext == ".fset") {
            FunctionSetRead s = loadFunctionSet(e.path());
            diags = s.diagnostics;
            EXPECT_FALSE(s.functions.empty()) << e.path();
        } else if (ext == ".con") {
            if (test::slurp(e.path()).starts_with("version:")) {  // a `curve:` file (curveX/Y/Z), not a contour
                CurveRead c = loadCurve(e.path(), 100);
                diags = c.diagnostics;
                EXPECT_GT(c.curve.length(), 0) << e.path();
                ++curves;
            } else {
                ContourRead c = loadContour(e.path());
                diags = c.diagnostics;
                if (c.contour) {
                    EXPECT_EQ(c.contour->sampled(8).size(), 9u) << e.path();
                }
            }
        } else if (ext == ".cset") {
            diags = loadContourSet(e.path()).diagnostics;
        } else {
            continue;
        }
        ++read;
        for (const CurveFileDiagnostic& d : diags) ADD_FAILURE() << d.text();
    }
    EXPECT_GE(read, 30);
    EXPECT_GE(curves, 1);  // Ridley's profile.con
}

}  // namespace
}  // namespace sprout
