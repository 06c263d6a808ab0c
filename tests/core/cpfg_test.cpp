// tests/cpfg: small cpfg / L-Py family files written for Sprout, each carrying what it must
// give in comment lines:
//   // expect N: STRING     step N as `sprout expand` prints it, character by character
//   // draws N: STRING      step N after the homomorphism: what the turtle draws
//   // warning L: MESSAGE   a warning on line L (every warning must be listed)
//   // n: N                 the derivation length the file sets
// Every file must be recognised as the cpfg family by its content, not its name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <glm/geometric.hpp>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/turtle/turtle.hpp"
#include "tests/core/test_util.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

using test::slurp;

std::vector<fs::path> cpfgFiles() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(SPROUT_CPFG_DIR))
        if (e.path().extension() == ".l" || e.path().extension() == ".lpy") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// One annotated file: parsed with `options`, its warnings, derivation length and strings
// checked against its comment lines (and its dialect, with a `// dialect: NAME` line).
// Returns the number of strings checked.
int checkAnnotatedFile(const fs::path& path, const ParseOptions& options) {
    static const std::regex expectLine(R"(^// (expect|draws) (\d+): (.*)$)"), warningLine(R"(^// warning (\d+): (.*)$)"),
        nLine(R"(^// n: (\d+)$)"), dialectLine(R"(^// dialect: (.*)$)");
    SCOPED_TRACE(path.filename().string());
    const std::string text = slurp(path);
    ParseResult r = parse(text, options);
    std::set<std::string> warnings;
    for (const auto& d : r.diagnostics) {
        if (d.severity == Severity::Error) ADD_FAILURE() << formatDiagnostic(d, path.filename().string());
        else warnings.insert(std::to_string(d.line) + ": " + d.message);
    }
    if (!r.ok()) {
        ADD_FAILURE() << "does not parse";
        return 0;
    }
    std::set<std::string> expectedWarnings;
    std::istringstream lines(text);
    int checked = 0;
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_match(line, m, warningLine)) {
            expectedWarnings.insert(m[1].str() + ": " + m[2].str());
        } else if (std::regex_match(line, m, nLine)) {
            EXPECT_EQ(r.grammar->settings.iterations, std::stoi(m[1].str()));
        } else if (std::regex_match(line, m, dialectLine)) {
            EXPECT_EQ(r.grammar->dialect, m[1].str());
        } else if (std::regex_match(line, m, expectLine)) {
            const int n = std::stoi(m[2].str());
            DeriveResult d = derive(r.grammar, n);
            if (!d.outcome.ok()) {
                ADD_FAILURE() << d.outcome.message;
                return checked;
            }
            const ModuleString shown = m[1] == "draws" ? applyInterpretation(*r.grammar, *d.string, r.grammar->settings.seed)
                                                       : *d.string;
            EXPECT_EQ(toString(shown, r.grammar->alphabet), m[3].str()) << m[1] << " " << n;
            ++checked;
        }
    }
    EXPECT_GT(checked, 0) << "no '// expect N: STRING' line";
    EXPECT_EQ(warnings, expectedWarnings);
    return checked;
}

TEST(Cpfg, EveryFileDerivesWhatItSays) {
    const auto files = cpfgFiles();
    ASSERT_GE(files.size(), 40u) << "tests/cpfg holds the cpfg-family test files";
    int checked = 0;
    for (const auto& path : files) {
        const std::string text = slurp(path);
        EXPECT_TRUE(cpfgFamily(detectFileKind(path.string(), text))) << path.filename();
        checked += checkAnnotatedFile(path, parseOptionsFor(FileKind::Cpfg, path.string()));
    }
    EXPECT_GE(checked, 80);
}

// tests/explorer: L-system Explorer's constructs (`.ls` files written for Sprout), read as a
// user opens them: the kind from the content and the name, that tool's defaults.
TEST(Explorer, EveryFileDerivesWhatItSays) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(SPROUT_EXPLORER_DIR))
        if (e.path().extension() == ".ls") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 10u);
    int checked = 0;
    for (const auto& path : files) {
        const std::string text = slurp(path);
        const FileKind kind = detectFileKind(path.string(), text);
        ASSERT_TRUE(kind == FileKind::Lsys || kind == FileKind::Cpfg) << path.filename() << ": " << fileKindName(kind);
        const ParseOptions o = parseOptionsFor(kind, path.string());
        EXPECT_TRUE(o.explorer) << path.filename();
        checked += checkAnnotatedFile(path, o);
    }
    EXPECT_GE(checked, 15);
}

