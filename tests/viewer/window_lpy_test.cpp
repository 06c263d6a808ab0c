// The window on L-Py models under Xvfb: trust before their Python runs, a model that cannot
// end the viewer, growth refused at the line that asks for it, labels, picking and the
// inspector on Python rules.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "app/image.hpp"
#include "tests/viewer/window_support.hpp"

namespace sprout {
namespace {

// Trust before code runs, in the window: an L-Py file whose preamble writes a file is shown
// with the trust bar and runs nothing until "Trust and run"; the answer is remembered.
TEST(Window, AnLpyFileRunsItsPythonOnlyOnceTrusted) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("trust_window");
    const fs::path marker = dir / "written-by-the-model", model = dir / "model.lpy";
    fs::remove(marker);
    std::ofstream(model) << "import os\nopen('" << marker.string() << "', 'w').write('ran')\n"
                         << "Axiom: _(0.3) F(3) [ + F(2) ] [ - F(2) ] F(2)\nderivation length: 0\nproduction:\nendlsystem\n";
    const std::string before = (dir / "before.png").string(), after = (dir / "after.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1200x800",
                                   "wait\ntrust ?\nscreenshot " + before + " 400x300\ntrust yes\nwait\nscreenshot " + after +
                                       " 400x300\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"python=asking", "python=allowed"}));
    EXPECT_TRUE(fs::exists(marker)) << "trusted, the model ran";
    auto stems = [](const Image& img) {  // L-Py's default material 1, brown
        std::size_t n = 0;
        for (std::size_t i = 0; i < img.rgba.size(); i += 4)
            n += img.rgba[i] > 90 && img.rgba[i] < 220 && img.rgba[i + 1] < 150 && img.rgba[i + 2] < 80 && img.rgba[i] > img.rgba[i + 2] + 50;
        return n;
    };
    EXPECT_LT(stems(load(before)), 20u) << "nothing is drawn before the model is trusted";
    EXPECT_GT(stems(load(after)), 500u) << "the trusted model is drawn";
    // Opened again: remembered by its text's hash, it runs without asking.
    fs::remove(marker);
    EXPECT_EQ(runScript(dir, model.string(), "wait\ntrust ?\nquit\n"), std::vector<std::string>{"python=allowed"});
    EXPECT_TRUE(fs::exists(marker));
}

// Issue 39: a trusted model that calls os._exit does not end the viewer: the window runs on,
// says so at the model's line, and the script goes on to its end.
TEST(Window, AModelCallingOsExitDoesNotEndTheViewer) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("exit_window");
    const fs::path model = dir / "model.lpy";
    std::ofstream(model) << "import os\n\nAxiom: A\nderivation length: 2\nproduction:\nA:\n    os._exit(0)\n    produce AA\nendlsystem\n";
    const auto printed = runScript(dir, model.string() + " --size 900x600", "trust yes\nwait\nwait\ndiagnostics\nquit\n");
    ASSERT_GE(printed.size(), 2u);
    EXPECT_EQ(printed[0], "python=allowed");
    EXPECT_NE(std::find(printed.begin(), printed.end(), "diagnostic=7:5: a model cannot end Sprout (os._exit)"), printed.end())
        << (printed.size() > 1 ? printed[1] : "");
}

// Issue 39: explosive growth in the viewer is refused at once, said at the line that sets the
// derivation length, and the last plant stays on screen.
TEST(Window, ExplosiveGrowthIsRefusedAtTheDerivationLengthAndThePlantStays) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = testDir("growth_window");
    const fs::path grammar = dir / "boom.lsys";
    std::ofstream(grammar) << "n: 3\naxiom: A(1)\nA(x) -> F(1)[+A(x+1)]A(x*2)[-A(x)]\n";
    const auto start = std::chrono::steady_clock::now();
    const auto printed = runScript(dir, grammar.string() + " --size 900x600", "wait\ndiagnostics\nset n 60\nwait\nwait\ndiagnostics\nquit\n");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(printed.size(), 3u) << (printed.empty() ? "" : printed.back());
    EXPECT_EQ(printed[0], "plant=shown");
    EXPECT_EQ(printed[1].rfind("diagnostic=1:1: step 17 would produce 581,130,730 modules", 0), 0u) << printed[1];
    EXPECT_EQ(printed[2], "plant=shown");  // the plant of n 3 stays
    EXPECT_LT(seconds, 60.0);  // (not timed: refused at once, this only keeps a hang from passing)
}

