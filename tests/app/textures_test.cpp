// Textures as the picture shows them (issue 53): an image of four coloured quarters on an L-Py
// patch, rendered through the program as a user runs it, under each of L-Py's texture
// transforms; the quarter seen at each of 16 places of the patch is the one PlantGL's
// Texture2DTransformation puts there. And the image files themselves: PNG, JPEG, SGI, broken.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app/image.hpp"
#include "app/mesh/texture_images.hpp"
#include "tests/app/quarters.hpp"
#include "tests/app/run_sprout.hpp"

namespace {

using sprout_test::runSprout;
using sprout_test::writeTemp;

using namespace sprout_test::quarters;

// An L-Py model: a square patch `quad` (in the x = 0 plane, facing the front view), material 1
// a texture of `image`, and `axiom`.
std::string quadModel(const std::string& image, const std::string& axiom) {
    return "from openalea.plantgl.all import *\n"
           "quad = NurbsPatch([[(0, -1, -1, 1), (0, -1, 1, 1)], [(0, 1, -1, 1), (0, 1, 1, 1)]], udegree=1, vdegree=1)\n"
           "context().turtle.setMaterial(1, ImageTexture('" + image + "'))\n"
           "Axiom: " + axiom + "\nderivation length: 0\n";
}

// A square patch facing the front view, textured with the image by material 1, with
// `transform` (L-Py's modules) before it.
sprout::Image render(const std::string& name, const std::string& transform, const std::string& shape = "@g(quad)") {
    const std::string dir = testing::TempDir();
    std::string error;
    EXPECT_TRUE(sprout::writePng(dir + "quarters.png", quarters(), error)) << error;
    const std::string path = writeTemp(name + ".lpy", quadModel("quarters.png", transform + " " + shape)), png = dir + name + ".png";
    const auto r = runSprout("render " + path + " -o " + png + " --size 240x240 --view front --no-ground --no-shadows");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    sprout::Image image;
    EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
    return image;
}

// Where (u, v) lies in the picture, from the centres of the four quarters seen untransformed.
struct Mapping {
    std::array<double, 2> centre[4]{};
    std::array<double, 2> at(double u, double v) const {
        // Bilinear between the quarters' centres at (0.25 | 0.75, 0.25 | 0.75).
        const double s = (u - 0.25) / 0.5, t = (v - 0.25) / 0.5;
        std::array<double, 2> p{};
        for (int k = 0; k < 2; ++k)
            p[size_t(k)] = (1 - s) * (1 - t) * centre[Blue][size_t(k)] + s * (1 - t) * centre[Yellow][size_t(k)] +
                           (1 - s) * t * centre[Red][size_t(k)] + s * t * centre[Green][size_t(k)];
        return p;
    }
};

Mapping mappingOf(const sprout::Image& plain) {
    Mapping m;
    double n[4] = {0, 0, 0, 0};
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x)
            if (const Quarter q = classify(plain, x, y); q != None) m.centre[q][0] += x, m.centre[q][1] += y, ++n[q];
    for (int q = 0; q < 4; ++q) {
        EXPECT_GT(n[q], 200) << kNames[q] << " is seen on the untransformed patch";
        if (n[q] > 0) m.centre[q][0] /= n[q], m.centre[q][1] /= n[q];
    }
    return m;
}

// The 16 places (i + 1/2) / 4 of the patch show the quarters `transform(u, v)` names.
template <class F>
void expectQuarters(const sprout::Image& picture, const Mapping& m, F transform, const char* what) {
    int wrong = 0;
    std::string seen;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double u = (i + 0.5) / 4, v = (j + 0.5) / 4;
            const auto p = m.at(u, v);
            const auto [tu, tv] = transform(u, v);
            const Quarter want = quarterAt(tu, tv), got = classify(picture, int(std::lround(p[0])), int(std::lround(p[1])));
            if (want != got) ++wrong, seen += std::string(" (") + std::to_string(u) + "," + std::to_string(v) + "): " + kNames[got] + " not " + kNames[want];
        }
    EXPECT_EQ(wrong, 0) << what << seen;
}

}  // namespace

