// L-Py models run by the embedded Python (lpy/). tests/lpy/models: small models written for
// Sprout from L-Py's documentation, each carrying what it must derive in comment lines:
//   # expect N: STRING     the string after N steps, as `sprout expand -n N` prints it
// and the collection of L-Py's own examples (../shared/corpus/lpy, when it is there).
#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "core/derive/draw.hpp"
#include "core/derive/provenance.hpp"
#include "core/language/file_kind.hpp"
#include "lpy/lpy.hpp"
#include "tests/lpy/lpy_messages.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Growth stepping keeps where each module came from, natively as in Python: the lineage of
// every `stride`th module of the last step.
void expectSameLineage(const std::string& text, lpy::RunOptions o, std::uint32_t stride) {
    o.keepSteps = true;
    o.native = false;
    lpy::Model pythonSteps = lpy::runModel(text, o);
    o.native = true;
    lpy::Model nativeSteps = lpy::runModel(text, o);
    ASSERT_TRUE(pythonSteps.ok() && nativeSteps.ok()) << messages(nativeSteps) << messages(pythonSteps);
    EXPECT_TRUE(nativeSteps.ranNative);
    const auto& rn = nativeSteps.record;
    const auto& rp = pythonSteps.record;
    ASSERT_EQ(rn.steps.size(), rp.steps.size());
    const int last = int(rn.steps.size()) - 1;
    const std::uint32_t size = std::uint32_t(rn.steps[size_t(last)]->size());
    ASSERT_EQ(size, rp.steps[size_t(last)]->size());
    for (std::uint32_t i = 0; i < size; i += stride)
        EXPECT_EQ(describeLineage(*rn.grammar, lineage(rn, last, i)), describeLineage(*rp.grammar, lineage(rp, last, i)))
            << "module " << i;
}

TEST(LpyTranslate, LinesKeepTheirNumbers) {
    const std::string text = "def f(x):\n    return x\nAxiom: A(1)\nderivation length: 2\nproduction:\nA(x) :\n  produce B(f(x))\nendlsystem\n";
    lpy::Translation t = lpy::translate(text);
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(std::count(t.mainCode.begin(), t.mainCode.end(), '\n'), std::count(text.begin(), text.end(), '\n') + 1);
    ASSERT_EQ(t.rules.size(), 1u);
    EXPECT_EQ(t.rules[0].line, 6);
    EXPECT_EQ(t.rules[0].params, std::vector<std::string>{"x"});
    EXPECT_TRUE(looksLikeLpy(text));
    EXPECT_EQ(detectFileKind("", text), FileKind::Lpy);
    EXPECT_EQ(detectFileKind("x.lpy", "Axiom: F\n"), FileKind::Lpy);
}

// The L-systems of one Python process share their module names' ids: a translation starts
// from the process's table with its names hidden, so a text reads as with a fresh table, and
// a name used again keeps its id.
TEST(LpyTranslate, SeededTableKeepsIdsAndReadsAsFresh) {
    lpy::Translation first = lpy::translate("module Apex, Leaf\nAxiom: Apex Leaf\n");
    ASSERT_TRUE(first.ok());
    lpy::ModuleClasses process;
    process.adopt(first.classes, false);
    const int apex = process.find("Apex"), leaf = process.find("Leaf");
    ASSERT_GE(apex, 0);
    lpy::Translation second = lpy::translate("module Leaf\nAxiom: Apex Leaf\n", &process);
    ASSERT_TRUE(second.ok());
    std::vector<Diagnostic> diags;
    auto mods = lpy::readLstring("Apex Leaf", second.classes, 1, 1, diags);
    std::vector<std::string> names;
    for (const auto& m : mods) names.push_back(second.classes.name(m.cls));
    // Apex is not declared here: its letters, as a fresh table reads them; Leaf keeps its id.
    EXPECT_EQ(names, (std::vector<std::string>{"A", "p", "e", "x", "Leaf"}));
    EXPECT_EQ(second.classes.find("Leaf"), leaf);
    EXPECT_EQ(second.classes.find("Apex"), -1);
    EXPECT_EQ(second.classes.name(apex), "Apex");  // still its id, hidden
    // Given back, the process's table grows by the new names only, at the same ids.
    const size_t before = process.size();
    process.adopt(second.classes, false);
    EXPECT_EQ(process.find("Leaf"), leaf);
    EXPECT_EQ(process.name(apex), "Apex");
    EXPECT_GE(process.size(), before);
    EXPECT_EQ(process.name(second.classes.find("x")), "x");
}

TEST(LpyTranslate, LongestKnownNameFirst) {
    lpy::ModuleClasses classes;
    std::vector<Diagnostic> diags;
    auto mods = lpy::readLstring("Leaf @GcI(0.5) ~l(2) $m F (1)", classes, 1, 1, diags);
    std::vector<std::string> names;
    for (const auto& m : mods) names.push_back(m.variable.empty() ? classes.name(m.cls) : "$" + m.variable);
    // An undeclared name splits into letters (L-Py's on-the-fly declaration).
    EXPECT_EQ(names, (std::vector<std::string>{"L", "e", "a", "f", "@Gc", "I", "~", "$m", "F"}));
    EXPECT_EQ(mods[5].args, std::vector<std::string>{"0.5"});
    EXPECT_EQ(mods[6].args, (std::vector<std::string>{"'l'", "2"}));
    EXPECT_TRUE(diags.empty());
}

