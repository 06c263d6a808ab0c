// cpfg's background scenes (VLab's cpfg/background.c): the file a view file's `background
// scene:` names, read through the preprocessor (core/language/vlab/background_scene.hpp), and
// drawn as cpfg draws it (core/turtle/background_scene.hpp). The scenes are written here; the
// manual's two objects that have one are read from the shared corpus when it is there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <glm/geometric.hpp>

#include "core/language/vlab/background_scene.hpp"
#include "core/language/vlab/view_file.hpp"
#include "core/turtle/background_scene.hpp"

using namespace sprout;
using namespace sprout::vlab;
namespace fs = std::filesystem;

namespace {

BackgroundScene read(const std::string& text, const std::map<std::string, std::string>& others = {}) {
    BackgroundScene s;
    readBackgroundScene(text, "scene.dat", s, [&](const std::string&, const std::string& name, std::string& path, std::string& error) {
        path = name;
        auto it = others.find(name);
        if (it == others.end()) {
            error = "No such file or directory";
            return std::optional<std::string>();
        }
        return std::optional<std::string>(it->second);
    });
    return s;
}

std::vector<float> valuesOf(const BackgroundScene& s, size_t item) {
    const BackgroundItem& it = s.items.at(item);
    return {s.values.begin() + it.first, s.values.begin() + it.first + it.count};
}

std::vector<std::string> texts(const BackgroundScene& s) {
    std::vector<std::string> out;
    for (const auto& p : s.problems) out.push_back(p.text());
    return out;
}

bool has(const BackgroundScene& s, const std::string& text) {
    const auto t = texts(s);
    return std::find(t.begin(), t.end(), text) != t.end();
}

std::string all(const BackgroundScene& s) {
    std::string out;
    for (const auto& t : texts(s)) out += t + "\n";
    return out;
}

Geometry drawn(const BackgroundScene& s) {
    Geometry g;
    drawBackgroundScene(s, g);
    return g;
}

size_t triangles(const Geometry& g) { return g.polygons.indices.size() / 3; }

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

}  // namespace

TEST(VlabBackground, ReadsEveryCommandWithItsNumbers) {
    const BackgroundScene s = read(
        "material\n0.2 0 0 1\n0.5 0.2 0.2 1\n0 0 0 1\n0 0 0 1\n25\n"
        "pushmatrix translate 2 2 0 rotate 45 1 1 0 scale 2 1 1 sphere 0.5 popmatrix\n"
        "cylinder 0.3 2.0\ncone 1 0.5 2\nprism 1 1 1\nbox 1 2 3\n"
        "polygon -1 -1 0  -1 1 0  1 1 0  1 -1 0\n"
        "polygonuv 0 0 0 0 0 1  1 0 0 0 0 1  1 1 0 0 0 1\n"
        "rectangle 2 1 0.5 0.5 2\n"
        "mesh 1 0 0 2 0 0  1 1 0 2 1 0\n"
        "multmatrix 1 0 0 0 0 1 0 0 0 0 1 0 0 2 0 1\n");
    EXPECT_TRUE(s.ok()) << all(s);
    EXPECT_TRUE(s.problems.empty()) << all(s);
    using C = BackgroundCommand;
    const std::vector<C> commands = {C::Material, C::PushMatrix, C::Translate, C::Rotate, C::Scale, C::Sphere, C::PopMatrix,
                                     C::Cylinder, C::Cone, C::Prism, C::Prism, C::Polygon, C::PolygonUV, C::Rectangle,
                                     C::Mesh, C::MultMatrix};
    ASSERT_EQ(s.items.size(), commands.size());
    for (size_t i = 0; i < commands.size(); ++i) EXPECT_EQ(s.items[i].command, commands[i]) << i;
    EXPECT_EQ(valuesOf(s, 0).size(), 17u);
    EXPECT_FLOAT_EQ(valuesOf(s, 0)[16], 25);
    EXPECT_EQ(valuesOf(s, 3), (std::vector<float>{45, 1, 1, 0}));
    EXPECT_EQ(valuesOf(s, 10), (std::vector<float>{1, 2, 3}));  // box is prism
    EXPECT_EQ(valuesOf(s, 11).size(), 12u);
    EXPECT_EQ(valuesOf(s, 13), (std::vector<float>{2, 1, 0.5f, 0.5f, 2}));
    EXPECT_EQ(s.items[7].line, 8);
    EXPECT_EQ(s.pushed, 0);
}