// The image on the patch, and each of L-Py's transforms moving it as PlantGL's
// Texture2DTransformation does: (u, v) scaled, turned about the centre, then moved.
TEST(Textures, AnImageLiesOnAPatchAsLpysTransformsPutIt) {
    const sprout::Image plain = render("tex_plain", "");
    ASSERT_EQ(plain.width, 240);
    const Mapping m = mappingOf(plain);
    // The quarters stand apart on the patch: it faces the camera.
    EXPECT_GT(std::hypot(m.centre[Blue][0] - m.centre[Green][0], m.centre[Blue][1] - m.centre[Green][1]), 60);
    expectQuarters(plain, m, [](double u, double v) { return std::pair{u, v}; }, "untransformed");
    expectQuarters(render("tex_scale", "TextureScale(2)"), m, [](double u, double v) { return std::pair{2 * u, 2 * v}; }, "TextureScale(2)");
    expectQuarters(render("tex_uscale", "TextureUScale(2)"), m, [](double u, double v) { return std::pair{2 * u, v}; }, "TextureUScale(2)");
    expectQuarters(render("tex_vscale", "TextureVScale(2)"), m, [](double u, double v) { return std::pair{u, 2 * v}; }, "TextureVScale(2)");
    expectQuarters(render("tex_move", "TextureTranslation(0.5, 0.25)"), m, [](double u, double v) { return std::pair{u + 0.5, v + 0.25}; },
                   "TextureTranslation(0.5, 0.25)");
    // A quarter turn about (0.5, 0.5): (u, v) - centre turned by 90 degrees.
    expectQuarters(render("tex_turn", "TextureRotation(90)"), m, [](double u, double v) { return std::pair{0.5 - (v - 0.5), 0.5 + (u - 0.5)}; },
                   "TextureRotation(90)");
    expectQuarters(render("tex_all", "TextureTransformation(1, 1, 0.5, 0, 180, 0.5, 0.5)"), m,
                   [](double u, double v) { return std::pair{1.0 - u + 0.5, 1.0 - v}; }, "TextureTransformation(... 180 ...)");
}

// A model whose texture image is not there: a warning that names it, the patch in its colour.
TEST(Textures, AMissingImageIsAWarningAndTheColour) {
    const std::string path = writeTemp("tex_missing.lpy", quadModel("no_such_leaf.png", "@g(quad)")), png = testing::TempDir() + "tex_missing.png";
    const auto r = runSprout("render " + path + " -o " + png + " --size 120x120 --view front --no-ground --no-shadows");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("no_such_leaf.png"), std::string::npos) << r.err;
    sprout::Image image;
    std::string error;
    ASSERT_TRUE(sprout::readPng(png, image, error)) << error;
    int grey = 0;  // the base colour, white, lit: greys
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t k = (std::size_t(y) * 120 + std::size_t(x)) * 4;
            const int r0 = image.rgba[k], g0 = image.rgba[k + 1], b0 = image.rgba[k + 2];
            grey += r0 > 90 && std::abs(r0 - g0) < 12 && std::abs(g0 - b0) < 12;
        }
    EXPECT_GT(grey, 1000);
}