TEST(Lpy, EveryModelDerivesWhatItSays) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(SPROUT_LPY_MODELS))
        if (e.path().extension() == ".lpy") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 10u);
    const std::regex expectLine(R"(^# expect (\d+): (.*)$)");
    int checked = 0, native = 0;
    for (const auto& path : files) {
        SCOPED_TRACE(path.filename().string());
        const std::string text = slurp(path);
        EXPECT_EQ(detectFileKind(path.string(), text), FileKind::Lpy);
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            std::smatch m;
            if (!std::regex_match(line, m, expectLine)) continue;
            lpy::RunOptions o;
            o.path = path.string();
            o.steps = std::stoi(m[1]);
            lpy::Model model = lpy::runModel(text, o);
            ASSERT_TRUE(model.ok()) << messages(model);
            EXPECT_EQ(model.derived, m[2].str()) << "after " << m[1] << " steps";
            ++checked;
            // A model the native path takes derives the same with every match in Python.
            if (model.ranNative) {
                ++native;
                o.native = false;
                lpy::Model python = lpy::runModel(text, o);
                ASSERT_TRUE(python.ok()) << messages(python);
                EXPECT_FALSE(python.ranNative);
                EXPECT_EQ(python.derived, model.derived) << "the Python path, after " << m[1] << " steps";
                // The native string is drawn from its numbers, the Python one from its values:
                // the same modules for the turtle.
                EXPECT_TRUE(python.drawable->axiom.symbols == model.drawable->axiom.symbols &&
                            python.drawable->axiom.params == model.drawable->axiom.params)
                    << "the drawing after " << m[1] << " steps";
                SCOPED_TRACE("after " + m[1].str() + " steps");
                expectSameLineage(text, o, 1);
            }
        }
    }
    EXPECT_GE(checked, int(files.size()));
    EXPECT_GE(native, 3);  // native_*.lpy at least
}

TEST(Lpy, PythonErrorsSayWhereInTheFile) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string text = "def grow(x):\n    return x / 0\n\nAxiom: A(1)\nderivation length: 2\nproduction:\nA(x) :\n    y = grow(x)\n    produce A(y)\nendlsystem\n";
    lpy::RunOptions o;
    o.path = "bad.lpy";
    lpy::Model m = lpy::runModel(text, o);
    ASSERT_FALSE(m.ok());
    ASSERT_FALSE(m.diagnostics.empty());
    const Diagnostic& d = m.diagnostics.back();
    EXPECT_EQ(d.line, 2);  // the frame that raised, in the model's own function
    EXPECT_NE(d.message.find("ZeroDivisionError"), std::string::npos) << d.message;
    // A division by zero in a produce-only rule (the native path gives the model back to
    // Python, which raises): the rule's line, the column of its successor.
    lpy::Model z = lpy::runModel("Axiom: A(1) A(0)\nderivation length: 1\nproduction:\nA(x) --> A(1 / x)\nendlsystem\n", o);
    ASSERT_FALSE(z.ok());
    EXPECT_EQ(z.diagnostics.back().line, 4) << messages(z);
    EXPECT_EQ(z.diagnostics.back().col, 10) << messages(z);
    EXPECT_NE(z.diagnostics.back().message.find("ZeroDivisionError"), std::string::npos);
    // A syntax error in the Python of a rule: its line.
    lpy::Model s = lpy::runModel("Axiom: A\nderivation length: 1\nproduction:\nA :\n    if True\n        produce B\nendlsystem\n", o);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.diagnostics.back().line, 5) << messages(s);
    EXPECT_NE(s.diagnostics.back().message.find("SyntaxError"), std::string::npos);
    // An import that is missing.
    lpy::Model i = lpy::runModel("import no_such_module_here\nAxiom: A\nproduction:\nA --> B\n", o);
    ASSERT_FALSE(i.ok());
    EXPECT_EQ(i.diagnostics.back().line, 1);
    EXPECT_NE(i.diagnostics.back().message.find("no_such_module_here"), std::string::npos);
}

TEST(Lpy, CancelStopsAnEndlessLoopInARule) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string text = "Axiom: A\nderivation length: 1\nproduction:\nA :\n    while True:\n        pass\nendlsystem\n";
    std::atomic<bool> cancel{false};
    lpy::RunOptions o;
    o.cancel = &cancel;
    std::chrono::steady_clock::time_point cancelledAt;
    std::thread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        cancelledAt = std::chrono::steady_clock::now();
        cancel = true;
    });
    lpy::Model m = lpy::runModel(text, o);
    const auto stopped = std::chrono::steady_clock::now();
    stopper.join();
    EXPECT_TRUE(m.cancelled) << messages(m);
    EXPECT_FALSE(m.ok());
    const double ms = std::chrono::duration<double, std::milli>(stopped - cancelledAt).count();
    std::printf("cancel: Python stopped %.1f ms after Cancel\n", ms);
    EXPECT_LT(ms, 2000) << "Cancel must stop a rule's endless loop (the bar is 100 ms on an idle machine)";
    // The interpreter is usable again after a cancel.
    lpy::Model again = lpy::runModel("Axiom: A\nderivation length: 1\nproduction:\nA --> B\n", {});
    EXPECT_EQ(again.derived, "B") << messages(again);
}

