// A VLab object's picture (issue 50): its view file's camera, its colour map's or material
// set's colours, its window size and its animation file's steps, as `sprout render FOLDER`
// draws them. The objects are written here, their binary files too.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/image.hpp"
#include "tests/app/run_sprout.hpp"

using namespace sprout_test;
namespace fs = std::filesystem;

namespace {

struct Object {
    fs::path folder;
    explicit Object(const std::string& name) : folder(fs::path(testing::TempDir()) / (name + "_" + std::to_string(getpid()))) {
        fs::create_directories(folder);
        write("plant.l", "Lsystem: 1\nderivation length: 4\nAxiom: A\nA --> F[+A][-A]\nendlsystem\n");
    }
    ~Object() { fs::remove_all(folder); }
    void write(const std::string& name, const std::string& bytes) const { std::ofstream(folder / name, std::ios::binary) << bytes; }
    void cpfg(const std::string& line) const { write("specifications", "plant.l\nplant.v\nignore:\n*\nmodel:\n\t" + line + "\n"); }
    // The folder rendered; the picture read back.
    sprout::Image render(const std::string& options = "--size 320x240") const {
        const std::string png = (folder / "shot.png").string();
        const Result r = runSprout("render " + folder.string() + " -o " + png + " " + options);
        EXPECT_EQ(r.code, 0) << r.err;
        sprout::Image image;
        std::string error;
        EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
        return image;
    }
};

const std::string kView = "angle factor: 8\ninitial color: 5\nline style: cylinder\ninitial line width: 0.25\n";

// A colour map of 256 RGB triples: colour 0 `background`, colour 5 `plant`, the rest grey.
std::string colourMap(std::uint32_t background, std::uint32_t plant) {
    std::string bytes(768, char(128));
    for (auto [k, c] : {std::pair<int, std::uint32_t>{0, background}, {5, plant}})
        for (int i = 0; i < 3; ++i) bytes[size_t(3 * k + i)] = char(c >> (16 - 8 * i) & 0xFF);
    return bytes;
}

int count(const sprout::Image& im, bool (*test)(const std::uint8_t*)) {
    int n = 0;
    for (size_t i = 0; i + 3 < im.rgba.size(); i += 4) n += test(&im.rgba[i]);
    return n;
}
bool blue(const std::uint8_t* p) { return p[2] > 120 && p[0] < 60 && p[1] < 60; }
bool red(const std::uint8_t* p) { return p[0] > 100 && p[1] < 50 && p[2] < 50; }
bool yellow(const std::uint8_t* p) { return p[0] > 220 && p[1] > 220 && p[2] < 40; }

// The columns and rows where the picture is not its corner's colour.
struct Extent {
    int width = 0, height = 0;
};
Extent extent(const sprout::Image& im) {
    const std::uint8_t* bg = im.rgba.data();
    int x0 = im.width, x1 = -1, y0 = im.height, y1 = -1;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const std::uint8_t* p = &im.rgba[(size_t(y) * size_t(im.width) + size_t(x)) * 4];
            if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 60)
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    return {x1 - x0 + 1, y1 - y0 + 1};
}

TEST(VlabPicture, TheColourMapColoursThePlantAndItsBackground) {
    Object o("vlab_map");
    o.write("plant.v", kView);
    o.write("plant.map", colourMap(0xFFFF00, 0x0000FF));
    o.cpfg("cpfg plant.l plant.v");
    const sprout::Image without = o.render();
    o.cpfg("cpfg -m plant.map plant.l plant.v");
    const sprout::Image with = o.render();
    EXPECT_EQ(count(without, blue), 0);
    EXPECT_GT(count(with, blue), 300) << "colour 5 of the map draws the plant";
    EXPECT_TRUE(yellow(with.rgba.data())) << "colour 0 of the map is the background";
    EXPECT_FALSE(yellow(without.rgba.data()));
    // Another map, another colour: the same pixels now red.
    o.write("plant.map", colourMap(0xFFFF00, 0xFF0000));
    EXPECT_GT(count(o.render(), red), 300);
}