// The image files: PNG and JPEG through their libraries, SGI (verbatim and run-length, as
// VLab's `.rgb` images) read here; anything broken is an error, never a crash.
TEST(Textures, ImageFilesAreReadOrRefused) {
    std::string error;
    const std::string dir = testing::TempDir();
    ASSERT_TRUE(sprout::writePng(dir + "q.png", quarters(), error)) << error;
    const auto png = sprout::mesh::textureImage(dir + "q.png");
    ASSERT_EQ(png->error, "");
    EXPECT_EQ(png->width, 16);
    EXPECT_EQ(png->rgba[0], 255);  // top left: red
    EXPECT_EQ(png->rgba[2], 0);
    EXPECT_EQ(sprout::mesh::textureImage(dir + "q.png"), png) << "read once";

    // SGI, 2 x 2, three channels, verbatim: rows bottom first, channel by channel.
    std::string sgi(512, '\0');
    auto put16 = [&](std::string& s, std::size_t at, int v) { s[at] = char(v >> 8), s[at + 1] = char(v & 0xFF); };
    put16(sgi, 0, 474);
    sgi[3] = 1;        // a byte a channel
    put16(sgi, 4, 3);  // dimension
    put16(sgi, 6, 2), put16(sgi, 8, 2), put16(sgi, 10, 3);
    const std::string planes = std::string("\x10\x20\x30\x40", 4) + std::string("\x50\x60\x70\x80", 4) + std::string("\x90\xA0\xB0\xC0", 4);
    const auto verbatim = sprout::mesh::decodeImage(sgi + planes);
    ASSERT_EQ(verbatim.error, "");
    EXPECT_EQ(verbatim.format, "sgi");
    // The file's first row (0x10 0x20 ...) is the image's bottom one.
    EXPECT_EQ(verbatim.rgba[(2 + 0) * 4 + 0], 0x10);
    EXPECT_EQ(verbatim.rgba[(2 + 1) * 4 + 1], 0x60);
    EXPECT_EQ(verbatim.rgba[0 * 4 + 2], 0xB0);  // top left: the second row's first, blue plane
    // The same run-length: a row table of starts and lengths, then runs.
    std::string rle = sgi;
    rle[2] = 1;
    std::string runs, starts, lengths;
    const std::size_t first = 512 + 6 * 4 * 2;
    for (int row = 0; row < 6; ++row) {
        const std::string data = planes.substr(std::size_t(row) * 2, 2);
        std::string r = row % 2 ? std::string("\x82", 1) + data + std::string("\0", 1)                                  // two copied
                                : (data[0] == data[1] ? std::string("\x02", 1) + data[0] : std::string("\x81", 1) + data[0] + "\x81" + data[1]) +
                                      std::string("\0", 1);
        const std::size_t at = first + runs.size();
        starts += std::string{char(at >> 24), char(at >> 16 & 0xFF), char(at >> 8 & 0xFF), char(at & 0xFF)};
        lengths += std::string{0, 0, 0, char(r.size())};
        runs += r;
    }
    const auto packed = sprout::mesh::decodeImage(rle + starts + lengths + runs);
    ASSERT_EQ(packed.error, "");
    EXPECT_EQ(packed.rgba, verbatim.rgba);
    // Broken files: errors, whatever their bytes.
    EXPECT_NE(sprout::mesh::decodeImage(rle + starts + lengths).error, "") << "runs missing";
    EXPECT_NE(sprout::mesh::decodeImage(sgi).error, "") << "pixels missing";
    EXPECT_NE(sprout::mesh::decodeImage("\x89PNG\r\n\x1a\nnot a png").error, "");
    EXPECT_NE(sprout::mesh::decodeImage("\xff\xd8\xff\xe0 not a jpeg").error, "");
    EXPECT_NE(sprout::mesh::decodeImage("GIF89a").error, "");
    EXPECT_NE(sprout::mesh::textureImage(dir + "nothing_here.png")->error.find("nothing_here.png"), std::string::npos);
}

// A JPEG photo, as L-Py's orchid's leaves: read through libjpeg (the corpus's own where it is).
TEST(Textures, AJpegPhotoIsRead) {
    const std::filesystem::path leaf = std::filesystem::path(SPROUT_SHARED_DIR) / "corpus/lpy/tutorial/10 - graphics/leaf1.jpg";
    if (!std::filesystem::exists(leaf)) GTEST_SKIP() << "the corpus's leaf1.jpg is not here";
    const auto jpeg = sprout::mesh::textureImage(leaf.string());
    ASSERT_EQ(jpeg->error, "");
    EXPECT_EQ(jpeg->format, "jpeg");
    EXPECT_EQ(jpeg->width, 1024);
    EXPECT_EQ(jpeg->height, 768);
    long green = 0;
    for (std::size_t k = 0; k < jpeg->rgba.size(); k += 4) green += jpeg->rgba[k + 1] > jpeg->rgba[k + 2];
    EXPECT_GT(green, 1024 * 768 / 3) << "a leaf: more green than blue";
}