// The native path's big steps are shared with a second thread (from 8 k modules), its rules
// of the form x * a + b written without Sprout's expressions, the others with them: the same
// string as Python's, module for module, and the same origins for growth stepping.
TEST(Lpy, BigNativeStepsDeriveAsPython) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string text =
        "Axiom: A(1) B(2, 0.5) [ C ] D(3) G(1.5)\n"
        "derivation length: 9\n"
        "production:\n"
        "A(x) --> A(x + 1) B(x, x * 0.5) A(2 - x) [ E(7) A(x * 3) ]\n"  // x + c, c - x, x * c, constants
        "B(x, y) --> B(y, x - 1.5) E(x / 4)\n"                         // x / c: an expression
        "B(x) --> E(x)\n"                                              // B by its arity
        "C --> C E(1) C\n"                                             // a constant without x
        "D(n) --> D(n * 2) F\n"
        "E(v) --> E(0 - v)\n"
        "G(v) --> G(-v) G((v + 1) * 2)\n"
        "endlsystem\n";
    lpy::RunOptions o;
    lpy::Model native = lpy::runModel(text, o);
    ASSERT_TRUE(native.ok()) << messages(native);
    EXPECT_TRUE(native.ranNative);
    ASSERT_TRUE(native.drawable);
    EXPECT_GT(native.drawable->axiom.size(), 15000u) << "big enough for shared steps";
    o.native = false;
    lpy::Model python = lpy::runModel(text, o);
    ASSERT_TRUE(python.ok()) << messages(python);
    EXPECT_FALSE(python.ranNative);
    EXPECT_TRUE(native.derived == python.derived) << "the strings differ (" << native.derived.size() << " and "
                                                  << python.derived.size() << " characters)";
    EXPECT_TRUE(python.drawable->axiom.symbols == native.drawable->axiom.symbols &&
                python.drawable->axiom.params == native.drawable->axiom.params);
    // Growth stepping: where modules came from, natively as in Python.
    o.steps = 8;
    expectSameLineage(text, o, 97);
}

// Python's ints are exact past 2^53, doubles are not: a native run whose numbers grow past it
// goes to Python, also where the native path's unchecked arithmetic (x + c on numbers too
// small to reach 2^53) ran the steps before, on a string big enough to be shared.
TEST(Lpy, NativeIntsPastTwoToThe53AreLeftToPython) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string text =
        "Axiom: A(1) C\n"
        "derivation length: 10\n"
        "production:\n"
        "A(x) --> A(x + 1000000000000000)\n"
        "C --> D D D D D D D D D D D D D D D D\n"
        "D --> E E E E E E E E E E E E E E E E\n"
        "E --> H H H H H H H H H H H H H H H H\n"
        "H --> I I I I I I I I I I I I I I I I\n"
        "endlsystem\n";
    lpy::RunOptions o;
    o.steps = 9;  // 9000000000000001: below 2^53 (9007199254740992), exact in a double
    lpy::Model below = lpy::runModel(text, o);
    ASSERT_TRUE(below.ok()) << messages(below);
    EXPECT_TRUE(below.ranNative);
    EXPECT_EQ(below.derived, "A(9000000000000001)" + std::string(65536, 'I'));
    o.steps = 10;  // 10000000000000001: past it, and odd (a double would say ...000)
    lpy::Model past = lpy::runModel(text, o);
    ASSERT_TRUE(past.ok()) << messages(past);
    EXPECT_FALSE(past.ranNative);
    EXPECT_EQ(past.derived, "A(10000000000000001)" + std::string(65536, 'I'));
}

TEST(Lpy, AModelOfTooManyShapesDerivesInPython) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // The native string's modules are shapes (class, count, which numbers are ints), all found
    // before the derivation. A swap and a turn of 20 numbers, 10 of them ints, lead to
    // 184,756 shapes, past the 65,536 a derivation may have: the model runs in Python.
    const std::string many = "Axiom: A(1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5)\nderivation length: 2\nproduction:\n"
                             "A(a, b, c, d, e, f, g, h, i, j, k, l, m, n, o, p, q, r, s, t) --> A(b, a, c, d, e, f, g, h, i, j, k, l, m, n, o, p, q, r, s, t) A(b, c, d, e, f, g, h, i, j, k, l, m, n, o, p, q, r, s, t, a)\nendlsystem\n";
    // A swap of an int and a float: two shapes, native.
    const std::string two = "Axiom: A(1, 0.5)\nderivation length: 3\nproduction:\nA(a, b) --> A(b, a) A(a, b)\nendlsystem\n";
    lpy::RunOptions python;
    python.native = false;
    for (const std::string* text : {&many, &two}) {
        lpy::Model m = lpy::runModel(*text, {}), p = lpy::runModel(*text, python);
        ASSERT_TRUE(m.ok() && p.ok()) << messages(m) << messages(p);
        EXPECT_EQ(m.ranNative, text == &two);
        EXPECT_EQ(m.derived, p.derived);
        EXPECT_EQ(m.derived.substr(0, 9), text == &two ? "A(0.5,1)A" : "A(1,1,1,1");
    }
}

