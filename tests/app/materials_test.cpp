// Materials as the picture shows them (issue 53): PNG renders of small models of this file's
// own, through the program as a user runs it, checked at their pixels.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "app/image.hpp"
#include "tests/app/run_sprout.hpp"

namespace {

using sprout_test::runSprout;
using sprout_test::writeTemp;

// The L-Py model's picture, 240x240 seen from the front with no ground or shadows.
sprout::Image rendered(const std::string& name, const std::string& model) {
    const std::string path = writeTemp(name + ".lpy", model), png = testing::TempDir() + name + ".png";
    const auto r = runSprout("render " + path + " -o " + png + " --size 240x240 --view front --no-ground --no-shadows");
    sprout::Image image;
    std::string error;
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
    return image;
}

std::array<int, 3> at(const sprout::Image& i, int x, int y) {
    const std::size_t k = (std::size_t(y) * std::size_t(i.width) + std::size_t(x)) * 4;
    return {i.rgba[k], i.rgba[k + 1], i.rgba[k + 2]};
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
        const std::string path = writeTemp(name + ".lsys", "material: 1 #c00000\nmaterial: 2 #0000c0" + glass +
                                                               "\nn: 0\naxiom: [;(1) !(0.3) F(4)] ;(2) !(2) F(4)\n"),
                          png = testing::TempDir() + name + ".png";
        const auto r = runSprout("render " + path + " -o " + png + " --size 200x200 --view front --no-ground --no-shadows");
        EXPECT_EQ(r.code, 0) << r.err;
        sprout::Image image;
        std::string error;
        EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
        return image;
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
        {"material: 3 #ff0000 shine 2", "1:21: 'shine' is not a material's field: transparency"},
        {"material: 3 #ff0000 transparency 2", "1:34: transparency is from 0 to 1"},
    };
    for (const auto& [line, expected] : cases) {
        const std::string path = writeTemp("bad_material.lsys", std::string(line) + "\naxiom: F\n");
        const auto r = runSprout("expand " + path);
        EXPECT_NE(r.code, 0) << line;
        EXPECT_NE(r.err.find(expected), std::string::npos) << line << "\n" << r.err;
    }
}