TEST(VlabBackground, RunsThroughThePreprocessorAsCpfgDoes) {
    // #define (no space put after a minus sign, as preproc), comments, continued lines,
    // function-like macros, conditions, #include beside the file.
    const BackgroundScene s = read(
        "#define STEP 35\n"
        "#define R(x) (x)\n"
        "/* a comment\n   over two lines */ translate -STEP 0 0 // and one to the line's end\n"
        "#ifdef STEP\nsphere 1\n#else\nsphere 2\n#endif\n"
        "#if 0\ncylinder 1 1\n#elif defined(STEP)\ncylinder 2 \\\n 3\n#endif\n"
        "#include \"part.dat\"\n"
        "scale STEP STEP 1\n",
        {{"part.dat", "#define STEP 7\nsphere STEP\n"}});
    EXPECT_TRUE(s.problems.empty()) << all(s);
    ASSERT_EQ(s.items.size(), 5u);
    EXPECT_EQ(valuesOf(s, 0), (std::vector<float>{-35, 0, 0}));
    EXPECT_EQ(s.items[0].line, 4);
    EXPECT_EQ(valuesOf(s, 1), (std::vector<float>{1}));
    EXPECT_EQ(valuesOf(s, 2), (std::vector<float>{2, 3}));
    EXPECT_EQ(valuesOf(s, 3), (std::vector<float>{7}));
    EXPECT_EQ(s.files.at(s.items[3].file), "part.dat");
    EXPECT_EQ(s.items[3].line, 2);
    EXPECT_EQ(valuesOf(s, 4), (std::vector<float>{7, 7, 1}));  // the include's #define holds after it
    // What the preprocessor refuses names its line.
    const BackgroundScene bad = read("sphere 1\n/* never closed\nsphere 2\n");
    EXPECT_TRUE(has(bad, "scene.dat:2:1: a comment '/*' is never closed with '*/'")) << all(bad);
    EXPECT_EQ(bad.items.size(), 1u);
    const BackgroundScene missing = read("sphere 1\n#include \"gone.dat\"\n#ifdef X\n");
    EXPECT_TRUE(has(missing, "scene.dat:2:1: cannot include 'gone.dat': No such file or directory")) << all(missing);
    EXPECT_TRUE(has(missing, "scene.dat:3:1: an '#if' is never closed with '#endif'")) << all(missing);
    const BackgroundScene itself = read("#include \"scene.dat\"\n", {{"scene.dat", "#include \"scene.dat\"\n"}});
    EXPECT_TRUE(has(itself, "scene.dat:1:1: 'scene.dat' includes itself (through the files that include it)")) << all(itself);
    const BackgroundScene blowUp = read(
        "#define A x x x x x x x x x x\n#define B A A A A A A A A A A\n#define C B B B B B B B B B B\n"
        "#define D C C C C C C C C C C\n#define E D D D D D D D D D D\n#define F E E E E E E E E E E\n"
        "#define G F F F F F F F F F F\nG\n");
    EXPECT_FALSE(blowUp.ok());
    EXPECT_NE(all(blowUp).find("scene.dat:8:1: the #define names on this line expand to more than 1 MB"), std::string::npos) << all(blowUp);
}