TEST(Lpy, TheModelIsDrawnInLpysFrame) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    // L-Py's turtle heads up (+Z, Sprout's +Y), turns 60 degrees by default, and `_(w)` sets a radius.
    lpy::Model m = lpy::runModel("Axiom: _(0.5) F(2) + F(1)\nderivation length: 0\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    ASSERT_EQ(geo.cylinders.size(), 2u);
    EXPECT_NEAR(geo.cylinders[0].end.y, 2.0f, 1e-5f);
    EXPECT_NEAR(geo.cylinders[0].startRadius, 0.5f, 1e-5f);
    EXPECT_NEAR(std::hypot(geo.cylinders[1].end.x, geo.cylinders[1].end.z), std::sin(60 * 3.14159265 / 180), 1e-4);
    EXPECT_NEAR(geo.cylinders[1].end.y, 2 + 0.5, 1e-4);
}

// Cross-sections (PlantGL's SetContour and Sweep): a tube after SetContour(curve) has that
// curve's shape, scaled by the width; an open curve sweeps a surface (a leaf blade), a closed
// one a capped tube. Sweep(path, section, length, dl, radius, function) is SetGuide, SetContour
// and nF together, its width radius times the function from its first x to its last. And nF
// with a radius ramps the width to it.
TEST(Lpy, SectionsAndSweepsAreSweptAsInPlantGL) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    auto draw = [](const std::string& axiom, Geometry& geo) {
        lpy::Model m = lpy::runModel("from openalea.plantgl.all import *\n"
                                     "blade = Polyline2D([(-1, 0), (1, 0)])\nstraight = Polyline2D([(0, 0), (1, 0)])\n"
                                     "ramp = QuantisedFunction([(0, 0), (1, 1)])\n"
                                     "Axiom: " + axiom + "\nderivation length: 0\nproduction:\nendlsystem\n", {});
        ASSERT_TRUE(m.ok()) << messages(m);
        EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
        TurtleOptions to;
        interpret(m.drawable->axiom, *m.drawable, to, geo);
    };
    {
        SCOPED_TRACE("a blade swept straight up, 2 long, 0.3 either side at the top, 0 at the foot");
        Geometry geo;
        draw("Sweep(straight, blade, 2, 0.5, 0.3, ramp)", geo);
        EXPECT_TRUE(geo.cylinders.empty());
        const Mesh& m = geo.polygons;
        ASSERT_FALSE(m.positions.empty());
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& q : m.positions) lo = glm::min(lo, q), hi = glm::max(hi, q);
        EXPECT_NEAR(lo.y, 0, 1e-4f);  // along the heading (L-Py's z)
        EXPECT_NEAR(hi.y, 2, 1e-4f);
        EXPECT_NEAR(lo.x, -0.3f, 1e-3f);  // across, along the left (L-Py's y)
        EXPECT_NEAR(hi.x, 0.3f, 1e-3f);
        EXPECT_NEAR(lo.z, 0, 1e-5f);  // no thickness: an open section is a surface
        EXPECT_NEAR(hi.z, 0, 1e-5f);
        // Two points a ring: a strip of two triangles between rings, no caps.
        EXPECT_EQ(m.indices.size() / 3, 2 * (m.positions.size() / 2 - 1));
        // The foot is a point (the ramp's 0), the top full width.
        float footWidth = 0, topWidth = 0;
        for (const glm::vec3& q : m.positions) {
            if (q.y < 1e-4f) footWidth = std::max(footWidth, std::fabs(q.x));
            if (q.y > 2 - 1e-4f) topWidth = std::max(topWidth, std::fabs(q.x));
        }
        EXPECT_NEAR(footWidth, 0, 1e-4f);
        EXPECT_NEAR(topWidth, 0.3f, 1e-3f);
    }
    {
        SCOPED_TRACE("a closed section in a generalized cylinder: a square tube, capped");
        Geometry geo;
        draw("_(0.5) SetContour(Polyline2D([(1, 1), (-1, 1), (-1, -1), (1, -1), (1, 1)])) @Gc F(1) F(1) @Ge", geo);
        const Mesh& m = geo.polygons;
        ASSERT_FALSE(m.positions.empty());
        float corner = 0;
        for (const glm::vec3& q : m.positions) corner = std::max(corner, std::hypot(q.x, q.z));
        EXPECT_NEAR(corner, 0.5f * std::sqrt(2.0f), 1e-3f) << "the square's corners, 0.5 from the axis each way";
        // Rings of 4 (the repeated last point dropped); 8 triangles between two rings; caps.
        const size_t capVertices = 2 * 5, rings = (m.positions.size() - capVertices) / 4;
        EXPECT_EQ(m.indices.size() / 3, 8 * (rings - 1) + 2 * 4);
    }
    {
        SCOPED_TRACE("nF with a radius: the width ramps from 0.1 to it");
        Geometry geo;
        draw("nF(2, 0.5, 0.4)", geo);
        ASSERT_EQ(geo.cylinders.size(), 4u);
        EXPECT_NEAR(geo.cylinders[0].startRadius, 0.1f, 1e-5f);
        EXPECT_NEAR(geo.cylinders[3].endRadius, 0.4f, 1e-5f);
        EXPECT_NEAR(geo.cylinders[1].endRadius, 0.25f, 1e-5f);
    }
}

