// A VLab object's background scene (cpfg's `background scene:`) in what `sprout render` and
// `sprout export` make of the object: the scene's shapes in the picture's pixels and in the
// exported triangles, its file's mistakes reported at their line. The objects are written here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/image.hpp"
#include "tests/app/run_sprout.hpp"

using namespace sprout_test;
namespace fs = std::filesystem;

namespace {

struct Object {
    fs::path folder;
    explicit Object(const std::string& name) : folder(fs::path(testing::TempDir()) / (name + "_" + std::to_string(getpid()))) {
        fs::create_directories(folder);
        write("plant.l", "Lsystem: 1\nderivation length: 3\nAxiom: A\nA --> F[+A][-A]\nendlsystem\n");
        // A colour map: 0 white (the window), 5 blue (the plant), the rest grey.
        std::string map(768, char(128));
        for (int i = 0; i < 3; ++i) map[size_t(i)] = char(255);
        map[15] = 0, map[16] = 0, map[17] = char(255);
        write("plant.map", map);
        cpfg("cpfg -m plant.map plant.l plant.v");
    }
    ~Object() { fs::remove_all(folder); }
    void write(const std::string& name, const std::string& bytes) const { std::ofstream(folder / name, std::ios::binary) << bytes; }
    void cpfg(const std::string& line) const { write("specifications", "plant.l\nplant.v\nignore:\n*\nmodel:\n\t" + line + "\n"); }
    void view(const std::string& more) const {
        write("plant.v", "angle factor: 8\ninitial color: 5\nline style: cylinder\ninitial line width: 0.1\n"
                         "viewpoint: 0,0,1\nview reference point: 0,0,0\nlight direction: 0,0,1\n" + more);
    }
    Result render(sprout::Image& image) const {
        const std::string png = (folder / "shot.png").string();
        const Result r = runSprout("render " + folder.string() + " -o " + png + " --size 240x180");
        std::string error;
        EXPECT_TRUE(sprout::readPng(png, image, error)) << error << r.err;
        return r;
    }
};

int count(const sprout::Image& im, bool (*test)(const std::uint8_t*)) {
    int n = 0;
    for (size_t i = 0; i + 3 < im.rgba.size(); i += 4) n += test(&im.rgba[i]);
    return n;
}
bool red(const std::uint8_t* p) { return p[0] > 120 && p[1] < 60 && p[2] < 60; }
bool blue(const std::uint8_t* p) { return p[2] > 120 && p[0] < 60 && p[1] < 60; }

size_t faces(const std::string& obj) {
    std::ifstream in(obj);
    std::string line;
    size_t n = 0;
    while (std::getline(in, line)) n += line.rfind("f ", 0) == 0;
    return n;
}

// The square behind the plant (the plant grows up from the origin in the z = 0 plane), red.
const std::string kScene = "#define FAR -1\nmaterial\n0 0 0 1\n1 0 0 1\npolygon\n-9 -9 FAR  9 -9 FAR  9 9 FAR  -9 9 FAR\n";

}  // namespace

TEST(VlabBackgroundScene, TheSceneIsInThePictureBehindThePlant) {
    Object o("vlab_background");
    o.write("back.dat", kScene);
    o.view("");
    sprout::Image without, with;
    ASSERT_EQ(o.render(without).code, 0);
    o.view("background scene: back.dat\n");
    const Result r = o.render(with);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("back.dat"), std::string::npos) << r.err;
    EXPECT_EQ(count(without, red), 0);
    // The square fills what the plant leaves of the picture (cpfg frames the plant alone, so
    // the scene reaches past the picture's edges), and the plant stays in front of it.
    EXPECT_GT(count(with, red), int(with.rgba.size() / 4) * 6 / 10);
    EXPECT_GT(count(with, blue), 100);
    EXPECT_NEAR(count(with, blue), count(without, blue), count(without, blue) / 5);
    // Between the camera and the plant, the same square hides it.
    o.write("back.dat", "#define FAR 0.5\n" + kScene.substr(kScene.find('\n') + 1));
    o.render(with);
    EXPECT_EQ(count(with, blue), 0);
}

TEST(VlabBackgroundScene, TheSceneIsExported) {
    Object o("vlab_background_export");
    o.write("back.dat", kScene + "prism 1 1 1\n");
    o.view("");
    const std::string obj = (o.folder / "plant.obj").string();
    ASSERT_EQ(runSprout("export " + o.folder.string() + " -o " + obj).code, 0);
    const size_t plant = faces(obj);
    o.view("background scene: back.dat\n");
    const Result r = runSprout("export " + o.folder.string() + " -o " + obj);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(faces(obj), plant + 2 + 12) << "the square's 2 triangles and the box's 12";
}

TEST(VlabBackgroundScene, MistakesAreReportedAtTheirLine) {
    Object o("vlab_background_bad");
    o.write("back.dat", "material 0 0 0 1 1 0 0 1\nsphere\npolygon 0 0 0 1 0 0\n");
    o.view("background scene: back.dat\n");
    sprout::Image image;
    Result r = o.render(image);
    EXPECT_EQ(r.code, 0) << r.err;
    const std::string file = (o.folder / "back.dat").string();
    EXPECT_NE(r.err.find(file + ":3:1: 'sphere' expects a radius; found 'polygon'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(file + ":3:1: 'polygon' expects at least 3 points, x y z each; the file ends after 6 numbers"), std::string::npos)
        << r.err;
    // A scene file that is missing, and an object without colours, which cpfg draws none for.
    o.view("background scene: gone.dat\n");
    r = o.render(image);
    EXPECT_NE(r.err.find((o.folder / "gone.dat").string() + ": cannot be read: No such file or directory"), std::string::npos) << r.err;
    o.write("back.dat", kScene);
    o.view("background scene: back.dat\n");
    o.cpfg("cpfg plant.l plant.v");
    r = o.render(image);
    EXPECT_NE(r.err.find((o.folder / "plant.v").string() +
                         ":8:1: warning: cpfg draws a background scene only with a material set or a colour map"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(count(image, red), 0);
}