// L-system Explorer's `{(0)` ... `}` path is the tube `@Gs` ... `@Ge` makes through the same
// points; `{` without a parameter stays a polygon.
TEST(Explorer, BracePathIsTheTubeOfAGeneralizedCylinder) {
    auto geometryOf = [](const std::string& text) {
        ParseOptions o = parseOptionsFor(FileKind::Cpfg, "path.ls");
        ParseResult r = parse(text, o);
        EXPECT_TRUE(r.ok());
        EXPECT_TRUE(r.grammar->settings.bracePaths);
        Geometry g;
        interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
        return g;
    };
    const Geometry path = geometryOf("derivation length: 0\nwidth: 0.5\naxiom: {(0)F(1)+(30)F(1)+(30)F(1)}\n");
    const Geometry gc = geometryOf("derivation length: 0\nwidth: 0.5\naxiom: @Gs F(1)+(30)F(1)+(30)F(1)@Ge\n");
    EXPECT_EQ(path.cylinders.size(), 0u);
    ASSERT_GT(path.polygons.positions.size(), 24u);
    ASSERT_EQ(path.polygons.positions.size(), gc.polygons.positions.size());
    for (size_t k = 0; k < gc.polygons.positions.size(); ++k)
        EXPECT_NEAR(glm::length(path.polygons.positions[k] - gc.polygons.positions[k]), 0.0f, 1e-5f) << k;
    // A polygon: one flat triangle fan over its four corners, not a tube.
    const Geometry polygon = geometryOf("derivation length: 0\naxiom: {.-f.+f.+f.}\n");
    EXPECT_LE(polygon.polygons.positions.size(), 8u);
    EXPECT_GE(polygon.polygons.positions.size(), 3u);
}

// L-system Explorer's kept surfaces: `{ ... }('leaf')` is kept, not drawn; `~('leaf', s)` draws
// it in the turtle's frame, scaled by s. A number there (`}(0)`) keeps nothing.
TEST(Explorer, KeptPolygonIsDrawnWhereItIsPut) {
    auto geometryOf = [](const std::string& axiom) {
        ParseResult r = parse("derivation length: 0\naxiom: " + axiom + "\n", parseOptionsFor(FileKind::Cpfg, "kept.ls"));
        EXPECT_TRUE(r.ok());
        Geometry g;
        if (r.ok()) interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
        return g;
    };
    const std::string square = "{.-f.+f.+f.}";  // (0,0) (1,0) (1,1) (0,1) with the turtle's heading up
    const Geometry drawn = geometryOf(square);
    ASSERT_EQ(drawn.polygons.positions.size(), 4u);
    EXPECT_EQ(geometryOf(square + "('leaf')").polygons.positions.size(), 0u);
    EXPECT_EQ(geometryOf(square + "(0)").polygons.positions.size(), 4u);
    // The square ends at (0,1) heading -x; f(5) goes to (-5,1) and '+' turns the heading to -y.
    // In the frame at the '{' (heading +y, left -x) the square is (0,0) (-1,0) (-1,1) (0,1),
    // put in the new frame (heading -y, left +x) twice as large.
    const Geometry put = geometryOf(square + "('leaf')f(5)+~('leaf',2)");
    ASSERT_EQ(put.polygons.positions.size(), 4u);
    const glm::vec3 expected[] = {{-5, 1, 0}, {-7, 1, 0}, {-7, -1, 0}, {-5, -1, 0}};
    for (const glm::vec3& e : expected) {
        float nearest = 1e9f;
        for (const glm::vec3& q : put.polygons.positions) nearest = std::min(nearest, glm::length(q - e));
        EXPECT_LT(nearest, 1e-4f) << e.x << " " << e.y;
    }
    EXPECT_EQ(put.polygons.indices.size(), drawn.polygons.indices.size());
}