TEST(VlabBackground, WrongOrCutFilesNameTheLineAndWhatWasExpected) {
    const BackgroundScene s = read(
        "spere 0.5\n"              // 1: a slip
        "sphere 2 # cpfg skips what follows a word starting with '#' 7 8\n"
        "translate 1 2\nsphere 1\n"  // 3: too few numbers
        "sphere 1 2 3\n"           // 5: more than it uses
        "pushmatrix 4\n"           // 6
        "popmatrix\npopmatrix\n"   // 8: nothing pushed
        "rotate 30 0 0 0\n"        // 9
        "polygon 0 0 0 1 0 0 1 1 0 5\n"  // 10: a point cut short
        "translate 1,2,3\n"        // 11: commas are no separators to cpfg
        "multmatrix\n1 0 0 0\n0 1 0\n");  // 12: the file ends
    EXPECT_FALSE(s.ok());
    const std::string a = all(s);
    EXPECT_TRUE(has(s, "scene.dat:1:1: unknown background-scene command 'spere' (did you mean 'sphere'?); skipped with its numbers, as cpfg skips it")) << a;
    EXPECT_TRUE(has(s, "scene.dat:4:1: 'translate' expects x y z; found 2 numbers, then 'sphere'")) << a;
    EXPECT_TRUE(has(s, "scene.dat:5:10: warning: 'sphere' uses 1 number (a radius); the next 2 are ignored, as cpfg ignores them")) << a;
    EXPECT_TRUE(has(s, "scene.dat:6:12: warning: 'pushmatrix' takes no numbers; this one is ignored, as cpfg ignores them")) << a;
    EXPECT_TRUE(has(s, "scene.dat:8:1: warning: 'popmatrix' with no 'pushmatrix' before it: ignored, as cpfg ignores it")) << a;
    EXPECT_TRUE(has(s, "scene.dat:9:1: warning: 'rotate' about the axis 0 0 0, which has no direction: skipped")) << a;
    EXPECT_TRUE(has(s, "scene.dat:10:27: warning: 'polygon' uses 9 numbers (at least 3 points, x y z each); the next one is ignored, as cpfg ignores them")) << a;
    EXPECT_TRUE(has(s, "scene.dat:11:11: 'translate' expects x y z; found '1,2,3'")) << a;
    EXPECT_EQ(a.find("command '1,2,3'"), std::string::npos) << "named once";
    EXPECT_TRUE(has(s, "scene.dat:12:1: 'multmatrix' expects 16 numbers, the matrix row by row; the file ends after 7 numbers")) << a;
    // What is right is kept, in order: sphere 2, sphere 1, sphere 1 2 3 (as sphere 1), pushmatrix,
    // popmatrix, polygon.
    using C = BackgroundCommand;
    ASSERT_EQ(s.items.size(), 6u) << a;
    EXPECT_EQ(valuesOf(s, 0), (std::vector<float>{2}));
    EXPECT_EQ(s.items[1].command, C::Sphere);
    EXPECT_EQ(valuesOf(s, 2), (std::vector<float>{1}));
    EXPECT_EQ(s.items[3].command, C::PushMatrix);
    EXPECT_EQ(s.items[4].command, C::PopMatrix);
    EXPECT_EQ(valuesOf(s, 5).size(), 9u);
    // Numbers before any command.
    const BackgroundScene stray = read("0.5 1\nsphere 1\n");
    EXPECT_TRUE(has(stray, "scene.dat:1:1: expected a command (polygon, sphere, material ...) before the number '0.5'")) << all(stray);
    EXPECT_EQ(stray.items.size(), 1u);
    // cpfg keeps 50 matrices: the 50th push is ignored.
    std::string pushes;
    for (int i = 0; i < 50; ++i) pushes += "pushmatrix\n";
    const BackgroundScene deep = read(pushes);
    EXPECT_EQ(deep.items.size(), 49u);
    EXPECT_TRUE(has(deep, "scene.dat:50:1: warning: cpfg's matrix stack holds 50 matrices: this 'pushmatrix' is ignored, as cpfg ignores it")) << all(deep);
    // A file that cannot be read is one error naming it.
    BackgroundScene none;
    loadBackgroundScene(fs::path(testing::TempDir()) / "no_such_background.dat", none);
    ASSERT_EQ(none.problems.size(), 1u);
    EXPECT_EQ(none.problems[0].text(), (fs::path(testing::TempDir()) / "no_such_background.dat").string() + ": cannot be read: No such file or directory");
}

