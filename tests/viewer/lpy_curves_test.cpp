// An L-Py model's 2D curves as the panel's curve editor reads and writes them (issue 52):
// app/plant/lpy_objects.hpp on texts in each form L-Py writes, and on every model of the L-Py
// corpus whose panel lists curves; lpy::curveSamples, what the editor draws.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "app/plant/lpy_objects.hpp"
#include "lpy/lpy.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

// L-Py Studio's form (a tab and four spaces, the array named, a trailing " , "), a function
// among the curves, a Bezier written positionally, a polyline of pairs, a degree given.
const std::string kModel =
    "Axiom: A\nderivation length: 2\nproduction:\nA --> B\nendlsystem\n"
    "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\n"
    "def __initialiseContext__(context):\n"
    "\timport openalea.plantgl.all as pgl\n"
    "\tstem = pgl.NurbsCurve2D(\t\n"
    "\t    ctrlPointList = pgl.Point3Array([(-0.5, 0.1, 1),(-0.2, 0.3, 1),(0.1, 0.2, 1),(0.4, 0.35, 1)]) , \n"
    "\t    )\n"
    "\tstem.name = \"stem\"\n"
    "\tgrowth = pgl.NurbsCurve2D(\n"
    "\t    ctrlPointList = pgl.Point3Array([(0, 0, 1),(0.3, 0.8, 1),(0.7, 0.9, 1),(1, 0.2, 1)]) , \n"
    "\t    )\n"
    "\tarc = pgl.BezierCurve2D(\t\n"
    "\t    pgl.Point3Array([(0, 0, 1),(1, 2, 2),(2, 0, 1)]) , \n"
    "\t    )\n"
    "\toutline = pgl.Polyline2D([(0, 0),(0.5, 0.25),(1, 0)])\n"
    "\tsteep = pgl.NurbsCurve2D([(0, 0, 1),(1, 1, 1),(2, 0, 1),(3, 1, 1)], degree = 2)\n"
    "\tpanel_0 = ({'name': 'Panel 1', 'active': True, 'visible': True},[('Curve2D',stem),('Function',growth),"
    "('Curve2D',arc),('Curve2D',outline)])\n"
    "\tcontext[\"__curves__\"] = [('stem',stem),('arc',arc)]\n";

TEST(LpyCurves, EveryFormIsReadWithItsPlaceInTheText) {
    const std::vector<LpyCurve> curves = lpyCurves(kModel);
    ASSERT_EQ(curves.size(), 5u);
    EXPECT_EQ(curves[0].name, "stem");
    EXPECT_EQ(curves[0].kind, LpyCurve::Kind::Nurbs);
    EXPECT_FALSE(curves[0].function);
    EXPECT_EQ(curves[0].degree, 3);
    ASSERT_EQ(curves[0].points.size(), 4u);
    EXPECT_EQ(curves[0].points[1], (std::array<double, 3>{-0.2, 0.3, 1}));
    EXPECT_EQ(kModel.substr(curves[0].begin, 6), "[(-0.5");
    EXPECT_EQ(kModel[curves[0].end - 1], ']');
    EXPECT_EQ(curves[0].line, 12);
    EXPECT_EQ(curves[1].name, "growth");
    EXPECT_TRUE(curves[1].function);
    EXPECT_EQ(curves[2].name, "arc");
    EXPECT_EQ(curves[2].kind, LpyCurve::Kind::Bezier);
    EXPECT_EQ(curves[2].degree, 2);
    EXPECT_EQ(curves[2].points[1], (std::array<double, 3>{1, 2, 2}));
    EXPECT_EQ(curves[3].name, "outline");
    EXPECT_EQ(curves[3].kind, LpyCurve::Kind::Polyline);
    EXPECT_EQ(curves[3].points[1], (std::array<double, 3>{0.5, 0.25, 1}));
    EXPECT_EQ(curves[4].name, "steep");
    EXPECT_EQ(curves[4].degree, 2);
    // The panel that lists each (the panel's list groups them in the viewer).
    EXPECT_EQ(curves[0].panel, "Panel 1");
    EXPECT_EQ(curves[3].panel, "Panel 1");
    EXPECT_EQ(curves[4].panel, "") << "steep is in no panel";
    // Nothing before the INITIALISATION part's function is read.
    EXPECT_TRUE(lpyCurves("c = NurbsCurve2D([(0, 0, 1),(1, 1, 1)])\nAxiom: A\n").empty());
}

TEST(LpyCurves, APointMovedChangesOnlyItsListAndReadsBack) {
    const std::vector<LpyCurve> curves = lpyCurves(kModel);
    for (const LpyCurve& c : curves) {
        SCOPED_TRACE(c.name);
        std::vector<std::array<double, 3>> pts = c.points;
        pts[1][0] += 0.125;
        pts[1][1] = -1.0 / 3;
        const std::string moved = setLpyCurvePoints(kModel, c, pts);
        // The bytes before the list and after it are the same.
        EXPECT_EQ(moved.substr(0, c.begin), kModel.substr(0, c.begin));
        const size_t tail = kModel.size() - c.end;
        EXPECT_EQ(moved.substr(moved.size() - tail), kModel.substr(c.end));
        const std::vector<LpyCurve> again = lpyCurves(moved);
        ASSERT_EQ(again.size(), curves.size());
        const LpyCurve* same = nullptr;
        for (const LpyCurve& a : again)
            if (a.name == c.name) same = &a;
        ASSERT_NE(same, nullptr);
        EXPECT_NEAR(same->points[1][0], c.points[1][0] + 0.125, 1e-12);
        EXPECT_NEAR(same->points[1][1], -1.0 / 3, 1e-6);  // six digits, as L-Py Studio writes
        EXPECT_EQ(same->points[0], c.points[0]);
        // Written back as it was, the text is the same byte for byte.
        EXPECT_EQ(setLpyCurvePoints(moved, *same, c.points), kModel) << "the original numbers, in L-Py Studio's form";
    }
    // A polyline's points are pairs.
    const std::string poly = setLpyCurvePoints(kModel, curves[3], curves[3].points);
    EXPECT_NE(poly.find("Polyline2D([(0, 0),(0.5, 0.25),(1, 0)])"), std::string::npos);
}