// L-Py's labels (@L) over the view: the window showing a plant with a label differs from the
// same plant without one only in a small patch of the view (the text beside its point).
TEST(Window, LpyLabelsAreShownOverTheView) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("labels_window");
    Image shots[2];
    for (int k = 0; k < 2; ++k) {
        const fs::path model = dir / ("model" + std::to_string(k) + ".lpy"), png = dir / ("window" + std::to_string(k) + ".png");
        std::ofstream(model) << "Axiom: _(0.2) F(3) " << (k ? "@L('Hello there', 26)" : "") << " [ + F(2) ] F(2)\n"
                             << "derivation length: 0\nproduction:\nendlsystem\n";
        runScript(dir, model.string() + " --size 900x600 --screenshot " + png.string(), "trust yes\nwait\n");
        shots[k] = load(png.string());
        ASSERT_EQ(shots[k].width, 900);
    }
    std::size_t differ = 0, view = 0;
    for (int y = 0; y < shots[0].height; ++y)
        for (int x = 430; x < shots[0].width; ++x, ++view) {
            const std::size_t i = (std::size_t(y) * 900 + std::size_t(x)) * 4;
            differ += std::abs(int(shots[0].rgba[i]) - int(shots[1].rgba[i])) + std::abs(int(shots[0].rgba[i + 1]) - int(shots[1].rgba[i + 1])) > 40;
        }
    EXPECT_GT(differ, 100u) << "the label's text";
    EXPECT_LT(differ, view / 50) << "and nothing else";
}

// "Why this branch?" on an L-Py model: a click names the module, the step that made it and
// the line of the production; the inspector and the rule highlight work on it too.
TEST(Window, PickingAnLpyModelNamesItsProductionAndLine) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("pick_lpy");
    std::ofstream(dir / "model.lpy") << "# picking test\nAxiom: _(0.4) A\nderivation length: 3\nproduction:\n"
                                        "A --> F(2) [ + B ] A\nB --> F(1) B\nendlsystem\n";
    // The string: _(0.4) F(2) [ + F(1) F(1) B ] F(2) [ + F(1) B ] F(2) [ + B ] A
    const auto printed = runScript(dir, (dir / "model.lpy").string() + " --size 1300x860",
                                   "wait\ntrust yes\nwait\npick 980 750\npick 980 100\ninspect 3 5\nhighlight-rule 6\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"python=allowed", "module=F index=1 step=1 rule_line=5", "module=F index=14 step=3 rule_line=5",
                                                 "inspect: F(1)", "inspect: made at step 3 by line 6", "highlighted=3"}));
}

// The same for an L-Py model, whose rules are Python: where the context matched is kept by
// the run. Step 2 is F F F B; its B was made by B < A --> B (line 5) from step 1's A (3),
// whose left context was step 1's B (2).
TEST(Window, InspectorSaysWhichContextMatchedInAnLpyModel) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("inspect_lpy");
    std::ofstream(dir / "model.lpy") << "# a signal\nAxiom: F B A A\nderivation length: 2\nproduction:\nB < A --> B\nB --> F\nendlsystem\n";
    const auto printed = runScript(dir, (dir / "model.lpy").string() + " --size 1200x800", "wait\ntrust yes\nwait\ninspect 2 3\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"python=allowed", "inspect: B", "inspect: made at step 2 by line 5",
                                                 "inspect: context matched in step 1: B (2) < [A (3)] >"}));
}