// L-system Explorer's contours: the points '.' marks between @Cs and @Ce('c') (x and y) are the
// cross-section of the paths started after @#('c'); an unknown name is round.
TEST(Explorer, ContourIsTheCrossSectionOfThePathsAfterIt) {
    auto tubeOf = [](const std::string& axiom) {
        ParseResult r = parse("derivation length: 0\nwidth: 0.5\naxiom: " + axiom + "\n", parseOptionsFor(FileKind::Cpfg, "c.ls"));
        EXPECT_TRUE(r.ok());
        Geometry g;
        if (r.ok()) interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
        return g.polygons;
    };
    const std::string contour = "[@Cs@m(-1,-0.2,0).@m(1,-0.2,0).@m(1,0.2,0).@m(-1,0.2,0).@m(-1,-0.2,0).@Ce('c')]";
    const Mesh round = tubeOf(contour + "@#('none'){(0)F(1)F(1)}");
    const Mesh flat = tubeOf(contour + "@#('c'){(0)F(1)F(1)}");
    ASSERT_FALSE(round.positions.empty());
    ASSERT_FALSE(flat.positions.empty());
    EXPECT_NE(flat.positions.size(), round.positions.size());
    // The flat section is 4 wide and 0.8 deep in radius units (radius 0.25): 1 by 0.2 around the axis.
    float maxX = 0, maxZ = 0;
    for (const glm::vec3& q : flat.positions) maxX = std::max(maxX, std::fabs(q.x)), maxZ = std::max(maxZ, std::fabs(q.z));
    EXPECT_NEAR(std::max(maxX, maxZ), 0.5f, 1e-3f);
    EXPECT_NEAR(std::min(maxX, maxZ), 0.1f, 1e-3f);
}