// The rest of PlantGL's turtle that moves or points it: MoveRel, LineRel and OLineRel by a
// vector, Pinpoint and PinpointRel (the heading turned to a point or a direction by the least
// rotation, as OLineTo's and OLineRel's), Frame (three arrows: heading red, up blue, left
// green) and InterpolateColors (a colour between two materials). L-Py's x, y, z are Sprout's
// z, x, y.
TEST(Lpy, RelativeMovesPinpointsFramesAndMixedColours) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    auto draw = [](const std::string& axiom, Geometry& geo, std::shared_ptr<const Grammar>* drawn = nullptr) {
        lpy::Model m = lpy::runModel("Axiom: " + axiom + "\nderivation length: 0\nproduction:\nendlsystem\n", {});
        ASSERT_TRUE(m.ok()) << messages(m);
        EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
        TurtleOptions to;
        interpret(m.drawable->axiom, *m.drawable, to, geo);
        if (drawn) *drawn = m.drawable;
    };
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-4f; };
    {
        Geometry geo;
        draw("MoveRel(0, 0, 3) F(1) LineRel(1, 0, 0) OLineRel(0, 1, 0) F(1)", geo);
        ASSERT_EQ(geo.cylinders.size(), 4u);
        EXPECT_TRUE(near(geo.cylinders[0].start, {0, 3, 0})) << "moved up 3 without drawing";
        EXPECT_TRUE(near(geo.cylinders[1].end, {0, 4, 1})) << "a line by L-Py's +x, heading kept";
        EXPECT_TRUE(near(geo.cylinders[2].end, {1, 4, 1})) << "a line by L-Py's +y";
        EXPECT_TRUE(near(geo.cylinders[3].end, {2, 4, 1})) << "and the heading turned along it";
    }
    {
        Geometry geo;
        draw("[Pinpoint(1, 0, 1) F(1)] [PinpointRel(0, 0, -1) F(1)] f(1) Pinpoint(0, 0, 0) F(1)", geo);
        ASSERT_EQ(geo.cylinders.size(), 3u);
        const float h = std::sqrt(0.5f);
        EXPECT_TRUE(near(geo.cylinders[0].end, {0, h, h})) << "towards the point (1, 0, 1)";
        EXPECT_TRUE(near(geo.cylinders[1].end, {0, -1, 0})) << "straight behind: half a turn";
        EXPECT_TRUE(near(geo.cylinders[2].end, {0, 0, 0})) << "back to the origin from 1 above it";
    }
    {
        Geometry geo;
        std::shared_ptr<const Grammar> g;
        draw("_(0.05) Frame(2) InterpolateColors(3, 5, 0.5) F(1)", geo, &g);
        // Three arrows (a stick and a cone each), then the stem.
        ASSERT_EQ(geo.cylinders.size(), 7u);
        const std::uint32_t red = 0xFA3232FFu, blue = 0x3232FAFFu, green = 0x32FA32FFu;
        EXPECT_EQ(geo.cylinders[0].colour, red);
        EXPECT_TRUE(near(geo.cylinders[1].end, {0, 2, 0})) << "the heading's arrow";
        EXPECT_NEAR(geo.cylinders[1].startRadius, 0.1f, 1e-5f) << "its cone twice the width";
        EXPECT_NEAR(geo.cylinders[1].endRadius, 0, 1e-5f);
        EXPECT_NEAR(geo.cylinders[0].endRadius, 0.05f, 1e-5f) << "its stick the width";
        EXPECT_EQ(geo.cylinders[2].colour, blue);
        EXPECT_TRUE(near(geo.cylinders[3].end, {0, 0, 2})) << "the up arrow (L-Py's +x)";
        EXPECT_EQ(geo.cylinders[4].colour, green);
        EXPECT_TRUE(near(geo.cylinders[5].end, {-2, 0, 0})) << "the left arrow (L-Py's -y)";
        // Materials 3 (red 60,0,0) and 5 (blue 0,0,60), each times 3: half of each.
        const std::uint32_t c = geo.cylinders[6].colour;
        EXPECT_EQ(c, 0x5A005AFFu) << std::hex << c;
    }
}