TEST(VlabPicture, TheMaterialSetColoursThePlant) {
    Object o("vlab_mat");
    o.write("plant.v", kView);
    // medit's records: index, transparency, ambient, diffuse, emission, specular, shininess.
    std::string mat;
    mat += std::string{0, 0, 0, 0, 0, 0, 0, 0, char(255), char(255), 0, 0, 0, 0, 0};  // 0: emits yellow (the background)
    mat += std::string{5, 0, 20, 0, 0, char(220), 0, 0, 0, 0, 0, 60, 60, 60, 30};      // 5: diffuse red
    o.write("plant.mat", mat);
    o.cpfg("cpfg -M plant.mat plant.l plant.v");
    const sprout::Image with = o.render();
    EXPECT_GT(count(with, red), 300);
    EXPECT_TRUE(yellow(with.rgba.data()));
    // A material set cut short: the file, the byte and what was expected; cpfg's defaults drawn.
    o.write("plant.mat", mat.substr(0, 20));
    const Result r = runSprout("render " + o.folder.string() + " -o " + (o.folder / "cut.png").string() + " --size 64x48");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find((o.folder / "plant.mat").string() + ": byte 15: a material of 5 bytes; expected 15"), std::string::npos) << r.err;
}

// A material's specular colour and shininess (the exponent cpfg gives OpenGL) are its
// highlight, and its transparency lets the background through (issue 53).
TEST(VlabPicture, AMaterialsSpecularAndTransparencyAreDrawn) {
    Object o("vlab_shine");
    o.write("plant.v", kView);
    // Material 0 emits black (the background); material 5 a red with this specular grey, shininess and transparency.
    auto material = [](char specular, char shininess, char transparency) {
        return std::string(15, char(0)) + std::string{5, transparency, 20, 0, 0, char(150), 0, 0, 0, 0, 0, specular, specular, specular, shininess};
    };
    auto brightest = [](const sprout::Image& im) {
        int best = 0;
        for (size_t i = 0; i + 3 < im.rgba.size(); i += 4) best = std::max(best, im.rgba[i] + im.rgba[i + 1] + im.rgba[i + 2]);
        return best;
    };
    auto redSum = [](const sprout::Image& im) {
        long sum = 0;
        for (size_t i = 0; i + 3 < im.rgba.size(); i += 4) sum += im.rgba[i];
        return sum;
    };
    o.cpfg("cpfg -M plant.mat plant.l plant.v");
    o.write("plant.mat", material(0, 0, 0));
    const sprout::Image dull = o.render();
    o.write("plant.mat", material(char(255), 40, 0));
    const sprout::Image shiny = o.render();
    EXPECT_GT(brightest(shiny), brightest(dull) + 150) << brightest(shiny) << " against " << brightest(dull);
    o.write("plant.mat", material(0, 0, char(200)));
    const sprout::Image glass = o.render();
    EXPECT_LT(2 * redSum(glass), redSum(dull)) << "a transparency of 200/255 over black is a faint red";
    // An emission is light of its own, added after the lighting: a black material emitting red
    // is the same red across each stem, lit side and shaded side (not a red colour shaded).
    const std::string glowing = std::string(15, char(0)) + std::string{5, 0, 0, 0, 0, 0, 0, 0, char(200), 0, 0, 0, 0, 0, 0};
    o.write("plant.mat", glowing);
    const sprout::Image glow = o.render();
    std::vector<int> reds;  // the stems' (their antialiased edges, a tenth each side, left out)
    for (size_t i = 0; i + 3 < glow.rgba.size(); i += 4)
        if (glow.rgba[i] > 60) reds.push_back(glow.rgba[i]);
    ASSERT_GT(reds.size(), 200u);
    std::sort(reds.begin(), reds.end());
    const int lo = reds[reds.size() / 10], hi = reds[reds.size() * 9 / 10];
    EXPECT_GT(hi, 150) << "the stems glow red";
    EXPECT_LT(hi - lo, 30) << "evenly: " << lo << " to " << hi;
}