TEST(VlabBackground, TheViewFileNamesOneOrMoreScenes) {
    const ViewFile v = readViewFile("contour sides: 12\nbackground scene: floor.dat, trees.dat;rocks.dat\nbackground scene:\n");
    std::vector<std::string> files;
    for (const FileReference& f : v.files)
        if (f.command == "background scene") {
            files.push_back(f.file);
            EXPECT_EQ(f.line, 2);
        }
    EXPECT_EQ(files, (std::vector<std::string>{"floor.dat", "trees.dat", "rocks.dat"}));
    ASSERT_EQ(v.diagnostics.size(), 1u);
    EXPECT_EQ(v.diagnostics[0].line, 3);
}

TEST(VlabBackground, ShapesHaveCpfgsSizesAndPlaces) {
    // A box from the origin: 6 faces of 2 triangles; in the scene's bounds, not the plant's.
    Geometry box = drawn(read("prism 1 2 3\n"));
    EXPECT_EQ(triangles(box), 12u);
    EXPECT_TRUE(box.bounds.empty) << "cpfg frames the plant alone";
    expectNear(box.backdrop.min, {0, 0, 0});
    expectNear(box.backdrop.max, {1, 2, 3});
    EXPECT_EQ(box.backdropFirst, 0u);
    EXPECT_EQ(box.backdropCount, box.polygons.positions.size());
    EXPECT_EQ(box.extent().max, box.backdrop.max);
    // A cylinder runs along y from the origin, closed by discs: 8 sides are 16 + 2 x 8 triangles.
    BackgroundScene cylinder = read("translate 1 0 0\ncylinder 0.5 2\n");
    Geometry c = drawn(cylinder);
    EXPECT_EQ(triangles(c), 32u);
    expectNear(c.backdrop.min, {0.5f, 0, -0.5f});
    expectNear(c.backdrop.max, {1.5f, 2, 0.5f});
    cylinder.sides = 18;
    EXPECT_EQ(triangles(drawn(cylinder)), 72u);
    // A cone from radius 1 to 0.5; with tapered lines off, cpfg draws it as a cylinder.
    BackgroundScene cone = read("cone 1 0.5 2\n");
    Geometry k = drawn(cone);
    float topWidth = 0;
    for (const glm::vec3& p : k.polygons.positions)
        if (std::fabs(p.y - 2) < 1e-5f) topWidth = std::max(topWidth, p.x);
    EXPECT_NEAR(topWidth, 0.5f, 1e-5f);
    cone.tapered = false;
    expectNear(drawn(cone).backdrop.max, {1, 2, 1});
    // A sphere: sides slices and sides / 2 + 1 bands, poles on z.
    Geometry ball = drawn(read("sphere 2\n"));
    EXPECT_EQ(triangles(ball), 8u * (2 * 5 - 2));
    EXPECT_NEAR(ball.backdrop.min.z, -2, 1e-5f);
    EXPECT_NEAR(ball.backdrop.max.z, 2, 1e-5f);
    // The matrix: rotate turns right-handed (y to -x about z), scale stretches a sphere into an
    // ellipsoid, pushmatrix and popmatrix keep what was before.
    Geometry turned = drawn(read("pushmatrix rotate 90 0 0 1 cylinder 0.1 3 popmatrix\n"));
    expectNear(turned.backdrop.min, {-3, -0.1f, -0.1f});
    expectNear(turned.backdrop.max, {0, 0.1f, 0.1f});
    Geometry stretched = drawn(read("translate 2 2 0\nscale 2 1 1\nsphere 0.5\n"));
    expectNear(stretched.backdrop.centre(), {2, 2, 0});
    EXPECT_NEAR(stretched.backdrop.size().x, 2 * stretched.backdrop.size().y, 1e-4f);
    EXPECT_NEAR(stretched.backdrop.size().z, 1, 1e-4f);  // the poles, where the scale does not reach
    EXPECT_NEAR(stretched.backdrop.size().x, 2, 0.1f);
    // multmatrix is written row by row, IRIS GL's way: its last row moves. CelticKnot's bar:
    // the matrix turns y to x, the cylinder of length 4 runs from (5, 6) to (9, 6).
    Geometry bar = drawn(read("multmatrix\n0 -1 0 0\n1 0 0 0\n0 0 1 0\n5 6 0 1\ncylinder 0.05 4\n"));
    expectNear(bar.backdrop.min, {5, 5.95f, -0.05f});
    expectNear(bar.backdrop.max, {9, 6.05f, 0.05f});
    // A rectangle w h x y in the z = 0 plane; a mesh's rows of two points make quads.
    Geometry rect = drawn(read("rectangle 2 1 0.5 0.25\n"));
    EXPECT_EQ(triangles(rect), 2u);
    expectNear(rect.backdrop.min, {0.5f, 0.25f, 0});
    expectNear(rect.backdrop.max, {2.5f, 1.25f, 0});
    EXPECT_EQ(triangles(drawn(read("mesh 1 0 0 2 0 0  1 1 0 2 1 0  1 1 1 2 1 1  1 2 2 2 2 2\n"))), 6u);
}