// A name two panels set (L-Py Studio keeps each panel's version): NAME is the last, which the
// model's variable holds; NAME#0 the earlier one, each edited where it is written.
TEST(LpyCurves, EachVersionOfANameSeveralPanelsSetHasItsKey) {
    const std::string text =
        "def __initialiseContext__(context):\n\timport openalea.plantgl.all as pgl\n"
        "\tpath = pgl.NurbsCurve2D(pgl.Point3Array([(0, 0, 1),(1, 0, 1),(2, 0, 1)]), degree = 2)\n"
        "\tpanel_0 = ({'name': 'Panel 1'},[('Curve2D',path)])\n"
        "\tpath = pgl.NurbsCurve2D(pgl.Point3Array([(0, 1, 1),(1, 1, 1),(2, 1, 1)]), degree = 2)\n"
        "\tpanel_1 = ({'name': 'Panel 2'},[('Curve2D',path)])\n";
    const std::vector<LpyCurve> curves = lpyCurves(text);
    ASSERT_EQ(curves.size(), 2u);
    EXPECT_EQ(lpyCurveKey(curves, 0), "path#0");
    EXPECT_EQ(lpyCurveKey(curves, 1), "path");
    EXPECT_EQ(lpyCurveNamed(curves, "path"), &curves[1]) << "the last: the model's";
    EXPECT_EQ(lpyCurveNamed(curves, "path#0"), &curves[0]);
    EXPECT_EQ(lpyCurveNamed(curves, "path#1"), &curves[1]);
    EXPECT_EQ(lpyCurveNamed(curves, "path#2"), nullptr);
    EXPECT_EQ(lpyCurveNamed(curves, "path#x"), nullptr) << "no curve is named so";
    auto pts = curves[0].points;
    pts[1][1] = 0.5;
    const std::string moved = setLpyCurvePoints(text, *lpyCurveNamed(curves, "path#0"), pts);
    EXPECT_NE(moved.find("[(0, 0, 1),(1, 0.5, 1),(2, 0, 1)]"), std::string::npos) << moved;
    EXPECT_NE(moved.find("[(0, 1, 1),(1, 1, 1),(2, 1, 1)]"), std::string::npos) << "the last one as it was";
}

TEST(LpyCurves, TheEditorDrawsTheCurveAsPlantGLEvaluatesIt) {
    const std::vector<std::array<double, 3>> ctrl{{0, 0, 1}, {1, 2, 1}, {2, 0, 1}};
    // A Bezier of three points: its middle at (1, 1).
    const auto bezier = lpy::curveSamples(1, 0, ctrl, 3);
    ASSERT_EQ(bezier.size(), 3u);
    EXPECT_NEAR(bezier[1][0], 1, 1e-12);
    EXPECT_NEAR(bezier[1][1], 1, 1e-12);
    // A clamped NURBS starts and ends at its end points; a weight pulls the curve to its point.
    const auto nurbs = lpy::curveSamples(0, 3, ctrl, 50);
    ASSERT_EQ(nurbs.size(), 50u);
    EXPECT_EQ(nurbs.front(), (std::array<double, 2>{0, 0}));
    EXPECT_NEAR(nurbs.back()[0], 2, 1e-12);
    const auto heavy = lpy::curveSamples(1, 0, {{0, 0, 1}, {1, 2, 4}, {2, 0, 1}}, 3);
    EXPECT_GT(heavy[1][1], 1.5);
    // A polyline is its points; one point is no curve.
    EXPECT_EQ(lpy::curveSamples(2, 0, ctrl, 10).size(), 3u);
    EXPECT_TRUE(lpy::curveSamples(0, 3, {{0, 0, 1}}, 10).empty());
}

// Every curve L-Py's own models list in their panels (`('Curve2D', NAME)`, `('Function',
// NAME)`) is found, with as many points as its list has.
TEST(LpyCurves, EveryCurveTheCorpusModelsListIsFound) {
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "lpy";
    if (!fs::exists(root)) GTEST_SKIP() << "no L-Py corpus at " << root;
    const std::regex listed(R"(\('(Curve2D|Function)',\s*(\w+)\))");
    int models = 0, found = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (entry.path().extension() != ".lpy") continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        const std::string text = ss.str();
        std::vector<std::string> names;
        for (std::sregex_iterator it(text.begin(), text.end(), listed), end; it != end; ++it) names.push_back((*it)[2]);
        if (names.empty()) continue;
        ++models;
        const std::vector<LpyCurve> curves = lpyCurves(text);
        for (const std::string& name : names) {
            const bool here = std::any_of(curves.begin(), curves.end(), [&](const LpyCurve& c) { return c.name == name && c.points.size() >= 2; });
            EXPECT_TRUE(here) << entry.path() << ": " << name;
            found += here;
        }
    }
    EXPECT_GE(models, 20) << "the corpus's models with curves";
    std::printf("%d curves found in %d models\n", found, models);
}

}  // namespace
}  // namespace sprout