// @g(shape[, scale]): a PlantGL shape at the turtle, in its frame (the shape's x along the
// turtle's up, y to its right, z along its heading: PlantGL's PglTurtle::transform), with the
// turtle's colour; wrappers
// (Scaled, Translated, AxisRotated, ...) applied. A curve is drawn as stems along it; text is
// not drawn: a warning names it.
TEST(Lpy, PlantGLShapesAreDrawnAtTheTurtle) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("from openalea.plantgl.all import *\n"
                                 "Axiom: [@M(0, 2, 1) @g(Box(1, 0.2, 0.5))] [@M(0, 0, 5) @g(Scaled(2, Sphere(1)), 0.5)]"
                                 " @g(Text('no')) f(10) @g(Polyline([(0, 0, 0), (1, 0, 0), (1, 0, 2)]))\nderivation length: 0\n"
                                 "production:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    ASSERT_EQ(m.diagnostics.size(), 1u) << messages(m);
    EXPECT_NE(m.diagnostics[0].message.find("@g with text"), std::string::npos) << messages(m);
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    // The polyline, 10 above the origin: 1 along the up (L-Py's x, Sprout's z), then 2 along
    // the heading (Sprout's y).
    ASSERT_EQ(geo.cylinders.size(), 2u);
    EXPECT_NEAR(glm::length(geo.cylinders[0].start - glm::vec3(0, 10, 0)), 0, 1e-4f);
    EXPECT_NEAR(glm::length(geo.cylinders[0].end - glm::vec3(0, 10, 1)), 0, 1e-4f);
    EXPECT_NEAR(glm::length(geo.cylinders[1].end - glm::vec3(0, 12, 1)), 0, 1e-4f);
    const Mesh& mesh = geo.polygons;
    ASSERT_FALSE(mesh.indices.empty());
    // The box at L-Py (0, 2, 1), Sprout (2, 1, 0): half sizes 1 along the up (Sprout z), 0.2
    // to the right (L-Py's y, Sprout's x), 0.5 along the heading (Sprout y).
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& q : mesh.positions)
        if (q.y < 3) lo = glm::min(lo, q), hi = glm::max(hi, q);
    EXPECT_NEAR(lo.x, 1.8f, 1e-4f);
    EXPECT_NEAR(hi.x, 2.2f, 1e-4f);
    EXPECT_NEAR(lo.y, 0.5f, 1e-4f);
    EXPECT_NEAR(hi.y, 1.5f, 1e-4f);
    EXPECT_NEAR(lo.z, -1, 1e-4f);
    EXPECT_NEAR(hi.z, 1, 1e-4f);
    // The sphere at L-Py (0, 0, 5), Sprout (0, 5, 0): radius 1, scaled by 2, then by @g's 0.5.
    float r = 0;
    for (const glm::vec3& q : mesh.positions)
        if (q.y > 3 && q.y < 7) r = std::max(r, glm::length(q - glm::vec3(0, 5, 0)));
    EXPECT_NEAR(r, 1, 1e-3f);
    // The turtle's colour: L-Py's material 1.
    EXPECT_EQ(mesh.colours[0], 0xC3872DFFu);  // (65, 45, 15) times its diffuse, 3
}

// Where a context matched is kept with the steps (the derivation inspector's "context
// matched"): L-Py's rules are Python, so the record keeps it as the run matched it. A signal
// moving right (a left context), and a right context that skips a branch.
TEST(Lpy, TheRecordKeepsWhereContextsMatched) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::RunOptions o;
    o.keepSteps = true;
    lpy::Model m = lpy::runModel("Axiom: B A A A\nderivation length: 2\nproduction:\nB < A --> B\nB --> A\nendlsystem\n", o);
    ASSERT_TRUE(m.ok()) << messages(m);
    EXPECT_EQ(m.derived, "AABA");
    ASSERT_EQ(m.record.contexts.size(), 3u);
    EXPECT_FALSE(m.record.contexts[0]) << "the axiom";
    std::vector<std::size_t> left, right;
    ASSERT_TRUE(m.record.contexts[1] && m.record.contexts[1]->find(1, left, right));  // A B A A: the A at 1 saw B
    EXPECT_EQ(left, std::vector<std::size_t>{0});
    EXPECT_TRUE(right.empty());
    EXPECT_FALSE(m.record.contexts[1]->find(0, left, right)) << "B --> A has no context";
    EXPECT_FALSE(m.record.contexts[1]->find(2, left, right)) << "no rule rewrote it";
    ASSERT_TRUE(m.record.contexts[2]->find(2, left, right));  // A A B A: the A at 2 saw the B at 1
    EXPECT_EQ(left, std::vector<std::size_t>{1});
    // The lineage's origins say the same module: step 2's B came from step 1's module 2.
    EXPECT_EQ(m.record.origins[2]->parent.data()[2], 2u);
    lpy::Model r = lpy::runModel("Axiom: A [ B ] C\nderivation length: 1\nproduction:\nA > C --> D\nendlsystem\n", o);
    ASSERT_TRUE(r.ok()) << messages(r);
    EXPECT_EQ(r.derived, "D[B]C");
    ASSERT_TRUE(r.record.contexts.size() == 2 && r.record.contexts[1]->find(0, left, right));
    EXPECT_TRUE(left.empty());
    EXPECT_EQ(right, std::vector<std::size_t>{4}) << "the branch [ B ] skipped";
}