// The exports carry the image: a .glb embeds it (TEXCOORD_0, a baseColorTexture, its clear
// parts cut away: MASK) and passes the Khronos validator with the same triangles as the
// picture; an .obj's .mtl names it (map_Kd), written beside, and its faces have texture
// coordinates.
TEST(Textures, ExportsCarryTheImage) {
    const std::string dir = testing::TempDir() + "tex_export/";
    std::filesystem::create_directories(dir);
    std::string error;
    ASSERT_TRUE(sprout::writePng(dir + "quarters.png", quarters(), error)) << error;
    std::ofstream(dir + "quad.lpy") << quadModel("quarters.png", "@g(quad) ,(2) F");
    const auto glb = runSprout("export " + dir + "quad.lpy -o " + dir + "quad.glb");
    ASSERT_EQ(glb.code, 0) << glb.err;
    const std::string validator = std::string(SPROUT_TOOLS_DIR) + "/validate_gltf.js";
    ASSERT_TRUE(std::filesystem::exists(std::string(SPROUT_TOOLS_DIR) + "/node_modules/gltf-validator"));
    const std::string report = dir + "report.json";
    EXPECT_EQ(std::system(("node " + validator + " " + dir + "quad.glb > " + report).c_str()), 0);
    std::ifstream in(report);
    const std::string r((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(r.find("\"errors\": 0"), std::string::npos) << r;
    EXPECT_NE(r.find("\"warnings\": 0"), std::string::npos) << r;
    EXPECT_NE(r.find("\"hasTextures\": true"), std::string::npos) << r;
    EXPECT_NE(r.find("\"maxUVs\": 1"), std::string::npos) << r;
    EXPECT_NE(r.find("\"width\": 16"), std::string::npos) << "the image embedded: " << r;
    std::ifstream g(dir + "quad.glb", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(g)), {});
    EXPECT_NE(bytes.find("\"alphaMode\":\"MASK\""), std::string::npos);
    EXPECT_NE(bytes.find("\"baseColorTexture\":{\"index\":0}"), std::string::npos);

    std::filesystem::create_directories(dir + "out");
    const auto obj = runSprout("export " + dir + "quad.lpy -o " + dir + "out/quad.obj");
    ASSERT_EQ(obj.code, 0) << obj.err;
    std::ifstream mtl(dir + "out/quad.mtl");
    const std::string m((std::istreambuf_iterator<char>(mtl)), {});
    EXPECT_NE(m.find("map_Kd quarters.png"), std::string::npos) << m;
    std::ifstream o(dir + "out/quad.obj");
    const std::string text((std::istreambuf_iterator<char>(o)), {});
    EXPECT_NE(text.find("\nvt "), std::string::npos);
    EXPECT_NE(text.find("/1/"), std::string::npos) << "faces with texture coordinates";
    EXPECT_NE(text.find("//"), std::string::npos) << "and the stem's without";
    const auto copied = sprout::mesh::textureImage(dir + "out/quarters.png");
    EXPECT_EQ(copied->error, "") << "the image beside the .obj";
    EXPECT_EQ(copied->width, 16);
}

// A generalized cylinder takes the image as PlantGL's Extrusion gives it: u around the section,
// v the length along the axis (the image again each unit); TextureVScale stretches it along.
TEST(Textures, AGeneralizedCylinderIsWrappedInTheImage) {
    auto quartersSeen = [](const sprout::Image& im, int* bands) {
        int n[5] = {0, 0, 0, 0, 0};
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) ++n[classify(im, x, y)];
        int kinds = 0;
        for (int q = 0; q < 4; ++q) kinds += n[q] > 80;
        // Colour changes down the middle column: how many bands the tube shows along its length.
        *bands = 0;
        Quarter last = None;
        for (int y = 0; y < im.height; ++y)
            if (const Quarter q = classify(im, im.width / 2, y); q != None && q != last) ++*bands, last = q;
        return kinds;
    };
    int bands = 0, stretched = 0;
    const sprout::Image tube = render("tex_tube", "_(0.4) @Gc F(1) F(1) F(1) F(1) @Ge", "");
    EXPECT_GE(quartersSeen(tube, &bands), 2) << "the image's quarters along the tube (half of it around is seen)";
    const sprout::Image longer = render("tex_tube_v", "_(0.4) TextureVScale(0.25) @Gc F(1) F(1) F(1) F(1) @Ge", "");
    quartersSeen(longer, &stretched);
    EXPECT_GE(bands, 6) << "4 units long: the image 4 times along, two quarters each";
    EXPECT_LE(stretched, 3) << "a quarter of the scale: the image once along the tube";
}