// Issue 39: the same in an L-Py model whose Python body doubles the string: refused before its
// first step, at the `derivation length:` line; the plant of the derivation length before stays.
TEST(Window, LpyGrowthIsRefusedAtTheDerivationLengthAndThePlantStays) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("growth_lpy_window");
    const fs::path model = dir / "boom.lpy";
    const std::string head = "Axiom: _(0.2) A(1)\\nderivation length: ";
    const std::string rules = "\\nproduction:\\nA(x):\\n    y = x*2\\n    produce F(1) [ + A(x+1) ] A(y)\\nendlsystem\\n";
    std::ofstream(model) << "Axiom: _(0.2) A(1)\nderivation length: 3\nproduction:\nA(x):\n    y = x*2\n    produce F(1) [ + A(x+1) ] A(y)\nendlsystem\n";
    const auto start = std::chrono::steady_clock::now();
    const auto printed = runScript(dir, model.string() + " --size 900x600",
                                   "trust yes\nwait\ndiagnostics\ntext " + head + "40" + rules + "\nwait\nwait\ndiagnostics\nquit\n");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(printed.size(), 4u) << (printed.empty() ? "" : printed.back());
    EXPECT_EQ(printed[1], "plant=shown");
    EXPECT_EQ(printed[2].rfind("diagnostic=2:1: step 24 would make 83,886,077 modules", 0), 0u) << printed[2];
    EXPECT_EQ(printed[3], "plant=shown");  // the plant of derivation length 3 stays
    EXPECT_LT(seconds, 60.0);  // (not timed: refused at once, this only keeps a hang from passing)
}

// Issue 52: a point of an L-Py model's curve, moved as a drag in the panel's curve editor moves
// it, moves in the model's text (only its list, in L-Py Studio's form) and the plant follows it;
// one undo takes the whole drag back: the picture and the saved file are what they were.
// A stem guided by a NURBS curve, as L-Py Studio writes one.
const std::string kGuidedModel =
    "Axiom: _(0.15) SetGuide(path, 8) nF(8, 0.1)\nderivation length: 0\nproduction:\nendlsystem\n"
    "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\ndef __initialiseContext__(context):\n"
    "\timport openalea.plantgl.all as pgl\n\tpath = pgl.NurbsCurve2D(\t\n"
    "\t    ctrlPointList = pgl.Point3Array([(-0.5, 0, 1),(-0.1, 0.05, 1),(0.2, -0.05, 1),(0.5, 0, 1)]) , \n\t    )\n"
    "\tpath.name = \"path\"\n"
    "\tpanel_0 = ({'name': 'Panel 1', 'active': True, 'visible': True},[('Curve2D',path)])\n"
    "\tparameterset = [panel_0,]\n\tcontext[\"__curves__\"] = [('path',path),]\n"
    "\tcontext[\"__parameterset__\"] = parameterset\n\tcontext[\"path\"] = path\n";

// A name two panels set: the earlier version is listed and edited where it is written (the
// picture stays: the model uses the last), the last bends the plant.
TEST(Window, AnEarlierPanelsVersionOfACurveIsEditedInPlace) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("curve_versions");
    const fs::path model = dir / "two.lpy", saved = dir / "saved.lpy";
    std::string text = kGuidedModel;
    const std::string earlier = "\tpath = pgl.NurbsCurve2D(pgl.Point3Array([(-0.5, 0, 1),(0, 0.3, 1),(0.5, 0, 1)]), degree = 2)\n"
                                "\tpanel_9 = ({'name': 'Old'},[('Curve2D',path)])\n";
    text.insert(text.find("\tpath = pgl.NurbsCurve2D(\t\n"), earlier);
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\ncurves\nscreenshot " + a + " 400x300\ncurve-point path#0 1 0 0.9\nwait\n"
                                   "screenshot " + b + " 400x300\ncurve-point path 2 0.2 0.6\nwait\nscreenshot " + c +
                                   " 400x300\nsaveas " + saved.string() + "\nquit\n");
    ASSERT_EQ(printed.size(), 3u);
    EXPECT_EQ(printed[1], "curve=path#0 kind=0 points=-0.5,0,1;0,0.3,1;0.5,0,1");
    EXPECT_EQ(printed[2], "curve=path kind=0 points=-0.5,0,1;-0.1,0.05,1;0.2,-0.05,1;0.5,0,1");
    const std::string out = fileText(saved);
    EXPECT_NE(out.find("[(-0.5, 0, 1),(0, 0.9, 1),(0.5, 0, 1)]"), std::string::npos) << "the earlier version, where it is written";
    EXPECT_NE(out.find("(0.2, 0.6, 1)"), std::string::npos) << "and the last";
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_LE(pixelsThatDiffer(ia, ib), 20u) << "the model uses the last version: the plant as it was";
    EXPECT_GT(pixelsThatDiffer(ib, ic), 400u * 300u / 200) << "the last one bends it";
}