TEST(VlabBackground, PolygonsWindAndFaceAsCpfgsDo) {
    // cpfg's normal is (a - b) x (c - b) of the first three points: for a b c going
    // counter-clockwise seen from +z, it points to -z; each triangle winds counter-clockwise
    // about the normal it is stored with, and a polygon is a fan from its first point.
    Geometry g = drawn(read("polygon 0 0 0  1 0 0  1 1 0  0 1 0  -0.5 0.5 0\n"));
    ASSERT_EQ(triangles(g), 3u);
    for (const glm::vec3& n : g.polygons.normals) expectNear(n, {0, 0, -1});
    for (size_t t = 0; t < g.polygons.indices.size(); t += 3) {
        const glm::vec3 a = g.polygons.positions[g.polygons.indices[t]], b = g.polygons.positions[g.polygons.indices[t + 1]],
                        c = g.polygons.positions[g.polygons.indices[t + 2]];
        EXPECT_LT(glm::cross(b - a, c - a).z, 0) << t;
        expectNear(a, {0, 0, 0});  // the fan's centre
    }
    // A sphere's normals point outwards, its triangles wind about them.
    Geometry ball = drawn(read("translate 0 1 0\nsphere 1\n"));
    for (size_t t = 0; t < ball.polygons.indices.size(); t += 3) {
        const glm::vec3 a = ball.polygons.positions[ball.polygons.indices[t]], b = ball.polygons.positions[ball.polygons.indices[t + 1]],
                        c = ball.polygons.positions[ball.polygons.indices[t + 2]];
        const glm::vec3 centre = (a + b + c) / 3.0f - glm::vec3(0, 1, 0);
        ASSERT_GT(glm::dot(glm::cross(b - a, c - a), centre), 0) << t;
        ASSERT_GT(glm::dot(ball.polygons.normals[ball.polygons.indices[t]], centre), 0) << t;
    }
}