TEST(VlabPicture, TheViewFilesCameraFramesThePicture) {
    Object o("vlab_camera");
    o.cpfg("cpfg -m plant.map plant.l plant.v");
    o.write("plant.map", colourMap(0xFFFFFF, 0x0000FF));
    auto view = [&](const std::string& camera, const std::string& options = "--size 320x240") {
        o.write("plant.v", kView + camera);
        return o.render(options);
    };
    const sprout::Image frontImage = view("viewpoint: 0,0,1\nview reference point: 0,0,0\n");
    const Extent front = extent(frontImage);
    ASSERT_GT(front.width, 100);
    // From the side the flat plant is edge-on: only its stems' thickness is left across.
    const Extent side = extent(view("viewpoint: 1,0,0\nview reference point: 0,0,0\n"));
    EXPECT_LT(side.width, front.width / 3) << side.width << " " << front.width;
    EXPECT_NEAR(side.height, front.height, front.height / 10);
    // A twist of 900 tenths of a degree turns the picture a quarter: the wide plant stands tall.
    const Extent turned = extent(view("viewpoint: 0,0,1\ntwist: 900\n"));
    EXPECT_NEAR(double(turned.width) / turned.height, double(front.height) / front.width, 0.08) << turned.width << "x" << turned.height;
    // The scale factor: half as big.
    const Extent half = extent(view("scale factor: 0.5\n"));
    EXPECT_NEAR(double(half.height) / front.height, 0.5, 0.06);
    // Perspective against parallel, seen from above and aside: not the same picture.
    const sprout::Image parallel = view("viewpoint: 3,2,3\nprojection: parallel\n");
    const sprout::Image perspective = view("viewpoint: 3,2,3\nprojection: perspective\nviewing angle: 70\n");
    int differ = 0;
    for (size_t i = 0; i < parallel.rgba.size(); i += 4) differ += std::abs(parallel.rgba[i + 2] - perspective.rgba[i + 2]) > 60;
    EXPECT_GT(differ, 500);
    // -w: the window's size, unless --size says otherwise.
    o.cpfg("cpfg -w 200 150 -m plant.map plant.l plant.v");
    const sprout::Image small = view("", "");
    EXPECT_EQ(small.width, 200);
    EXPECT_EQ(small.height, 150);
}

TEST(VlabPicture, TheAnimationFileSaysWhichStepsGrowthShows) {
    Object o("vlab_animation");
    o.write("plant.v", kView);
    o.write("plant.a", "double buffer: on\nfirst frame: 1\nlast frame: 4\nstep: 2\n");
    o.cpfg("cpfg plant.l plant.v plant.a");
    const std::string base = (o.folder / "grow").string();
    const Result r = runSprout("render " + o.folder.string() + " --animate growth --size 96x64 -o " + base + ".png");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(base + "_0001.png"));  // step 1
    EXPECT_TRUE(fs::exists(base + "_0002.png"));  // step 3
    EXPECT_FALSE(fs::exists(base + "_0003.png"));
    // A wrong value in the animation file: its file and line, and what was expected.
    o.write("plant.a", "first frame: 1\nstep: often\n");
    const Result bad = runSprout("expand " + o.folder.string());
    EXPECT_NE(bad.err.find((o.folder / "plant.a").string() + ":2:1: 'step:' expects a whole number; found 'often'"), std::string::npos) << bad.err;
}