TEST(Window, ACurvePointDraggedBendsThePlantAndOneUndoRestoresIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("curve_window");
    const fs::path model = dir / "guided.lpy";
    const std::string text = kGuidedModel;
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const fs::path moved = dir / "moved.lpy", back = dir / "back.lpy";
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\ncurves\nscreenshot " + a + " 400x300\n"
                                   // one drag, three moves: one undo step
                                   "curve-point path 2 0.2 0.2 1\nwait\ncurve-point path 2 0.2 0.4 1\nwait\n"
                                   "curve-point path 2 0.2 0.6 1\nwait\ncurves\n"
                                   "screenshot " + b + " 400x300\nsaveas " + moved.string() + "\nundo\nwait\n"
                                   "screenshot " + c + " 400x300\nsaveas " + back.string() + "\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"python=allowed", "curve=path kind=0 points=-0.5,0,1;-0.1,0.05,1;0.2,-0.05,1;0.5,0,1",
                                                 "curve=path kind=0 points=-0.5,0,1;-0.1,0.05,1;0.2,0.6,1;0.5,0,1"}));
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 400u * 300u / 200) << "the stem follows its path";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u) << "undone, the plant is as it was";
    const std::string was = "(0.2, -0.05, 1)", now = "(0.2, 0.6, 1)";
    std::string expected = text;
    expected.replace(expected.find(was), was.size(), now);
    EXPECT_EQ(fileText(moved), expected) << "only the point's numbers change";
    EXPECT_EQ(fileText(back), text) << "one undo: the file is the same byte for byte";
}

// What the X server shows after a curve's point is dragged, a step a frame: on software GL a
// frame whose view is as it was (no plant came) sends only the panel's strip to the server and
// leaves the view in the back buffer as it is; one whose panel is as it was sends only the
// view. Copied so, or swapped whole (SPROUT_SWAP=1), the screen shows the same window, and its
// view is the window's picture.
TEST(Window, TheScreenShowsTheWindowAfterACurveDrag) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    constexpr int kW = 1000, kH = 700, kPanel = 430;
    const fs::path dir = testDir("curve_screen"), model = dir / "guided.lpy";
    std::ofstream(model, std::ios::binary) << kGuidedModel;
    std::vector<std::uint8_t> screens[2];
    for (int way = 0; way < 2; ++way) {
        SCOPED_TRACE(way ? "swapped" : "copied");
        const fs::path fb = dir / (way ? "fb_swap" : "fb_copy"), view = dir / (way ? "view_swap.png" : "view_copy.png");
        fs::remove_all(fb);
        fs::create_directories(fb);
        fs::remove(view);
        std::ofstream(dir / "script.txt") << "trust yes\nwait\nsleep 0.3\nwait\ncurve-drag path 2 0.1 0.6 40\nwait\nsleep 0.5\nwait\n"
                                          << "screenshot " << view.string() << "\nsleep 3\nquit\n";
        int code = -1;
        std::thread app([&] {
            code = runUnderXvfb(model.string() + " --size " + std::to_string(kW) + "x" + std::to_string(kH) + " --script " +
                                    (dir / "script.txt").string(),
                                way ? "SPROUT_SWAP=1" : "", "/dev/null", "-screen 0 1600x1000x24 -fbdir " + fb.string());
        });
        for (int k = 0; k < 1200 && !fs::exists(view); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(100));
        std::this_thread::sleep_for(std::chrono::milliseconds(800));
        std::ifstream in(fb / "Xvfb_screen0", std::ios::binary);
        const bool read = screenCorner(std::string(std::istreambuf_iterator<char>(in), {}), kW, kH, screens[way]);
        app.join();
        EXPECT_EQ(code, 0);
        ASSERT_TRUE(read) << "no screen read";
        const Image v = load(view.string());
        ASSERT_EQ(v.width, kW - kPanel);
        EXPECT_LT(viewDiffersOnScreen(screens[way], kW, kPanel, v), v.width * kH / 100) << "the screen's view is the window's picture";
    }
    EXPECT_LT(screensDiffer(screens[0], screens[1], kW, 0, kW, kH), kW * kH / 200) << "copied and swapped frames show the same window, panel and view";
}

