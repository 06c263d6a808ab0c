// Materials as the picture shows them (issue 53): PNG renders of small models of this file's
// own, through the program as a user runs it, checked at their pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/image.hpp"
#include "tests/app/run_sprout.hpp"

namespace {

using sprout_test::runSprout;
using sprout_test::writeTemp;

// A model's picture (`name` with its file's extension), `size` pixels square, seen from the
// front with no ground or shadows.
sprout::Image renderedFile(const std::string& name, const std::string& text, int size) {
    const std::string path = writeTemp(name, text), png = testing::TempDir() + name + ".png", side = std::to_string(size);
    const auto r = runSprout("render " + path + " -o " + png + " --size " + side + "x" + side + " --view front --no-ground --no-shadows");
    sprout::Image image;
    std::string error;
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
    return image;
}

// An L-Py model's picture, 240x240; a grammar's, 200x200.
sprout::Image rendered(const std::string& name, const std::string& model) { return renderedFile(name + ".lpy", model, 240); }
sprout::Image renderedLsys(const std::string& name, const std::string& grammar) { return renderedFile(name + ".lsys", grammar, 200); }

std::array<int, 3> at(const sprout::Image& i, int x, int y) {
    const std::size_t k = (std::size_t(y) * std::size_t(i.width) + std::size_t(x)) * 4;
    return {i.rgba[k], i.rgba[k + 1], i.rgba[k + 2]};
}

// The brightest pixel's sum of channels within 60 pixels of the picture's centre (the sphere's
// own, not the sky's).
int brightest(const sprout::Image& i) {
    int best = 0;
    for (int y = 0; y < i.height; ++y)
        for (int x = 0; x < i.width; ++x)
            if ((x - i.width / 2) * (x - i.width / 2) + (y - i.height / 2) * (y - i.height / 2) < 60 * 60) {
                const auto c = at(i, x, y);
                best = std::max(best, c[0] + c[1] + c[2]);
            }
    return best;
}

// A small red box inside a big blue one whose material has `transparency`.
std::string boxes(double transparency) {
    return "from openalea.plantgl.all import *\n"
           "red = Shape(Box(0.25, 0.25, 0.25), Material((100, 0, 0)))\n"
           "glass = Shape(Box(1, 1, 1), Material((0, 0, 100), transparency=" +
           std::to_string(transparency) +
           "))\n"
           "Axiom: @g(red) @g(glass)\n"
           "derivation length: 0\n";
}

}  // namespace

// L-Py's grid-rootinsoil2 draws its soil as PlantGL boxes of translucent materials: what is
// behind or inside one shows through it, in the box's colour (PlantGL's Material: ambient x
// diffuse, and its transparency as the alpha the box is blended with).
TEST(Materials, ATranslucentBoxShowsWhatIsInsideIt) {
    const sprout::Image glass = rendered("glass", boxes(0.6)), solid = rendered("solid", boxes(0));
    ASSERT_EQ(glass.width, 240);
    ASSERT_EQ(solid.width, 240);
    const auto g = at(glass, 120, 120), s = at(solid, 120, 120);
    // Opaque, the big box hides the red one: blue, no red.
    EXPECT_GT(s[2], 150) << s[0] << " " << s[1] << " " << s[2];
    EXPECT_LT(s[0], 40) << s[0] << " " << s[1] << " " << s[2];
    // Translucent, the red box shows through the blue: both.
    EXPECT_GT(g[0], 80) << g[0] << " " << g[1] << " " << g[2];
    EXPECT_GT(g[2], 60) << g[0] << " " << g[1] << " " << g[2];
    // Beside the red box, the sky shows through the glass: lighter than the solid blue there.
    const auto gs = at(glass, 120, 60), ss = at(solid, 120, 60);
    EXPECT_GT(gs[0] + gs[1], ss[0] + ss[1] + 100) << gs[0] << " " << gs[1] << " " << gs[2];
}

// A Shape given to @g is drawn in its own Material, not the turtle's colour (PglTurtle::pglShape).
TEST(Materials, AShapesMaterialIsItsColour) {
    const sprout::Image i = rendered("shape", "from openalea.plantgl.all import *\n"
                                               "Axiom: ,(2) @g(Shape(Box(1, 1, 1), Material((110, 10, 10))))\n"
                                               "derivation length: 0\n");
    ASSERT_EQ(i.width, 240);
    const auto c = at(i, 120, 120);
    EXPECT_GT(c[0], 2 * c[1] + 40) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_GT(c[0], 2 * c[2] + 40) << c[0] << " " << c[1] << " " << c[2];
}

// Sprout's own grammars: `material: INDEX #rrggbb transparency T` makes a palette entry one
// sees through. A thin red stem inside a thick stem of a half transparent blue.
TEST(Materials, AnLsysMaterialsTransparencyShowsTheStemInside) {
    auto picture = [](const std::string& name, const std::string& glass) {
        return renderedLsys(name, "material: 1 #c00000\nmaterial: 2 #0000c0" + glass + "\nn: 0\naxiom: [;(1) !(0.3) F(4)] ;(2) !(2) F(4)\n");
    };
    const sprout::Image glass = picture("lsys_glass", " transparency 0.5"), solid = picture("lsys_solid", "");
    ASSERT_EQ(glass.width, 200);
    ASSERT_EQ(solid.width, 200);
    const auto g = at(glass, 100, 100), s = at(solid, 100, 100);
    EXPECT_LT(s[0], 40) << "opaque, the blue stem hides the red: " << s[0] << " " << s[1] << " " << s[2];
    EXPECT_GT(g[0], 60) << "half transparent, the red shows: " << g[0] << " " << g[1] << " " << g[2];
    EXPECT_GT(g[2], 40) << g[0] << " " << g[1] << " " << g[2];
}