// Issue 50: every object of VLab's manuals (../shared/corpus/vlab-manuals) opens as an object
// and draws with `sprout render FOLDER`: exit 0, and a picture with something on it (pixels
// other than the background's, the corner's colour). Names every one that does not.
TEST(VlabPicture, EveryManualObjectDraws) {
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals";
    if (!fs::is_directory(root)) GTEST_SKIP() << root << " is not here";
    std::vector<fs::path> objects;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.path().filename() == "specifications") objects.push_back(e.path().parent_path());
    std::sort(objects.begin(), objects.end());
    const fs::path png = fs::path(testing::TempDir()) / ("vlab_manual_" + std::to_string(getpid()) + ".png");
    std::string failures;
    int drawn = 0;
    for (const fs::path& folder : objects) {
        const std::string name = fs::relative(folder, root).string();
        fs::remove(png);
        const Result r = runSprout("render " + folder.string() + " -o " + png.string() + " --size 160x160");
        sprout::Image img;
        std::string error;
        if (r.code != 0 || !sprout::readPng(png.string(), img, error)) {
            failures += "  " + name + ": " + (r.code != 0 ? r.err : error) + "\n";
            continue;
        }
        size_t other = 0;
        for (size_t i = 0; i + 3 < img.rgba.size(); i += 4)
            other += std::abs(int(img.rgba[i]) - img.rgba[0]) + std::abs(int(img.rgba[i + 1]) - img.rgba[1]) +
                         std::abs(int(img.rgba[i + 2]) - img.rgba[2]) > 24;
        if (other * 500 < img.rgba.size() / 4) failures += "  " + name + ": the picture is empty\n";
        else ++drawn;
    }
    fs::remove(png);
    EXPECT_EQ(objects.size(), 29u);
    EXPECT_EQ(drawn, int(objects.size())) << failures;
}

// An SGI image (VLab's .rgb), 4 x 4, three channels, verbatim: red on one half, blue on the
// other; `topBottom`: the top half red, else the left half.
std::string halvesSgi(bool topBottom) {
    std::string sgi(512, char(0));
    const int header[][2] = {{0, 474}, {4, 3}, {6, 4}, {8, 4}, {10, 3}};
    for (auto [at, v] : header) sgi[size_t(at)] = char(v >> 8), sgi[size_t(at) + 1] = char(v & 0xFF);
    sgi[3] = 1;
    for (int channel = 0; channel < 3; ++channel)
        for (int y = 0; y < 4; ++y)  // the file's rows bottom first
            for (int x = 0; x < 4; ++x) {
                const bool red = topBottom ? y >= 2 : x < 2;
                sgi += char((channel == 0 && red) || (channel == 2 && !red) ? 255 : 0);
            }
    return sgi;
}

}  // namespace

// A VLab object's texture (issue 53): its view file's `texture: F: FILE` lines, chosen by
// `@Tx(n)`, on its `.s` surfaces, an SGI image (VLab's .rgb) read here; `@Tx` alone takes it off.
TEST(VlabPicture, ATextureLiesOnTheSurfacesAfterTx) {
    Object o("vlab_texture");
    // A flat square Bezier patch, 2 x 2, facing the camera.
    std::string patch = "-1 1 -1 1 0 0\nCONTACT POINT X: 0 Y: -1 Z: 0\nEND POINT X: 0 Y: 1 Z: 0\nHEADING X: 0 Y: 1 Z: 0\n"
                        "UP X: 0 Y: 0 Z: 1\nSIZE: 2\nsquare\nTOP COLOR: 0 DIFFUSE: 0 BOTTOM COLOR: 0 DIFFUSE: 0\n"
                        "AL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n";
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) patch += std::to_string(-1 + 2 * col / 3.0) + " " + std::to_string(1 - 2 * row / 3.0) + " 0  ";
        patch += "\n";
    }
    o.write("square.s", patch);
    o.write("halves.rgb", halvesSgi(false));  // the left half red, the right half blue
    o.write("plant.v", kView + "surface: l square.s 1\ntexture: F: halves.rgb E: m S:\n");
    o.write("plant.map", colourMap(0x000000, 0xFFFFFF));
    o.cpfg("cpfg -m plant.map plant.l plant.v");
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: [f] ;(5) @Tx(1) ~l(1)\nendlsystem\n");
    const sprout::Image textured = o.render();
    EXPECT_GT(count(textured, red), 1000);
    EXPECT_GT(count(textured, blue), 1000);
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: [f] ;(5) @Tx(1) @Tx ~l(1)\nendlsystem\n");
    const sprout::Image plain = o.render();
    EXPECT_EQ(count(plain, red), 0) << "no texture: the surface in its colour";
    EXPECT_EQ(count(plain, blue), 0);
    EXPECT_GT(extent(plain).width, 60) << "the white square is drawn";
}