// The turtle additions draw what they say.
TEST(Cpfg, DiscIsAPolygonAcrossTheHeading) {
    ParseResult r = parse("Axiom: F(2) @c(0.8)\nderivation length: 0\n", parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_EQ(g.polygons.positions.size(), 24u);
    for (const auto& p : g.polygons.positions) {
        EXPECT_NEAR(p.y, 2.0f, 1e-5f);  // across the heading (+Y), at the turtle
        EXPECT_NEAR(std::hypot(p.x, p.z), 0.4f, 1e-5f);  // cpfg's @c(d): a diameter
    }
}

// cpfg's turtle scale (blackbox.c): @D(s) sets it, @Di(s) multiplies, @Dd without a number
// divides by the view file's scale multiplier; F's number, widths and @O's diameter are times
// it; @L("format", x) is a label, not Lparser's length factor.
TEST(Cpfg, TurtleScaleSizesWhatFollowsAndLabelsArePrinted) {
    ParseResult r = parse("Lsystem: 1\nderivation length: 0\n"
                          "Axiom: F(1) @D(2) F(1) #(0.5) F @Di(0.5) F(3) @O(1) @Dd F(1) @L(\"n=%g!\", 3.5) F(1)\nendlsystem\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    auto g = std::make_shared<Grammar>(*r.grammar);
    g->settings.scaleMultiplier = 4;  // the view file's `scale multiplier: 4`
    Geometry out;
    interpret(g->axiom, *g, {0, 1, nullptr}, out);
    ASSERT_EQ(out.cylinders.size(), 6u);
    auto length = [&](size_t k) { return glm::length(out.cylinders[k].end - out.cylinders[k].start); };
    EXPECT_FLOAT_EQ(length(0), 1);    // scale 1
    EXPECT_FLOAT_EQ(length(1), 2);    // @D(2)
    EXPECT_FLOAT_EQ(length(2), 2);    // F: the step times the scale
    EXPECT_FLOAT_EQ(out.cylinders[2].startRadius, 0.5f);  // #(0.5) times 2, a diameter of 1
    EXPECT_FLOAT_EQ(length(3), 3);    // @Di(0.5): scale 1
    EXPECT_FLOAT_EQ(length(4), 0.25f);  // @Dd: 1 / 4
    EXPECT_FLOAT_EQ(length(5), 0.25f);  // @L changes no length
    ASSERT_EQ(out.surfaces.size(), 1u);
    EXPECT_FLOAT_EQ(out.surfaces[0].size, 0.5f);  // @O(1) at scale 1: radius 0.5
    ASSERT_EQ(out.labels.size(), 1u);
    EXPECT_EQ(out.labels[0].text, "n=3.5!");
}

TEST(Cpfg, MoveToStartsANewStemThere) {
    ParseResult r = parse("Axiom: F(1) @M(5,0,0) F(1)\nderivation length: 0\n", parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_EQ(g.cylinders.size(), 2u);
    EXPECT_NEAR(g.cylinders[1].start.x, 5.0f, 1e-6f);
    EXPECT_NEAR(g.cylinders[1].end.y, 1.0f, 1e-6f);
}

// A generalized cylinder is one tube through the turtle's positions: no cylinders, rings of
// 12 vertices at the radius around the curve, which passes through every control point.
// cpfg copies the turtle's generalized cylinder into a branch: each branch's tube goes on from
// the last control point before '[' and ends at its own @Ge (Horneophyton's forking stems).
TEST(Cpfg, GeneralizedCylinderGoesOnIntoEachBranch) {
    ParseResult r = parse("derivation length: 0\nwidth: 0.2\nAxiom: @Gs f(1) @Gc(2) [+(90) f(1) @Ge(2)] [-(90) f(1) @Ge(2)]\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_FALSE(g.polygons.positions.empty());
    float left = 0, right = 0, top = 0;
    for (const auto& p : g.polygons.positions) left = std::min(left, p.x), right = std::max(right, p.x), top = std::max(top, p.y);
    EXPECT_NEAR(left, -1.0f, 0.15f);  // the branches' tubes reach their tips, a step to each side
    EXPECT_NEAR(right, 1.0f, 0.15f);
    EXPECT_LT(top, 1.3f);  // and start at the fork: nothing drawn twice up the stem
}

// cpfg's @Gr radius tangents (general.c): the radius along a span is a Hermite curve in
// (t, radius); here from 0 to 0 with tangents (0, -0.5) and (0, 0.5): 0.5 q^2 - 0.5 q, widest
// (0.125) half way. Without them the tube would have no width (FernLeaf's leaflets).
TEST(Cpfg, RadiusTangentsShapeTheTube) {
    ParseResult r = parse("Lsystem: 1\nderivation length: 0\n"
                          "Axiom: !(0) @Gr(0,0,-90,0.5) @Gs f(1) !(0) @Gr(90,0.5,0,0) @Ge(8)\nendlsystem\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_FALSE(g.polygons.positions.empty());
    float widest = 0;
    for (const auto& p : g.polygons.positions) widest = std::max(widest, std::hypot(p.x, p.z));
    EXPECT_NEAR(widest, 0.125f, 0.005f);
}

// cpfg's tropisms (movements.c): before each F the heading turns towards the tropism's
// direction by |H x eT| radians; @Ts(1, 0) sets its elasticity to 0 (kept in a branch only);
// a tropism at 90 degrees (plagiotropism) bends the heading to the plane across it.
TEST(Cpfg, TropismsBendTheHeadingAndElasticityModulesChangeThem) {
    ParseResult r = parse("Lsystem: 1\nderivation length: 0\nAxiom: &(90) F F [@Ts(1,0) F F] F @Ts(1,0) F F\nendlsystem\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    auto g = std::make_shared<Grammar>(*r.grammar);
    g->settings.movements.push_back({false, {0, 1, 0}, 0, 0.2, 0});  // tropism: T: 0 1 0 E: 0.2
    Geometry out;
    interpret(g->axiom, *g, {0, 1, nullptr}, out);
    ASSERT_EQ(out.cylinders.size(), 7u);
    auto dir = [&](size_t k) { return glm::normalize(out.cylinders[k].end - out.cylinders[k].start); };
    // &(90): the heading starts across +y; the first F turns it by 0.2 rad (|H x eT| = 0.2).
    EXPECT_NEAR(std::asin(dir(0).y), 0.2f, 1e-4f);
    EXPECT_GT(dir(1).y, dir(0).y);
    EXPECT_NEAR(glm::length(dir(3) - dir(2)), 0.0f, 1e-5f);  // in the branch: elasticity 0, straight
    EXPECT_NEAR(glm::length(dir(2) - dir(1)), 0.0f, 1e-5f);
    EXPECT_GT(dir(4).y, dir(1).y);  // after ']' the elasticity is back
    EXPECT_NEAR(glm::length(dir(6) - dir(4)), 0.0f, 1e-5f);  // @Ts(1,0): straight on
    // A plagiotropism (A: 90) takes a heading along +y down towards the horizontal plane.
    g->settings.movements = {{false, {0, 1, 0}, 90, 0.3, 0}};
    ParseResult up = parse("Lsystem: 1\nderivation length: 0\nAxiom: &(10) F F F F F F F F F F F F\nendlsystem\n",
                           parseOptionsFor(FileKind::Cpfg, ""));
    auto g2 = std::make_shared<Grammar>(*up.grammar);
    g2->settings.movements = g->settings.movements;
    Geometry flat;
    interpret(g2->axiom, *g2, {0, 1, nullptr}, flat);
    const glm::vec3 last = glm::normalize(flat.cylinders.back().end - flat.cylinders.back().start);
    EXPECT_LT(std::fabs(last.y), 0.05f);
}

// cpfg's L-system defined surfaces (patches.c): @PC puts control points where the turtle is,
// @PD(id, s, t) draws the Bezier patch as s x t quads: its corners are the corner points, and
// the four inner points raised to 1 lift its middle to (3/8 + 3/8)^2 = 0.5625 (the two inner
// Bezier weights at 1/2 are 3/8 each, in each direction).
TEST(Cpfg, LsystemDefinedSurfaceIsDrawnThroughItsControlPoints) {
    ParseResult r = parse("Lsystem: 1\nderivation length: 0\nAxiom: @PS(1,1) @M(0,0,0) @PC(1,0,0) @M(1,0,0) @PC(1,0,1) @M(2,0,0) @PC(1,0,2) @M(3,0,0) @PC(1,0,3) @M(0,1,0) @PC(1,1,0) @M(1,1,1) @PC(1,1,1) @M(2,1,1) @PC(1,1,2) @M(3,1,0) @PC(1,1,3) @M(0,2,0) @PC(1,2,0) @M(1,2,1) @PC(1,2,1) @M(2,2,1) @PC(1,2,2) @M(3,2,0) @PC(1,2,3) @M(0,3,0) @PC(1,3,0) @M(1,3,0) @PC(1,3,1) @M(2,3,0) @PC(1,3,2) @M(3,3,0) @PC(1,3,3) @PD(1,4,4) @PD(2)\nendlsystem\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_EQ(g.polygons.positions.size(), 25u);  // 5 x 5 vertices; patch 2 has no points: nothing
    ASSERT_EQ(g.polygons.indices.size(), 4u * 4 * 6);
    EXPECT_NEAR(glm::length(g.polygons.positions.front() - glm::vec3(0, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(g.polygons.positions.back() - glm::vec3(3, 3, 0)), 0.0f, 1e-5f);
    const glm::vec3 middle = g.polygons.positions[12];
    EXPECT_NEAR(middle.x, 1.5f, 1e-5f);
    EXPECT_NEAR(middle.y, 1.5f, 1e-5f);
    EXPECT_NEAR(middle.z, 0.5625f, 1e-5f);  // (3/8 + 3/8)^2
}

TEST(Cpfg, GeneralizedCylinderIsOneSmoothTube) {
    ParseResult r = parse("derivation length: 0\nwidth: 0.5\nAxiom: @Gs F(1) +(30) F(1) @Gc(5) +(30) F(1) @Ge(5)\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    EXPECT_EQ(g.cylinders.size(), 0u);
    // 4 control points: spans of 4 (the default), 5 and 5 pieces: 15 rings, plus two caps.
    ASSERT_EQ(g.polygons.positions.size(), 15u * 12 + 2 * 13);
    ASSERT_EQ(g.polygons.indices.size(), 14u * 12 * 6 + 2 * 12 * 3);
    // Every ring vertex lies at the radius from its ring's centre; the centres of the rings at
    // the control points are the turtle's positions.
    const glm::vec3 control[] = {{0, 0, 0}, {0, 1, 0}, {-0.5f, 1 + std::sqrt(3.0f) / 2, 0},
                                 {-0.5f - std::sqrt(3.0f) / 2, 1.5f + std::sqrt(3.0f) / 2, 0}};
    const int ringAt[] = {0, 4, 9, 14};
    for (int c = 0; c < 4; ++c) {
        glm::vec3 centre(0);
        for (int k = 0; k < 12; ++k) centre += g.polygons.positions[size_t(ringAt[c] * 12 + k)] / 12.0f;
        EXPECT_NEAR(glm::length(centre - control[c]), 0.0f, 1e-4f) << "control point " << c;
        for (int k = 0; k < 12; ++k)
            EXPECT_NEAR(glm::length(g.polygons.positions[size_t(ringAt[c] * 12 + k)] - centre), 0.25f, 1e-4f);
    }
    // Smooth: the rings' normals turn by less than 20 degrees from one ring to the next.
    for (int i = 0; i + 1 < 15; ++i) {
        glm::vec3 a = g.polygons.positions[size_t(i * 12)] , b = g.polygons.positions[size_t((i + 1) * 12)];
        glm::vec3 na = g.polygons.normals[size_t(i * 12)], nb = g.polygons.normals[size_t((i + 1) * 12)];
        EXPECT_GT(glm::dot(na, nb), std::cos(20.0f * 3.14159265f / 180)) << "ring " << i << " " << a.y << " " << b.y;
    }
}

// A cpfg surface file is its Bezier patch, tessellated, in the turtle's frame.
TEST(Cpfg, SurfaceFileIsPlacedInTheTurtlesFrame) {
    const std::string dir = std::string(SPROUT_CPFG_DIR) + "/";
    ParseResult r = parse("derivation length: 0\nsurface: b blade.s\nAxiom: ~b(2) +(90) ~q(1)\n",
                          parseOptionsFor(FileKind::Cpfg, dir + "x.l"));
    for (const auto& d : r.diagnostics) ADD_FAILURE() << formatDiagnostic(d, "x.l");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.grammar->surfaceFiles.size(), 2u);  // b by its line, q found beside the grammar
    Geometry g;
    interpret(r.grammar->axiom, *r.grammar, {0, 1, nullptr}, g);
    ASSERT_EQ(g.polygons.positions.size(), 2u * 81);  // one patch, 8 x 8 quads, each surface
    ASSERT_EQ(g.polygons.indices.size(), 2u * 8 * 8 * 6);
    // The blade's tip (0, 1, 0) along its heading: at twice the heading (+Y) for ~b(2), at the
    // turned heading (-X after '+' by 90) for ~q(1).
    auto has = [&](glm::vec3 want) {
        return std::any_of(g.polygons.positions.begin(), g.polygons.positions.end(),
                           [&](const glm::vec3& p) { return glm::length(p - want) < 1e-5f; });
    };
    EXPECT_TRUE(has({0, 2, 0}));
    EXPECT_TRUE(has({-1, 0, 0}));
    // Not a surface file: said with its line.
    ParseResult bad = parse("surface: b include_defs.h\nAxiom: ~b\n", parseOptionsFor(FileKind::Cpfg, dir + "x.l"));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.diagnostics[0].message,
              "'include_defs.h' is not a cpfg surface file: no Bezier patch in it (a cpfg surface file has a CONTACT "
              "POINT line and patches of 16 control points)");
}

// Decomposition that never ends is refused with the step and the depth (cpfg decomposes
// within the steps, not the axiom: step 1).
TEST(Cpfg, EndlessDecompositionIsRefused) {
    ParseResult r = parse("derivation length: 1\nAxiom: A\ndecomposition\nmaximum depth: 5\nA --> B A\n",
                          parseOptionsFor(FileKind::Cpfg, ""));
    ASSERT_TRUE(r.ok());
    DeriveResult d = derive(r.grammar, 1);
    EXPECT_FALSE(d.outcome.ok());
    EXPECT_EQ(d.outcome.message,
              "step 1: the decomposition rules still apply after 5 levels (maximum depth): they never end. A decomposition "
              "must end in modules no decomposition rule rewrites; raise 'maximum depth:' if it is this deep on purpose");
}

// Text typed without a folder cannot include; a file can include only beside itself.
TEST(Cpfg, IncludeStaysInTheGrammarsFolder) {
    auto errorsOf = [](const std::string& text, const std::string& path) {
        std::vector<std::string> out;
        for (const auto& d : parse(text, parseOptionsFor(FileKind::Cpfg, path)).diagnostics)
            if (d.severity == Severity::Error) out.push_back(std::to_string(d.line) + ":" + std::to_string(d.col) + ": " + d.message);
        return out;
    };
    const std::string dir = std::string(SPROUT_CPFG_DIR) + "/";
    EXPECT_EQ(errorsOf("#include \"include_defs.h\"\nAxiom: F\n", ""),
              std::vector<std::string>{"1:10: #include \"include_defs.h\" needs the grammar's folder: save the grammar beside it first"});
    EXPECT_TRUE(errorsOf("#include \"include_defs.h\"\nAxiom: F(LEN)\n", dir + "x.l").empty());
    EXPECT_EQ(errorsOf("#include \"../cpfg/include_defs.h\"\nAxiom: F\n", dir + "x.l"),
              std::vector<std::string>{"1:10: cannot include '../cpfg/include_defs.h': only files in the grammar's own folder can be included"});
    EXPECT_EQ(errorsOf("#include \"x.l\"\nAxiom: F\n", dir + "x.l"),
              std::vector<std::string>{"1:10: 'x.l' includes itself"});
}

}  // namespace
}  // namespace sprout
