// A VLab object's view file, animation file, material sets and colour maps
// (core/language/vlab/), read from small files written here.
#include <gtest/gtest.h>

#include <string>

#include "core/language/vlab/animation_file.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/language/vlab/view_file.hpp"

namespace sprout::vlab {
namespace {

bool hasMessage(const std::vector<Diagnostic>& ds, int line, const std::string& part, Severity s) {
    for (const auto& d : ds)
        if (d.line == line && d.severity == s && d.message.find(part) != std::string::npos) return true;
    return false;
}

TEST(VlabViewFile, ReadsTheTurtleCameraAndLightsAsCpfgDoes) {
    const ViewFile v = readViewFile(
        "/* a comment\n over two lines */ angle factor: 16\n"
        "initial color: 3 5\n"
        "color increment: 2\n"
        "initial line width: 0.5 pixels\n"
        "line width increment: 0.1  // a remark\n"
        "viewpoint: 0,5,10\n"
        "view reference point: 0, 5, 0\n"
        "twist: 90\n"
        "projection: perspective\n"
        "viewing angle: 30\n"
        "front distance: 1\n"
        "back distance: 50\n"
        "scale factor: 0\n"
        "light direction: 0,0,2\n"
        "light: V:5.0 6.0 10.0 D: 0.5 0.4 0.3\n"
        "tropism direction: 0,-3,0\n"
        "initial elasticity: 0.25\n"
        "twist of cylinders: on\n"
        "box: x: -1,1 y: 0,2 z: -3,3\n"
        "render mode: shaded\n"
        "line style: cylinder\n"
        "polygonization level: 3\n");
    ASSERT_TRUE(v.ok());
    EXPECT_TRUE(v.diagnostics.empty()) << v.diagnostics.front().message;
    EXPECT_DOUBLE_EQ(*v.angleIncrement, 22.5);
    EXPECT_EQ(*v.initialColour, 3);
    EXPECT_EQ(*v.initialColourBack, 5);
    EXPECT_EQ(v.colourIncrement, 2);
    EXPECT_DOUBLE_EQ(*v.lineWidth, 0.5);
    EXPECT_DOUBLE_EQ(v.widthIncrement, 0.1);
    EXPECT_EQ(v.lineStyle, LineStyle::Cylinder);  // the later `line style:` wins
    EXPECT_EQ(v.viewpoint, (Vec3{0, 5, 10}));
    EXPECT_EQ(v.reference, (Vec3{0, 5, 0}));
    EXPECT_DOUBLE_EQ(v.twist, 90);
    EXPECT_TRUE(v.perspective);
    EXPECT_DOUBLE_EQ(v.viewingAngle, 30);
    EXPECT_DOUBLE_EQ(v.front, 1);
    EXPECT_DOUBLE_EQ(v.back, 50);
    EXPECT_DOUBLE_EQ(v.scale, 1);  // 0 reads as 1
    EXPECT_EQ(v.lightDirection, (Vec3{0, 0, 1}));
    ASSERT_EQ(v.lights.size(), 1u);
    EXPECT_EQ(v.lights[0].vector, (Vec3{5, 6, 10}));
    EXPECT_EQ(v.lights[0].diffuse, (Vec3{0.5, 0.4, 0.3}));
    EXPECT_EQ(*v.tropismDirection, (Vec3{0, -1, 0}));
    EXPECT_DOUBLE_EQ(v.elasticity, 0.25);
    EXPECT_TRUE(v.twistOfCylinders);
    ASSERT_TRUE(v.box);
    EXPECT_EQ((*v.box)[1], (Vec3{1, 2, 3}));
    EXPECT_EQ(v.renderMode, "shaded");
    EXPECT_EQ(v.contourSides, 16);
}

TEST(VlabViewFile, KeepsTheFilesItNamesAndWarnsOfUnknownCommands) {
    const ViewFile v = readViewFile(
        "surface: l leaf.s 6 6 10\n"
        "contour: 1 calyx.con\n"
        "function: growth.func 20\n"
        "function set: functions.fset\n"
        "texture: F: bark.png E: m R: 1.6\n"
        "background scene: scene.dat\n"
        "font: -*-courier\n"
        "colour of leaves: 3\n"
        "no colon here\n");
    ASSERT_EQ(v.files.size(), 6u);
    EXPECT_EQ(v.files[0].command, "surface");
    EXPECT_EQ(v.files[0].id, 'l');
    EXPECT_EQ(v.files[0].file, "leaf.s");
    EXPECT_EQ(v.files[0].numbers, (std::vector<double>{6, 6, 10}));
    EXPECT_EQ(v.files[1].command, "contour");
    EXPECT_EQ(v.files[1].numbers, (std::vector<double>{1}));
    EXPECT_EQ(v.files[1].file, "calyx.con");
    EXPECT_EQ(v.files[2].numbers, (std::vector<double>{20}));
    EXPECT_EQ(v.files[3].command, "function set");
    EXPECT_EQ(v.files[4].file, "bark.png");
    EXPECT_EQ(v.files[4].options, "E: m R: 1.6");
    EXPECT_EQ(v.files[5].line, 6);
    ASSERT_EQ(v.others.size(), 1u);
    EXPECT_EQ(v.others[0].command, "font");
    EXPECT_TRUE(v.ok());
    EXPECT_TRUE(hasMessage(v.diagnostics, 8, "unknown view-file command 'colour of leaves:'", Severity::Warning));
    EXPECT_TRUE(hasMessage(v.diagnostics, 9, "expected 'name: value'", Severity::Warning));
}

TEST(VlabViewFile, WrongValuesNameTheLineAndWhatWasExpected) {
    const ViewFile v = readViewFile("viewpoint: 0,1\nangle factor: zero\nline style: dotted\nsurface: l\n");
    EXPECT_FALSE(v.ok());
    EXPECT_TRUE(hasMessage(v.diagnostics, 1, "'viewpoint:' expects three numbers x,y,z; found ' 0,1'", Severity::Error));
    EXPECT_TRUE(hasMessage(v.diagnostics, 2, "'angle factor:' expects a number", Severity::Error));
    EXPECT_TRUE(hasMessage(v.diagnostics, 3, "unknown line style 'dotted' (expected pixel, polygon or cylinder)", Severity::Warning));
    EXPECT_TRUE(hasMessage(v.diagnostics, 4, "a letter, a file and a size", Severity::Error));
    EXPECT_EQ(v.viewpoint, (Vec3{0, 0, 1}));  // the default kept
}

// movements.c's read_movement: T's direction made unit (or of length I, at most as long as T),
// A, E, S by their first letter; a tropism without a direction is an error at its line.
TEST(VlabViewFile, TropismAndTorqueLinesAreMovements) {
    const ViewFile v = readViewFile("tropism: T: 0 2 0 I: 0.5 A: 90 E: 0.3 S: 0.1\ntorque: T: 3,0,4\ntropism: A: 10\n");
    ASSERT_EQ(v.movements.size(), 2u);
    EXPECT_FALSE(v.movements[0].torque);
    EXPECT_NEAR(v.movements[0].direction[1], 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(v.movements[0].angle, 90);
    EXPECT_DOUBLE_EQ(v.movements[0].elasticity, 0.3);
    EXPECT_DOUBLE_EQ(v.movements[0].step, 0.1);
    EXPECT_TRUE(v.movements[1].torque);
    EXPECT_NEAR(v.movements[1].direction[0], 0.6, 1e-12);
    EXPECT_NEAR(v.movements[1].direction[2], 0.8, 1e-12);
    EXPECT_TRUE(hasMessage(v.diagnostics, 3, "a direction 'T: x y z' that is not 0 0 0", Severity::Error));
}

TEST(VlabAnimationFile, ReadsTheFramesAndTheFlags) {
    const AnimationFile a = readAnimationFile(
        "double buffer: off\nclear between frames: on\nswap interval: 0\nfirst frame: 2\nlast frame: 10\nstep: 3\nwhat: 1\n");
    EXPECT_FALSE(a.doubleBuffer);
    EXPECT_TRUE(a.clearBetweenFrames);
    EXPECT_EQ(a.swapInterval, 0);
    EXPECT_EQ(a.frames(20), (std::vector<int>{2, 5, 8}));
    EXPECT_TRUE(hasMessage(a.diagnostics, 7, "unknown animation command 'what:'", Severity::Warning));
    // last frame -1: the derivation length
    EXPECT_EQ(readAnimationFile("first frame: 0\nlast frame: -1\nstep: 2\n").frames(5), (std::vector<int>{0, 2, 4}));
    EXPECT_EQ(readAnimationFile("frame intervals: 1-3, 6, 8-12 step 2\n").frames(20), (std::vector<int>{1, 2, 3, 6, 8, 10, 12}));
    const AnimationFile bad = readAnimationFile("\n\nstep: often\n");
    EXPECT_FALSE(bad.ok());
    EXPECT_TRUE(hasMessage(bad.diagnostics, 3, "'step:' expects a whole number; found 'often'", Severity::Error));
}

TEST(VlabColours, MaterialsAsMeditWritesThem) {
    std::string bytes;
    // index 1: opaque, diffuse pure red, specular grey, shininess 40
    bytes += std::string{char(1), char(0), char(10), char(10), char(10), char(255), char(0), char(0), char(0), char(0), char(0),
                         char(128), char(128), char(128), char(40)};
    // index 200: half transparent, emissive blue
    bytes += std::string{char(200), char(128), 0, 0, 0, 0, 0, 0, 0, 0, char(255), 0, 0, 0, 0};
    std::string error;
    auto set = readMaterials(bytes, error);
    ASSERT_TRUE(set) << error;
    EXPECT_EQ(set->count, 2);
    ASSERT_TRUE(set->materials[1]);
    EXPECT_FLOAT_EQ(set->materials[1]->diffuse[0], 1.0f);
    EXPECT_NEAR(set->materials[1]->specular[1], 128 / 255.0, 1e-6);
    EXPECT_FLOAT_EQ(set->materials[1]->shininess, 40);
    EXPECT_EQ(materialColour(*set->materials[1]), 0xFF0000FFu);
    EXPECT_NEAR(set->materials[200]->transparency, 128 / 255.0, 1e-6);
    EXPECT_EQ(materialColour(*set->materials[200]), 0x0000FF7Fu);
    EXPECT_FALSE(set->materials[2]);
    // cut short: the offset of the broken record
    EXPECT_FALSE(readMaterials(bytes.substr(0, 20), error));
    EXPECT_NE(error.find("byte 15: a material of 5 bytes; expected 15"), std::string::npos) << error;
    EXPECT_FALSE(readMaterials("", error));
}

TEST(VlabColours, ColourMapsAsPaletteWritesThem) {
    std::string bytes(768, '\0');
    bytes[3 * 7] = char(255);
    bytes[3 * 7 + 2] = char(16);
    std::string error;
    auto map = readColourMap(bytes, error);
    ASSERT_TRUE(map) << error;
    EXPECT_EQ(map->colours[7], 0xFF0010u);
    EXPECT_EQ(map->colours[8], 0u);
    EXPECT_FALSE(readColourMap(bytes.substr(0, 300), error));
    EXPECT_NE(error.find("byte 300: expected 768 bytes"), std::string::npos) << error;
    EXPECT_EQ(colourSetNumber("-M"), 1);
    EXPECT_EQ(colourSetNumber("-m3"), 3);
    EXPECT_EQ(colourSetNumber("-M0"), 0);
    EXPECT_FALSE(colourSetNumber("-m12"));
}

}  // namespace
}  // namespace sprout::vlab