// The editor as a user works it: the mouse (as ImGui sees it) presses a point in the panel's
// canvas and drags it up; the editor's tools add a point, weight one and set a preset. Each
// changes the plant; undoing them all gives back the first picture and the file.
TEST(Window, TheMouseDragsACurvePointInTheEditorAndUndoRestoresIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("curve_mouse");
    const fs::path model = dir / "guided.lpy", back = dir / "back.lpy", moved = dir / "moved.lpy";
    std::ofstream(model, std::ios::binary) << kGuidedModel;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string(),
                      d = (dir / "d.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\nscreenshot " + a + " 400x300\n"
                                   "mouse-drag-point 2 0 -80 6\nwait\ncurves\nscreenshot " + b + " 400x300\n"
                                   "saveas " + moved.string() + "\n"
                                   "curve-edit path add 3\ncurve-edit path weight 1 4\nwait\ncurves\n"
                                   "curve-preset path s\nwait\nscreenshot " + d + " 400x300\n"
                                   "undo\nundo\nundo\nundo\nwait\nscreenshot " + c + " 400x300\nsaveas " + back.string() + "\nquit\n");
    ASSERT_EQ(printed.size(), 3u);
    // Point 2 went up about 80 pixels' worth and hardly sideways; the others stayed.
    double x = 0, y = 0;
    ASSERT_EQ(std::sscanf(printed[1].c_str(), "curve=path kind=0 points=-0.5,0,1;-0.1,0.05,1;%lf,%lf,1;0.5,0,1", &x, &y), 2) << printed[1];
    EXPECT_NEAR(x, 0.2, 1e-3);
    EXPECT_GT(y, 0.15);
    EXPECT_NE(printed[2].find(";0.8,"), std::string::npos) << "a fifth point beyond the end: " << printed[2];
    EXPECT_NE(printed[2].find(";-0.1,0.05,4;"), std::string::npos) << "point 1 weighs 4: " << printed[2];
    const Image ia = load(a), ib = load(b), ic = load(c), id = load(d);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 400u * 300u / 200) << "the stem follows the dragged point";
    EXPECT_GT(pixelsThatDiffer(ib, id), 400u * 300u / 200) << "the S preset bends it again";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u) << "undone, the plant is as it was";
    EXPECT_NE(fileText(moved), kGuidedModel);
    EXPECT_EQ(fileText(back), kGuidedModel) << "four undos: the file is the same byte for byte";
}

// The material editor: a slider of material 1 (its ambient colour, as the panel's colour editor
// sets it) turns the stem from green to red; one undo gives back the picture and the file.
TEST(Window, AMaterialSetInThePanelRecoloursThePlantAndUndoRestoresIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("material_window");
    const fs::path model = dir / "stem.lpy", moved = dir / "moved.lpy", back = dir / "back.lpy";
    const std::string text = "Axiom: ,(1) _(0.3) F(3)\nderivation length: 0\nproduction:\nendlsystem\n"
                             "###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\ndef __initialiseContext__(context):\n"
                             "\timport openalea.plantgl.all as pgl\n"
                             "\tColor_1 = pgl.Material(\"Color_1\" , ambient = (10,60,10) , diffuse = 3 , )\n"
                             "\tColor_1.name = \"Color_1\"\n\tcontext.turtle.setMaterial(1,Color_1)\n";
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\nmaterials\nscreenshot " + a + " 400x300\nmaterial-set 1 ambient 80 10 10\nwait\n"
                                   "materials\nscreenshot " + b + " 400x300\nsaveas " + moved.string() + "\nundo\nwait\nscreenshot " + c +
                                   " 400x300\nsaveas " + back.string() + "\nquit\n");
    ASSERT_EQ(printed.size(), 3u);
    EXPECT_EQ(printed[1], "material=1 name=Color_1 ambient=10,60,10 diffuse=3 specular=0,0,0 emission=0,0,0 shininess=0.2 transparency=0");
    EXPECT_EQ(printed[2], "material=1 name=Color_1 ambient=80,10,10 diffuse=3 specular=0,0,0 emission=0,0,0 shininess=0.2 transparency=0");
    const Image ia = load(a), ib = load(b), ic = load(c);
    // The stem's middle: green, then red.
    const auto ma = mean(ia, 190, 120, 210, 180), mb = mean(ib, 190, 120, 210, 180);
    EXPECT_GT(ma[1], ma[0] + 40) << "green first";
    EXPECT_GT(mb[0], mb[1] + 40) << "red once set";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u) << "undone, the plant is as it was";
    std::string expected = text;
    expected.replace(expected.find("(10,60,10)"), 10, "(80,10,10)");
    EXPECT_EQ(fileText(moved), expected) << "only the colour's numbers change";
    EXPECT_EQ(fileText(back), text);
}

