// An L-Py model's materials read and written in its text (app/plant/lpy_materials.hpp), in
// both forms L-Py Studio writes; the corpus's models with materials are all read.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/plant/lpy_materials.hpp"
#include "core/base/read_file.hpp"

namespace sprout {
namespace {

const std::string kStudio =
    "def __initialiseContext__(context):\n\timport openalea.plantgl.all as pgl\n"
    "\tColor_0 = pgl.Material(\"Color_0\" , ambient = (30,60,10) , diffuse = 3 , )\n\tColor_0.name = \"Color_0\"\n"
    "\tcontext.turtle.setMaterial(0,Color_0)\n"
    "\tColor_5 = pgl.Material(\"Color_5\" , ambient = (0,0,0) , )\n\tcontext.turtle.setMaterial(5,Color_5)\n"
    "\tcontext.turtle.setMaterial(7,Material('Red',Color3(39,0,0),4.61538,Color3(40,40,40),Color3(0,0,0),1,0))\n"
    "\tcontext.turtle.setMaterial(9,ImageTexture('leaf.png'))\n";

TEST(LpyMaterials, BothFormsAreRead) {
    const auto m = lpyMaterials(kStudio);
    ASSERT_EQ(m.size(), 4u);
    EXPECT_EQ(m[0].index, 0);
    EXPECT_EQ(m[0].name, "Color_0");
    EXPECT_EQ(m[0].ambient, (std::array<int, 3>{30, 60, 10}));
    EXPECT_EQ(m[0].diffuse, 3);
    EXPECT_EQ(m[0].specular, (std::array<int, 3>{0, 0, 0})) << "PlantGL's default, not written";
    EXPECT_EQ(m[0].line, 5);
    EXPECT_EQ(m[1].diffuse, 2) << "PlantGL's default";
    EXPECT_EQ(m[2].name, "Red");
    EXPECT_FALSE(m[2].keywords);
    EXPECT_DOUBLE_EQ(m[2].diffuse, 4.61538);
    EXPECT_EQ(m[2].shininess, 1);
    EXPECT_EQ(m[3].texture, "leaf.png");
    EXPECT_EQ(lpyDiffuseColour(m[0]), (std::array<int, 3>{90, 180, 30}));
    LpyMaterial bright = m[0];
    bright.ambient = {200, 100, 0};
    EXPECT_EQ(lpyDiffuseColour(bright), (std::array<int, 3>{254, 127, 0})) << "PlantGL keeps ambient x diffuse within 255 (its floor of 200 x 255/200 is 254)";
}

// A texture's image file is written in its literal's place (ImageTexture(file) and Studio's
// ImageTexture("name" , "file" , ) behind a Texture2D alike); a plain material has none.
TEST(LpyMaterials, ATexturesImageFileIsWrittenInPlace) {
    const auto m = lpyMaterials(kStudio);
    std::string error;
    std::string t = setLpyTextureFile(kStudio, m[3], "bark.jpg", error);
    EXPECT_NE(t.find("setMaterial(9,ImageTexture('bark.jpg'))"), std::string::npos) << t;
    EXPECT_EQ(lpyMaterials(t)[3].texture, "bark.jpg");
    EXPECT_EQ(setLpyTextureFile(kStudio, m[0], "bark.jpg", error), "") << "a Material has no image";
    EXPECT_EQ(setLpyTextureFile(kStudio, m[3], "it's.png", error), "") << "no quote inside the literal";
    const std::string studio = "\tPGL_1 = pgl.ImageTexture(\"PGL_1\" , \"leaf.png\" , )\n\tColor_4 = pgl.Texture2D(image = PGL_1 , )\n"
                               "\tcontext.turtle.setMaterial(4,Color_4)\n";
    const auto s = lpyMaterials(studio);
    ASSERT_EQ(s.size(), 1u);
    t = setLpyTextureFile(studio, s[0], "images/vein.png", error);
    EXPECT_NE(t.find("pgl.ImageTexture(\"PGL_1\" , 'images/vein.png' , )"), std::string::npos) << t;
}

TEST(LpyMaterials, AFieldIsWrittenInPlaceOrAddedAsStudioWritesIt) {
    auto m = lpyMaterials(kStudio);
    LpyMaterial v = m[0];
    v.ambient = {200, 10, 0};
    std::string t = setLpyMaterial(kStudio, m[0], LpyMaterial::Ambient, v);
    std::string expected = kStudio;
    expected.replace(expected.find("(30,60,10)"), 10, "(200,10,0)");
    EXPECT_EQ(t, expected) << "only the value changes";
    v = m[1];
    v.transparency = 0.5;
    t = setLpyMaterial(t, lpyMaterials(t)[1], LpyMaterial::Transparency, v);
    EXPECT_NE(t.find("pgl.Material(\"Color_5\" , ambient = (0,0,0) , transparency = 0.5 , )"), std::string::npos) << t;
    EXPECT_EQ(lpyMaterials(t)[1].transparency, 0.5);
    v = m[2];
    v.emission = {5, 6, 7};
    t = setLpyMaterial(t, lpyMaterials(t)[2], LpyMaterial::Emission, v);
    EXPECT_NE(t.find("Material('Red',Color3(39,0,0),4.61538,Color3(40,40,40),Color3(5,6,7),1,0)"), std::string::npos) << t;
    const std::string bare = "c.setMaterial(1, Material('x', ambient=(1,2,3)))\n";
    v = lpyMaterials(bare)[0];
    v.diffuse = 1.5;
    EXPECT_EQ(setLpyMaterial(bare, lpyMaterials(bare)[0], LpyMaterial::Diffuse, v), "c.setMaterial(1, Material('x', ambient=(1,2,3), diffuse = 1.5))\n");
}

TEST(LpyMaterials, EveryCorpusModelsMaterialsAreRead) {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus";
    if (!fs::exists(root / "lpy")) GTEST_SKIP() << "no corpus";
    int models = 0, materials = 0;
    for (const char* sub : {"lpy", "lpy-tests"})
        for (const auto& e : fs::recursive_directory_iterator(root / sub)) {
            if (e.path().extension() != ".lpy") continue;
            const std::string text = readFile(e.path().string()).value_or("");
            size_t calls = 0;
            for (size_t at = text.find("setMaterial("); at != std::string::npos; at = text.find("setMaterial(", at + 1)) ++calls;
            if (calls == 0) continue;
            const auto m = lpyMaterials(text);
            EXPECT_EQ(m.size(), calls) << e.path();
            ++models;
            materials += int(m.size());
        }
    EXPECT_GT(models, 10);
    EXPECT_GT(materials, 40);
}

TEST(LpyMaterials, ARangeIsInterpolatedAsLpysColourMapDoes) {
    const std::string studio =
        "def __initialiseContext__(context):\n\timport openalea.plantgl.all as pgl\n"
        "\tColor_0 = pgl.Material(\"Color_0\" , ambient = (0,0,0) , diffuse = 2 , )\n\tcontext.turtle.setMaterial(0,Color_0)\n"
        "\tColor_2 = pgl.Material(\"Color_2\" , ambient = (9,9,9) , )\n\tcontext.turtle.setMaterial(2,Color_2)\n"
        "\tColor_4 = pgl.Material(\"Color_4\" , ambient = (100,120,40) , diffuse = 2 , transparency = 0.5 , )\n"
        "\tcontext.turtle.setMaterial(4,Color_4)\n";
    std::string error;
    const std::string t = interpolateLpyMaterials(studio, 4, 0, error);
    ASSERT_FALSE(t.empty()) << error;
    const auto m = lpyMaterials(t);
    ASSERT_EQ(m.size(), 5u) << t;
    std::array<const LpyMaterial*, 5> by{};
    for (const LpyMaterial& x : m) by[size_t(x.index)] = &x;
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(by[size_t(k)]) << k;
    EXPECT_EQ(by[1]->ambient, (std::array<int, 3>{25, 30, 10}));
    EXPECT_EQ(by[2]->ambient, (std::array<int, 3>{50, 60, 20})) << "the one set is set in place";
    EXPECT_EQ(by[3]->ambient, (std::array<int, 3>{75, 90, 30}));
    EXPECT_DOUBLE_EQ(by[3]->transparency, 0.375);
    EXPECT_NE(t.find("\tColor_1 = pgl.Material(\"Color_1\" , ambient = (25,30,10) ,"), std::string::npos) << t;
    EXPECT_EQ(interpolateLpyMaterials(studio, 0, 1, error), "") << "nothing between";
    EXPECT_EQ(interpolateLpyMaterials(studio, 0, 7, error), "") << "7 is not set";
    const std::string old = "\tcontext.turtle.setMaterial(0,Material('Red',Color3(40,0,0),2,Color3(40,40,40),Color3(0,0,0),1,0))\n"
                            "\tcontext.turtle.setMaterial(3,Material('Yellow',Color3(40,40,0),2,Color3(40,40,40),Color3(0,0,0),1,0))\n";
    const std::string u = interpolateLpyMaterials(old, 0, 3, error);
    EXPECT_NE(u.find("setMaterial(2,Material('Color_2',Color3(40,27,0),2,Color3(40,40,40),Color3(0,0,0),1,0))"), std::string::npos) << u;
}

}  // namespace
}  // namespace sprout