// PlantGL's AsymmetricHull (a crown: four radii, four heights, a bottom and a top point, the
// shapes of its lower and upper parts) as PlantGL's discretizer makes it, in @g's frame.
TEST(Lpy, AsymmetricHullIsACrownThroughItsPoints) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("from openalea.plantgl.all import *\n"
                                 "Axiom: f(20) @g(AsymmetricHull(1, 2, 3, 4, 0.5, 1.0, 1.5, 2.0, (0, 0, 0), (0, 0, 6), 3, 1))\n"
                                 "derivation length: 0\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    const Mesh& mesh = geo.polygons;
    // 4 slices x 4 quadrants meridians of 2 x 4 - 1 points, the bottom and the top; a fan at
    // each end and a strip of 2 x (7 - 1) triangles between neighbouring meridians.
    EXPECT_EQ(mesh.positions.size(), 16u * 7 + 2);
    EXPECT_EQ(mesh.indices.size(), 3u * 16 * (2 + 2 * 6));
    // PlantGL's frame at the turtle: x its up (Sprout z), y its right (Sprout x), z its heading
    // (Sprout y), 20 along it. The four points: +x radius 2 at height 1, +y radius 4 at height 2,
    // -x radius 1 at height 0.5, -y radius 3 at height 1.5; the bottom and the top.
    auto has = [&](glm::vec3 p) {
        for (const glm::vec3& q : mesh.positions)
            if (glm::length(q - p) < 1e-4f) return true;
        return false;
    };
    EXPECT_TRUE(has({0, 21, 2}));
    EXPECT_TRUE(has({4, 22, 0}));
    EXPECT_TRUE(has({0, 20.5f, -1}));
    EXPECT_TRUE(has({-3, 21.5f, 0}));
    EXPECT_TRUE(has({0, 20, 0}));
    EXPECT_TRUE(has({0, 26, 0}));
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& q : mesh.positions) lo = glm::min(lo, q), hi = glm::max(hi, q);
    EXPECT_NEAR(lo.x, -3, 1e-4f);
    EXPECT_NEAR(hi.x, 4, 1e-4f);
    EXPECT_NEAR(lo.y, 20, 1e-4f);
    EXPECT_NEAR(hi.y, 26, 1e-4f);
    EXPECT_NEAR(lo.z, -1, 1e-4f);
    EXPECT_NEAR(hi.z, 2, 1e-4f);
    // The lower part's shape 3: halfway out from the bottom towards the +x point (2, 0, 1),
    // the height is 1 * 0.5^3 (stack 2 of 4); the upper part's shape 1: straight to the top.
    EXPECT_TRUE(has({0, 20.125f, 1}));
    EXPECT_TRUE(has({0, 1 + 20 + 5 * 0.5f, 1}));
}

// A text past 200 bytes is cut where a character begins: what is kept stays UTF-8 (an
// exported model carries it).
TEST(Lpy, LongLabelsAreCutWhereACharacterBegins) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("Axiom: F @L('" + std::string(199, 'a') + "\u00e9\u00e9')\nderivation length: 0\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    ASSERT_EQ(m.drawable->settings.labels.size(), 1u);
    EXPECT_EQ(m.drawable->settings.labels[0], std::string(199, 'a')) << "not half of the first \u00e9";
}

// @L(text[, size]): a text at the turtle (its str() for a number), kept with the drawing.
TEST(Lpy, LabelsAreKeptAtTheTurtle) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("Axiom: F(2) @L('top') [+(90) F(1) @L(3.5, 26)] @L('top')\n"
                                 "derivation length: 0\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
    EXPECT_EQ(m.drawable->settings.labels.size(), 2u) << "each text once";
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    ASSERT_EQ(geo.labels.size(), 3u);
    EXPECT_EQ(geo.labels[0].text, "top");
    EXPECT_NEAR(geo.labels[0].position.y, 2, 1e-5f);
    EXPECT_NEAR(geo.labels[0].size, 13, 1e-5f);
    EXPECT_EQ(geo.labels[1].text, "3.5");
    EXPECT_NEAR(geo.labels[1].size, 26, 1e-5f);
    EXPECT_NEAR(geo.labels[1].position.x, -1, 1e-5f);  // turned left: L-Py's -y
    EXPECT_EQ(geo.labels[2].text, "top");
}

// L-Py's rolls: `/` is RollL, about the heading by +angle, which takes the left axis towards
// up (PlantGL's rollL); `\` is RollR. So /(90) then +(90) heads along the first up (L-Py's
// +x, Sprout's +z), and \(90) then +(90) the other way; iRollL and iRollR turn alike.
TEST(Lpy, RollsTurnAsInLpy) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::pair<const char*, float> cases[] = {{"/(90) +(90) F", 1}, {"\\(90) +(90) F", -1},
                                                   {"iRollL(90) +(90) F", 1}, {"iRollR(90) +(90) F", -1}};
    for (const auto& [axiom, z] : cases) {
        SCOPED_TRACE(axiom);
        lpy::Model m = lpy::runModel(std::string("Axiom: ") + axiom + "\nderivation length: 0\nproduction:\nendlsystem\n", {});
        ASSERT_TRUE(m.ok()) << messages(m);
        Geometry geo;
        TurtleOptions to;
        interpret(m.drawable->axiom, *m.drawable, to, geo);
        ASSERT_EQ(geo.cylinders.size(), 1u);
        EXPECT_NEAR(geo.cylinders[0].end.z, z, 1e-5f);
        EXPECT_NEAR(geo.cylinders[0].end.x, 0, 1e-5f);
        EXPECT_NEAR(geo.cylinders[0].end.y, 0, 1e-5f);
    }
}

// Elasticity and tropism: before each step H turns towards the tropism vector by e times the
// angle between them (L-Py's x is Sprout's z, its z Sprout's y).
TEST(Lpy, TropismBendsBeforeEachStep) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    lpy::Model m = lpy::runModel("Axiom: @Tp(1, 0, 0) @Ts(0.5) F [ Elasticity(0) F ] F\nderivation length: 0\nproduction:\nendlsystem\n", {});
    ASSERT_TRUE(m.ok()) << messages(m);
    Geometry geo;
    TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
    ASSERT_EQ(geo.cylinders.size(), 3u);
    const float s45 = std::sqrt(0.5f);
    EXPECT_NEAR(geo.cylinders[0].end.z, s45, 1e-4f);  // 45 degrees: half of 90
    EXPECT_NEAR(geo.cylinders[0].end.y, s45, 1e-4f);
    // In the branch, no elasticity: straight on at 45 degrees.
    EXPECT_NEAR(geo.cylinders[1].end.z - geo.cylinders[1].start.z, s45, 1e-4f);
    // After it, elasticity 0.5 again: half of the 45 degrees left, at 67.5 degrees.
    EXPECT_NEAR(geo.cylinders[2].end.z - geo.cylinders[2].start.z, std::sin(67.5f * 3.14159265f / 180), 1e-4f);
    EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
}