TEST(Materials, AWrongMaterialLineSaysWhereAndWhy) {
    const std::pair<const char*, const char*> cases[] = {
        {"material: x #ff0000", "1:11: a material begins with its index, 0 to 255"},
        {"material: 300 #ff0000", "1:11: a material begins with its index, 0 to 255"},
        {"material: 3 blue", "1:13: then its colour as #rrggbb"},
        {"material: 3 #ff0000 shine 2", "1:21: 'shine' is not a material's field: transparency, specular, shininess, emission"},
        {"material: 3 #ff0000 transparency 2", "1:34: transparency is from 0 to 1"},
        {"material: 3 #ff0000 specular white", "1:30: specular is a colour, #rrggbb"},
        {"material: 3 #ff0000 shininess", "1:21: shininess is from 0 to 1"},
    };
    for (const auto& [line, expected] : cases) {
        const std::string path = writeTemp("bad_material.lsys", std::string(line) + "\naxiom: F\n");
        const auto r = runSprout("expand " + path);
        EXPECT_NE(r.code, 0) << line;
        EXPECT_NE(r.err.find(expected), std::string::npos) << line << "\n" << r.err;
    }
}

// A material's specular colour and shininess: a dark sphere gets a white highlight, where the
// same sphere without them has none (it shows the plain grey sheen every surface has).
TEST(Materials, ASpecularSphereHasAHighlight) {
    const sprout::Image shiny = renderedLsys("shiny", "material: 1 #302020 specular #ffffff shininess 0.3\nn: 0\naxiom: ;(1) @O(2)\n"),
                        dull = renderedLsys("dull", "material: 1 #302020\nn: 0\naxiom: ;(1) @O(2)\n");
    ASSERT_EQ(shiny.width, 200);
    EXPECT_GT(brightest(shiny), brightest(dull) + 200) << brightest(shiny) << " against " << brightest(dull);
    EXPECT_GT(brightest(shiny), 600) << "a white highlight";
}

// A material's emission: a black sphere that glows green is green all over, in the shade as
// in the sun.
TEST(Materials, AnEmissiveSphereGlowsInItsColour) {
    const sprout::Image glowing = renderedLsys("glow", "material: 1 #000000 emission #00c000\nn: 0\naxiom: ;(1) @O(2)\n"),
                        black = renderedLsys("black", "material: 1 #000000\nn: 0\naxiom: ;(1) @O(2)\n");
    ASSERT_EQ(glowing.width, 200);
    const auto g = at(glowing, 100, 100), b = at(black, 100, 100);
    EXPECT_GT(g[1], 150) << g[0] << " " << g[1] << " " << g[2];
    EXPECT_LT(g[0], 80) << g[0] << " " << g[1] << " " << g[2];
    EXPECT_LT(b[1], 60) << "without it, black: " << b[0] << " " << b[1] << " " << b[2];
}

// An L-Py model's materials shine as PlantGL's renderer lights them: a red fruit set with
// specular white at shininess 0.5 has a highlight the plain one lacks.
TEST(Materials, AnLpyMaterialsSpecularIsItsHighlight) {
    auto fruit = [](const std::string& name, const std::string& extra) {
        return rendered(name, "from openalea.plantgl.all import *\n"
                              "context().turtle.setMaterial(1, Material((60, 5, 5), 2" + extra + "))\n"
                              "Axiom: ,(1) @O(1)\n"
                              "derivation length: 0\n");
    };
    const sprout::Image shiny = fruit("lpy_shiny", ", (255, 255, 255), (0, 0, 0), 0.5"), plain = fruit("lpy_plain", "");
    ASSERT_EQ(shiny.width, 240);
    EXPECT_GT(brightest(shiny), brightest(plain) + 200) << brightest(shiny) << " against " << brightest(plain);
}

// The exports carry the materials: a .glb's material of a shining colour its roughness from
// the shininess and its emission, a translucent one blended (the Khronos validator reads it
// without an error); an .obj's .mtl Ks, Ns and Ke, and d.
TEST(Materials, ExportsCarryTheMaterials) {
    const std::string grammar = writeTemp("shiny_export.lsys", "material: 1 #302020 specular #ffffff shininess 0.3 emission #003000\n"
                                                               "material: 2 #0000c0 transparency 0.5\nn: 0\n"
                                                               "axiom: ;(1) @O(2) ;(2) !(3) F(4)\n");
    const std::string glb = testing::TempDir() + "shiny_export.glb", obj = testing::TempDir() + "shiny_export.obj";
    ASSERT_EQ(runSprout("export " + grammar + " -o " + glb).code, 0);
    ASSERT_EQ(runSprout("export " + grammar + " -o " + obj).code, 0);
    std::ifstream in(glb, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(bytes.find("\"roughnessFactor\":0.7"), std::string::npos);
    EXPECT_NE(bytes.find("\"emissiveFactor\":[0,0.029556833,0]"), std::string::npos);
    EXPECT_NE(bytes.find("\"alphaMode\":\"BLEND\""), std::string::npos);
    const std::string validator = std::string(SPROUT_TOOLS_DIR) + "/validate_gltf.js";
    if (std::filesystem::exists(std::string(SPROUT_TOOLS_DIR) + "/node_modules/gltf-validator"))
        EXPECT_EQ(std::system(("node " + validator + " " + glb + " >/dev/null 2>&1").c_str()), 0);
    std::ifstream m(testing::TempDir() + "shiny_export.mtl");
    const std::string mtl((std::istreambuf_iterator<char>(m)), {});
    EXPECT_NE(mtl.find("Ks 1 1 1\nNs 38.4\nKe 0 0.029556833 0\nd 1\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("d 0.5019608\n"), std::string::npos) << mtl;
}