// The scalar editor: a model that uses a scalar it does not have is an error at its line; the
// scalar added from the panel makes it grow, renamed it is missing again, one undo brings it back.
TEST(Window, AScalarAddedInThePanelIsOneTheModelGrowsWith) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("scalar_window");
    const fs::path model = dir / "stem.lpy", saved = dir / "saved.lpy";
    std::ofstream(model, std::ios::binary) << "Axiom: _(0.3) F(H)\nderivation length: 1\nproduction:\nendlsystem\n";
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\ndiagnostics\nscalar-add H Float 3 0 5\nwait\nscalars\ndiagnostics\n"
                                   "scalar-rename H G\nwait\ndiagnostics\nundo\nwait\ndiagnostics\n"
                                   "scalar-add Sizes Category\nwait\nscalars\ndiagnostics\nsaveas " + saved.string() + "\nquit\n");
    EXPECT_EQ(printed, (std::vector<std::string>{"python=allowed", "diagnostic=1:1: NameError: name 'H' is not defined", "plant=none",
                                                 "scalar=H kind=1 value=3 min=0 max=5", "plant=shown",
                                                 "diagnostic=1:1: NameError: name 'H' is not defined", "plant=shown", "plant=shown",
                                                 "scalar=H kind=1 value=3 min=0 max=5", "scalar=Sizes kind=3 value=0 min=0 max=1",
                                                 "plant=shown"}));
    EXPECT_NE(fileText(saved).find("\tscalars = [('H', 'Float', 3.0, 0.0, 5.0, 2), ('Sizes', 'Category')]\n\tcontext[\"__scalars__\"] = scalars\n"),
              std::string::npos) << "a heading, as Studio writes it; the model still grows";
}

// A flat 4 x 4 NurbsPatch sheet of L-Py Studio's form (degrees 3, the default).
const std::string kSheet =
    "Axiom: @g(patch, 1)\n"
    "derivation length: 0\n"
    "production:\n"
    "endlsystem\n"
    "###### INITIALISATION ######\n"
    "\n"
    "__lpy_code_version__ = 1.1\n"
    "\n"
    "def __initialiseContext__(context):\n"
    "\timport openalea.plantgl.all as pgl\n"
    "\tpatch = pgl.NurbsPatch(\t\n"
    "\t    pgl.Point4Matrix([[(-1, 0, -1, 1), (-0.333333, 0, -1, 1), (0.333333, 0, -1, 1), (1, 0, -1, 1)], [(-1, 0, -0.333333, 1), (-0.333333, 0, -0.333333, 1), (0.333333, 0, -0.333333, 1), (1, 0, -0.333333, 1)], [(-1, 0, 0.333333, 1), (-0.333333, 0, 0.333333, 1), (0.333333, 0, 0.333333, 1), (1, 0, 0.333333, 1)], [(-1, 0, 1, 1), (-0.333333, 0, 1, 1), (0.333333, 0, 1, 1), (1, 0, 1, 1)]]) , \n"
    "\t    )\n"
    "\tpatch.name = \"patch\"\n"
    "\tpanel_0 = ({'name': 'Panel 1', 'active': True, 'visible': True},[('NurbsPatch',patch)])\n"
    "\tparameterset = [panel_0,]\n"
    "\tcontext[\"__parameterset__\"] = parameterset\n"
    "\tcontext[\"patch\"] = patch\n"
    "";