// On a generalized cylinder cpfg keeps a texture's proportions (update_segment_texture): the
// image's height along the tube is pi x its width x R: (its aspect 1 here); R: 0.5 puts it twice
// as often along the same tube.
TEST(VlabPicture, ATubesTextureKeepsCpfgsProportions) {
    Object o("vlab_tube_texture");
    o.write("halves.rgb", halvesSgi(true));  // the top half red, the bottom half blue
    o.write("plant.map", colourMap(0x000000, 0xFFFFFF));
    o.cpfg("cpfg -m plant.map plant.l plant.v");
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: #(0.5) ;(5) @Tx(1) @Gs F(2) F(2) F(2) F(2) @Ge\nendlsystem\n");
    auto bands = [&](const char* ratio) {
        o.write("plant.v", kView + "texture: F: halves.rgb E: m R: " + ratio + "\n");
        const sprout::Image im = o.render("--size 240x320");
        // Colour changes up the picture's middle column.
        int changes = 0, last = 0;
        for (int y = 0; y < im.height; ++y) {
            const std::uint8_t* p = &im.rgba[(size_t(y) * size_t(im.width) + size_t(im.width / 2)) * 4];
            const int now = red(p) ? 1 : blue(p) ? 2 : 0;
            if (now && now != last) ++changes, last = now;
        }
        return changes;
    };
    const int one = bands("1"), half = bands("0.5");
    EXPECT_GE(one, 4) << "8 units long, 0.5 wide: the image about 5 times along, two bands each";
    EXPECT_GT(half, one * 3 / 2) << one << " bands at R: 1, " << half << " at R: 0.5";
}

// After @Tx(n) cpfg textures the stems (as its tubes, the image's proportions kept) and the
// polygons (spread over the outline: the left half of the image left, the right half right).
TEST(VlabPicture, StemsAndPolygonsAfterTxWearTheTexture) {
    Object o("vlab_stem_texture");
    o.write("halves.rgb", halvesSgi(true));  // the top half red, the bottom half blue
    o.write("plant.map", colourMap(0x000000, 0xFFFFFF));
    o.write("plant.v", kView + "texture: F: halves.rgb E: m R: 1\n");
    o.cpfg("cpfg -m plant.map plant.l plant.v");
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: #(0.5) ;(5) @Tx(1) F(2) F(2) F(2) F(2)\nendlsystem\n");
    const sprout::Image stem = o.render("--size 240x320");
    int changes = 0, last = 0;
    for (int y = 0; y < stem.height; ++y) {
        const std::uint8_t* p = &stem.rgba[(size_t(y) * size_t(stem.width) + size_t(stem.width / 2)) * 4];
        const int now = red(p) ? 1 : blue(p) ? 2 : 0;
        if (now && now != last) ++changes, last = now;
    }
    EXPECT_GE(changes, 4) << "the image's bands along the stems, as along a tube of their width";
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: ;(5) @Tx(1) {. f(2) . +(90) f(2) . +(90) f(2) . +(90) f(2) .}\nendlsystem\n");
    const sprout::Image square = o.render();
    EXPECT_GT(count(square, red), 1000) << "the image's top half on the polygon";
    EXPECT_GT(count(square, blue), 1000) << "and its bottom half";
    o.write("plant.l", "Lsystem: 1\nderivation length: 0\nAxiom: ;(5) {. f(2) . +(90) f(2) . +(90) f(2) . +(90) f(2) .}\nendlsystem\n");
    EXPECT_EQ(count(o.render(), red), 0) << "no @Tx: the polygon in its colour";
}