// SetGuide: the F and f after it follow the curve, scaled to the length given (PlantGL's
// Turtle2DPath and Turtle3DPath). A 2D curve's x is the heading at the start and its y the up;
// with its third argument (yOrientation) its y is the heading and its x the right. A 3D curve's
// z is the heading at the start, its x the up and its y the right, and intrinsic rolls (iRollL,
// iRollR) turn the curve's frame with the turtle's, so the stem still traces the curve. L-Py's
// x, y, z are Sprout's z, x, y; the turtle starts with heading +z, up +x and left -y (L-Py's).
TEST(Lpy, AGuideIsFollowed) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const std::string models[] = {
        "from openalea.plantgl.all import *\npath = Polyline2D([(0, 0), (1, 0), (1, 1)])\n"
        "Axiom: SetGuide(path, 4) nF(4, 0.25)\nderivation length: 0\nproduction:\nendlsystem\n",
        "from openalea.plantgl.all import *\npath = Polyline2D([(0, 0), (1, 0), (1, 1)])\n"
        "Axiom: SetGuide(path, 2, True) nF(2, 0.25)\nderivation length: 0\nproduction:\nendlsystem\n",
        "from openalea.plantgl.all import *\npath = NurbsCurve([(0, 0, 0, 1), (0, 0, 1, 1), (1, 0, 1, 1), (1, 2, 1, 1)], degree=1)\n"
        "Axiom: SetGuide(path, 4) F(.5) iRollL(37) F(.5) iRollR(80) F(.5) F(.5) iRollL(10) F(.5) F(.5) iRollR(33) F(.5) F(.5)\n"
        "derivation length: 0\nproduction:\nendlsystem\n",
    };
    // Where the stem is after half its steps and at its end, in Sprout's axes.
    const glm::vec3 expected[][2] = {{{0, 2, 0}, {0, 2, 2}}, {{1, 0, 0}, {1, 1, 0}}, {{0, 1, 1}, {2, 1, 1}}};
    for (int c = 0; c < 3; ++c) {
        SCOPED_TRACE(models[c]);
        lpy::Model m = lpy::runModel(models[c], {});
        ASSERT_TRUE(m.ok()) << messages(m);
        EXPECT_TRUE(m.diagnostics.empty()) << messages(m);
        Geometry geo;
        TurtleOptions to;
        interpret(m.drawable->axiom, *m.drawable, to, geo);
        const size_t n = c == 0 ? 16 : 8;
        ASSERT_EQ(geo.cylinders.size(), n);
        const float tolerance = c == 2 ? 0.03f : 1e-3f;  // the 3D curve's corners sampled 200 times along it
        for (int k = 0; k < 2; ++k) {
            const glm::vec3 at = geo.cylinders[k ? n - 1 : n / 2 - 1].end;
            EXPECT_NEAR(at.x, expected[c][k].x, tolerance) << k;
            EXPECT_NEAR(at.y, expected[c][k].y, tolerance) << k;
            EXPECT_NEAR(at.z, expected[c][k].z, tolerance) << k;
        }
    }
}

// L-Py's own examples: each opens and draws, or names what it needs at its line.
TEST(Lpy, CorpusOpensAndDraws) {
    if (!lpy::pythonAvailable()) GTEST_SKIP() << "built without Python";
    const fs::path dir = fs::path(SPROUT_SHARED_DIR) / "corpus" / "lpy";
    if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " is not here";
    int total = 0, drawn = 0;
    std::string failures;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (e.path().extension() != ".lpy") continue;
        ++total;
        lpy::RunOptions o;
        o.path = e.path().string();
        lpy::Model m = lpy::runModel(slurp(e.path()), o);
        bool ok = m.ok();
        if (ok) {
            Geometry geo;
            TurtleOptions to;
    interpret(m.drawable->axiom, *m.drawable, to, geo);
            ok = !geo.cylinders.empty() || !geo.surfaces.empty() || !geo.polygons.indices.empty();
            if (!ok) failures += e.path().filename().string() + ": draws nothing\n";
        } else {
            const Diagnostic* err = nullptr;
            for (const auto& d : m.diagnostics)
                if (d.severity == Severity::Error) err = &d;
            ASSERT_NE(err, nullptr) << e.path() << " failed without an error";
            failures += formatDiagnostic(*err, e.path().filename().string()) + "\n";
        }
        drawn += ok;
    }
    std::printf("L-Py corpus: %d of %d models open and draw\n%s", drawn, total, failures.c_str());
    EXPECT_EQ(total, 127);
    EXPECT_GE(drawn, SPROUT_LPY_CORPUS_BAR) << failures;
}

}  // namespace
}  // namespace sprout