// The surface editor: the mouse drags the top corner of a NurbsPatch up in the panel's 3D view;
// the sheet follows, and one undo gives back the picture and the file.
TEST(Window, TheMouseDragsAPatchCornerInTheSurfaceEditorAndUndoRestoresIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("surface_window");
    const fs::path model = dir / "sheet.lpy", back = dir / "back.lpy";
    const std::string text = kSheet;
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\nscreenshot " + a + " 300x300\nmouse-drag-surface-point 3 3 0 -100 6\nwait\n"
                                   "screenshot " + b + " 300x300\nsurfaces\nundo\nwait\nscreenshot " + c + " 300x300\nsaveas " +
                                   back.string() + "\nquit\n");
    ASSERT_EQ(printed.size(), 2u);
    // Only the corner moved, and up.
    const std::string moved = printed[1].substr(printed[1].rfind(';') + 1);
    double x = 0, y = 0, z = 0;
    ASSERT_EQ(std::sscanf(moved.c_str(), "%lf,%lf,%lf", &x, &y, &z), 3) << printed[1];
    EXPECT_GT(z, 1.3);
    EXPECT_EQ(printed[1].substr(0, printed[1].rfind(';')), "surface=patch points=-1,0,-1;-0.333333,0,-1;0.333333,0,-1;1,0,-1;"
              "-1,0,-0.333333;-0.333333,0,-0.333333;0.333333,0,-0.333333;1,0,-0.333333;-1,0,0.333333;-0.333333,0,0.333333;"
              "0.333333,0,0.333333;1,0,0.333333;-1,0,1;-0.333333,0,1;0.333333,0,1");
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_GT(pixelsThatDiffer(ia, ib), 300u * 300u / 50) << "the sheet follows its corner";
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u);
    EXPECT_EQ(fileText(back), text) << "one undo: the file byte for byte";
}

// The surface editor's tools on an L-Py patch: a row added (midway), a column the degree needs
// refused, a column added, a point weighed; each one undo step, the file back byte for byte.
TEST(Window, TheSurfaceEditorAddsRowsAndColumnsAndWeighsPoints) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("surface_tools");
    const fs::path model = dir / "sheet.lpy", edited = dir / "edited.lpy", back = dir / "back.lpy";
    std::ofstream(model, std::ios::binary) << kSheet;
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\nsurface-edit 0 add-row 1\nwait\nsurface-edit 0 delete-column 0\n"
                                   "surface-edit 0 add-column 3\nwait\nsurface-edit 0 weight 2 2 5\nwait\ndiagnostics\nsurfaces\nsaveas " +
                                       edited.string() + "\nundo\nundo\nundo\nwait\nsaveas " + back.string() + "\nquit\n");
    ASSERT_EQ(printed.size(), 4u) << printed.size();
    EXPECT_EQ(printed[0], "python=allowed");
    EXPECT_EQ(printed[1], "refused=a patch of degree 3 along its columns keeps at least 4 of them");
    EXPECT_EQ(printed[2], "plant=shown") << "the model runs with the new patch";
    // 5 rows of 5: the row added between rows 1 and 2 (z midway), the column after the last
    // (x as far again beyond it).
    EXPECT_EQ(std::count(printed[3].begin(), printed[3].end(), ';'), 24) << printed[3];
    EXPECT_NE(printed[3].find(";-1,0,0;"), std::string::npos) << printed[3];
    EXPECT_NE(printed[3].find("1.66667,0,-1;"), std::string::npos) << printed[3];
    const std::string text = fileText(edited);
    EXPECT_NE(text.find("(0.333333, 0, 0, 5)"), std::string::npos) << "point 2,2 weighs 5: " << text;
    EXPECT_EQ(fileText(back), kSheet) << "three undos: the file byte for byte";
}

// An image under the curve editor's curve to trace: a PNG loads (its size said), a missing one
// is a message that names it.
TEST(Window, AnImageToTraceLoadsUnderTheCurve) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("trace_window");
    const fs::path model = dir / "guided.lpy", photo = dir / "leaf.png";
    std::ofstream(model, std::ios::binary) << kGuidedModel;
    Image leaf;
    leaf.width = 30, leaf.height = 20;
    leaf.rgba.assign(30 * 20 * 4, 200);
    std::string error;
    ASSERT_TRUE(writePng(photo.string(), leaf, error)) << error;
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\ncurve-trace " + photo.string() + "\ncurve-trace " + (dir / "none.png").string() +
                                   "\nquit\n");
    ASSERT_EQ(printed.size(), 3u);
    EXPECT_EQ(printed[1], "trace=30x20");
    EXPECT_EQ(printed[2].rfind("trace_error=" + (dir / "none.png").string() + ": cannot open", 0), 0u) << printed[2];
}