TEST(VlabBackground, MaterialsColourWhatFollows) {
    // The scene starts with the reference set's material 0; `material` changes its groups:
    // RGBA ambient, diffuse (whose alpha is the translucency), specular, emission.
    BackgroundScene s = read(
        "sphere 1\n"
        "material 0 0 0 1  1 0 0 1\nsphere 1\n"
        "material 0 0 0 1  0 0 1 0.5  0 0 0 1  0 0.5 0 1\nsphere 1\n"
        "rectangle 1 1 0 0 2\n");
    s.start.diffuse = {0, 1, 0};
    Geometry g = drawn(s);
    std::vector<std::uint32_t> colours;
    for (std::uint32_t c : g.polygons.colours)
        if (colours.empty() || colours.back() != c) colours.push_back(c);
    EXPECT_EQ(colours, (std::vector<std::uint32_t>{0x00FF00FF, 0xFF0000FF, 0x0080FF80, 0x00FFFF80}));
    // With a colour map, the scene takes the diffuse colour into the map's entry.
    s.materials = false;
    s.startColour = 0x102030;
    g = drawn(s);
    colours.clear();
    for (std::uint32_t c : g.polygons.colours)
        if (colours.empty() || colours.back() != c) colours.push_back(c);
    EXPECT_EQ(colours, (std::vector<std::uint32_t>{0x102030FF, 0xFF0000FF, 0x0000FFFF}));
}

TEST(VlabBackground, WhatOverflowsIsLeftOut) {
    Geometry g = drawn(read("scale 1e30 1e30 1e30\nscale 1e30 1e30 1e30\nsphere 1\nprism 1 1 1\n"));
    EXPECT_EQ(triangles(g), 0u);
    EXPECT_TRUE(g.backdrop.empty);
    // At most kMaxBackgroundTriangles: 100 spheres of 128 sides would be 1.6 M.
    std::string many;
    for (int i = 0; i < 100; ++i) many += "sphere 1\n";
    BackgroundScene s = read(many);
    s.sides = 128;
    EXPECT_LE(triangles(drawn(s)), kMaxBackgroundTriangles);
}

TEST(VlabBackground, TheManualsObjectsScenes) {
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals";
    if (!fs::exists(root)) GTEST_SKIP() << "no shared corpus at " << root;
    // BackgroundScene: a sphere, cylinders, a rotated polygon, a prism, a cone, a floor, a mesh.
    BackgroundScene shapes;
    loadBackgroundScene(root / "11-CPFG" / "BackgroundScene" / "background.dat", shapes);
    EXPECT_TRUE(shapes.problems.empty()) << all(shapes);
    EXPECT_EQ(shapes.items.size(), 30u);
    shapes.sides = 18;  // its contour sides
    const Geometry g = drawn(shapes);
    // 2 spheres of 18 x 18, 2 cylinders and a cone of 72, a prism of 12, 2 squares, 3 quads.
    EXPECT_EQ(triangles(g), 2u * 324 + 3 * 72 + 12 + 2 * 2 + 3 * 2);
    EXPECT_NEAR(g.backdrop.min.x, -4, 1e-4f);  // the floor
    EXPECT_NEAR(g.backdrop.min.z, -4, 1e-4f);
    EXPECT_NEAR(g.backdrop.max.x, 4, 1e-4f);
    EXPECT_NEAR(g.backdrop.max.z, 4, 1e-4f);
    // CelticKnot: the obstacles, 14 bars of radius 0.05 from (0, 0) to (24, 6).
    BackgroundScene knot;
    loadBackgroundScene(root / "20-EnviroPgms" / "CPFG-CelticKnot" / "background.dat", knot);
    EXPECT_TRUE(knot.problems.empty()) << all(knot);
    EXPECT_EQ(std::count_if(knot.items.begin(), knot.items.end(), [](const BackgroundItem& i) { return i.command == BackgroundCommand::Cylinder; }), 14);
    const Geometry k = drawn(knot);
    expectNear(k.backdrop.min, {0, -0.05f, -0.05f}, 1e-4f);
    expectNear(k.backdrop.max, {24, 6.05f, 0.05f}, 1e-4f);
}