// A .lsys grammar's material with a texture: its generalized cylinders wear the image; a file
// that is not there is a warning at its line, the tube in its colour.
TEST(Textures, AnLsysMaterialsTextureWrapsItsTubes) {
    const std::string dir = testing::TempDir() + "tex_lsys/";
    std::filesystem::create_directories(dir);
    std::string error;
    ASSERT_TRUE(sprout::writePng(dir + "quarters.png", quarters(), error)) << error;
    auto renderLsys = [&](const std::string& name, const std::string& image, std::string* err) {
        std::ofstream(dir + name + ".lsys") << "n: 0\nwidth: 0.8\nmaterial: 1 #ffffff texture " + image +
                                                   "\naxiom: ;(1) @Gs F(1) F(1) F(1) F(1) @Ge\n";
        const auto r = runSprout("render " + dir + name + ".lsys -o " + dir + name + ".png --size 160x240 --view front --no-ground --no-shadows");
        EXPECT_EQ(r.code, 0) << r.err;
        *err = r.err;
        sprout::Image im;
        std::string e;
        EXPECT_TRUE(sprout::readPng(dir + name + ".png", im, e)) << e;
        return im;
    };
    std::string err;
    const sprout::Image tube = renderLsys("tube", "quarters.png", &err);
    int n[5] = {0, 0, 0, 0, 0};
    for (int y = 0; y < tube.height; ++y)
        for (int x = 0; x < tube.width; ++x) ++n[classify(tube, x, y)];
    EXPECT_GT(n[Red] + n[Green] + n[Blue] + n[Yellow], 1000) << "the image on the tube";
    EXPECT_EQ(err.find("warning"), std::string::npos) << err;
    const sprout::Image plain = renderLsys("missing", "no_bark.png", &err);
    EXPECT_NE(err.find(":3:"), std::string::npos) << "the warning at the material's line: " << err;
    EXPECT_NE(err.find("no_bark.png"), std::string::npos) << err;
    int coloured = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x) coloured += classify(plain, x, y) != None;
    EXPECT_LT(coloured, 50) << "no image: the tube white, lit";
}

// TextureBaseColor tints a texture material's image from then on (PlantGL's texBaseColor):
// the image's white drawn in that colour; InterpolateTextureBaseColors mixes two materials'.
TEST(Textures, TextureBaseColorTintsTheImage) {
    auto redness = [](const sprout::Image& im) {
        long r = 0, g = 0;
        for (std::size_t k = 0; k + 3 < im.rgba.size(); k += 4) r += im.rgba[k], g += im.rgba[k + 1];
        return double(r) / double(std::max(1L, g));
    };
    // Only the yellow and green quarters have green: tinted red, they lose it.
    const sprout::Image plain = render("tex_base_plain", "", "@g(quad)");
    const sprout::Image tinted = render("tex_base_red", "TextureBaseColor(255, 40, 40)", "@g(quad)");
    EXPECT_GT(redness(tinted), 1.5 * redness(plain)) << redness(tinted) << " against " << redness(plain);
}

// A patch inside a transformed shape or a group keeps its texture coordinates.
TEST(Textures, APatchMovedOrGroupedKeepsItsImage) {
    for (const char* shape : {"@g(Scaled(Vector3(1.2, 1.2, 1.2), quad))", "@g(Group([Translated(Vector3(0, 0, 0.1), quad)]))"}) {
        const sprout::Image im = render("tex_moved", "", shape);
        int n[5] = {0, 0, 0, 0, 0};
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) ++n[classify(im, x, y)];
        for (int q = 0; q < 4; ++q) EXPECT_GT(n[q], 500) << shape << ": " << kNames[q];
    }
}

// An @g Shape in a texture appearance (PlantGL's Shape(geometry, Texture2D(...))) draws its
// patch with its own image, whatever the turtle's material, as PglTurtle::pglShape does.
TEST(Textures, AShapesTextureAppearanceIsItsImage) {
    // (the turtle in material 2, a plain green)
    const sprout::Image im = render("tex_shape", ",(2)", "@g(Shape(quad, Texture2D(image=ImageTexture('quarters.png'))))");
    int n[5] = {0, 0, 0, 0, 0};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) ++n[classify(im, x, y)];
    for (int q = 0; q < 4; ++q) EXPECT_GT(n[q], 500) << kNames[q];
}

// A QuadSet's texCoordList places the image on it, as PlantGL's renderer does.
TEST(Textures, AMeshsTexCoordListPlacesTheImage) {
    const char* quads = "@g(QuadSet([(0, -1, -1), (0, 1, -1), (0, 1, 1), (0, -1, 1)], [(0, 1, 2, 3)], "
                        "texCoordList=[(0, 0), (1, 0), (1, 1), (0, 1)]))";
    const sprout::Image im = render("tex_quadset", "", quads);
    int n[5] = {0, 0, 0, 0, 0};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) ++n[classify(im, x, y)];
    for (int q = 0; q < 4; ++q) EXPECT_GT(n[q], 500) << kNames[q];
}