// The material editor's texture: a Texture2D's image file changed in the panel (as Studio's
// ImageTexture writes it), the patch drawn with the new image at once; one undo gives back
// the picture and the file.
TEST(Window, ATexturesImageFileChangedInThePanelIsDrawn) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed";
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = testDir("texture_window");
    auto plainImage = [&](const char* name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        Image im;
        im.width = im.height = 4;
        for (int k = 0; k < 16; ++k) im.rgba.insert(im.rgba.end(), {r, g, b, std::uint8_t(255)});
        std::string error;
        EXPECT_TRUE(writePng((dir / name).string(), im, error)) << error;
    };
    plainImage("red.png", 230, 20, 20);
    plainImage("blue.png", 20, 20, 230);
    std::ofstream(dir / "broken.png", std::ios::binary) << "not an image";
    const fs::path model = dir / "leaf.lpy", back = dir / "back.lpy";
    const std::string text =
        "from openalea.plantgl.all import *\n"
        "quad = NurbsPatch([[(0, -1, -1, 1), (0, -1, 1, 1)], [(0, 1, -1, 1), (0, 1, 1, 1)]], udegree=1, vdegree=1)\n"
        "Axiom: @g(quad)\nderivation length: 0\nproduction:\nendlsystem\n###### INITIALISATION ######\n\n__lpy_code_version__ = 1.1\n\n"
        "def __initialiseContext__(context):\n\timport openalea.plantgl.all as pgl\n"
        "\tPGL_1 = pgl.ImageTexture(\"PGL_1\" , \"red.png\" , )\n\tPGL_1.name = \"PGL_1\"\n"
        "\tColor_1 = pgl.Texture2D(image = PGL_1 , )\n\tColor_1.name = \"Color_1\"\n\tcontext.turtle.setMaterial(1,Color_1)\n";
    std::ofstream(model, std::ios::binary) << text;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(), c = (dir / "c.png").string();
    const auto printed = runScript(dir, model.string() + " --size 1000x700",
                                   "trust yes\nwait\nmaterials\nscreenshot " + a + " 200x200\nmaterial-set 1 image blue.png\nwait\nmaterials\n"
                                   "screenshot " + b + " 200x200\nundo\nwait\nscreenshot " + c + " 200x200\nsaveas " + back.string() +
                                   "\nmaterial-set 1 image broken.png\nwait\nframe\nstatus\nquit\n");
    ASSERT_EQ(printed.size(), 4u);
    // A broken image: the window's status line names it (the surface in its colour).
    EXPECT_NE(printed[3].find("status=texture image '" + (dir / "broken.png").string() + "': not a PNG, JPEG or SGI image"), std::string::npos)
        << printed[3];
    EXPECT_NE(printed[1].find(" texture=red.png"), std::string::npos) << printed[1];
    EXPECT_NE(printed[2].find(" texture=blue.png"), std::string::npos) << printed[2];
    auto count = [](const Image& im, bool blue) {
        std::size_t n = 0;
        for (std::size_t k = 0; k + 3 < im.rgba.size(); k += 4) {
            const int r = im.rgba[k], g = im.rgba[k + 1], bl = im.rgba[k + 2];
            n += blue ? (bl > 120 && r < 80 && g < 80) : (r > 120 && g < 80 && bl < 80);
        }
        return n;
    };
    const Image ia = load(a), ib = load(b), ic = load(c);
    EXPECT_GT(count(ia, false), 2000u) << "the red image";
    EXPECT_GT(count(ib, true), 2000u) << "the blue image, drawn at once";
    EXPECT_LT(count(ib, false), 50u);
    EXPECT_LE(pixelsThatDiffer(ia, ic), 20u) << "one undo: the red again";
    EXPECT_EQ(fileText(back), text) << "and the file byte for byte";
}

}  // namespace
}  // namespace sprout
