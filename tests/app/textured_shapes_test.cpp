// Textures on what the turtle draws itself (issue 53): stems, the predefined leaves, petals
// and spheres, and polygons wear the image of their palette entry (L-Py's ImageTexture, a
// .lsys material's texture), rendered through the program as a user runs it. A stem's image
// runs on along the stems after it in the same colour (PlantGL's axial length).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/image.hpp"
#include "tests/app/quarters.hpp"
#include "tests/app/run_sprout.hpp"

namespace {

using namespace sprout_test::quarters;
using sprout_test::runSprout;

// `text` as model `name` (its extension says its language) beside the quarters image
// `quarters.png`, rendered from the front.
sprout::Image renderModel(const std::string& name, const std::string& text) {
    const std::string dir = testing::TempDir() + "textured_shapes/";
    std::filesystem::create_directories(dir);
    std::string error;
    EXPECT_TRUE(sprout::writePng(dir + "quarters.png", quarters(), error)) << error;
    std::ofstream(dir + name) << text;
    const std::string png = dir + name + ".png";
    const auto r = runSprout("render " + dir + name + " -o " + png + " --size 240x240 --view front --no-ground --no-shadows");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    sprout::Image image;
    EXPECT_TRUE(sprout::readPng(png, image, error)) << error;
    return image;
}

std::string lpyModel(const std::string& axiom) {
    return "from openalea.plantgl.all import *\n"
           "context().turtle.setMaterial(1, ImageTexture('quarters.png'))\n"
           "Axiom: " + axiom + "\nderivation length: 0\n";
}

// The quarters seen in rows [from, to) of the picture, in its middle half across (a stem's
// side, not its ends' rims): how many pixels of each.
std::array<int, 5> quartersIn(const sprout::Image& im, int from, int to) {
    std::array<int, 5> n{};
    for (int y = std::max(from, 0); y < std::min(to, im.height); ++y)
        for (int x = im.width / 4; x < im.width * 3 / 4; ++x) ++n[classify(im, x, y)];
    return n;
}

// The rows the image's colours are seen in: [first, last].
std::array<int, 2> rowsSeen(const sprout::Image& im) {
    std::array<int, 2> rows{im.height, -1};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            if (classify(im, x, y) != None) rows[0] = std::min(rows[0], y), rows[1] = std::max(rows[1], y);
    return rows;
}

// The centre of the pixels showing quarter q.
std::array<double, 2> centreOf(const sprout::Image& im, Quarter q) {
    double x = 0, y = 0, n = 0;
    for (int j = 0; j < im.height; ++j)
        for (int i = 0; i < im.width; ++i)
            if (classify(im, i, j) == q) x += i, y += j, ++n;
    EXPECT_GT(n, 30) << kNames[q] << " is seen";
    return {n ? x / n : 0, n ? y / n : 0};
}

}  // namespace

// Two stems half a unit long, one on the other: the first wears the image's lower half (v 0
// to 0.5: blue and yellow), the second its upper half (v 0.5 to 1: red and green), as
// PlantGL's cylinders shifted by the axial length. A colour set again starts the image afresh.
TEST(TexturedShapes, AStemsImageRunsOnAlongTheStemsAfterIt) {
    const sprout::Image on = renderModel("stems.lpy", lpyModel(",(1) _(0.6) F(0.5) F(0.5)"));
    const auto [top, bottom] = rowsSeen(on);
    ASSERT_GT(bottom - top, 100) << "the stems are drawn in the image's colours";
    const int middle = (top + bottom) / 2;
    const auto lower = quartersIn(on, middle + 8, bottom + 1), upper = quartersIn(on, top, middle - 8);
    EXPECT_GT(lower[Blue] + lower[Yellow], 10 * (lower[Red] + lower[Green]) + 200) << "the lower stem: the image's lower half";
    // (Where red meets green round the stem, the filtered image is yellow: blue tells the halves apart.)
    EXPECT_GT(upper[Red] + upper[Green], 10 * upper[Blue] + 200) << "the upper stem: its upper half";

    const sprout::Image afresh = renderModel("stems_afresh.lpy", lpyModel(",(1) _(0.6) F(0.5) ,(1) F(0.5)"));
    const auto [top2, bottom2] = rowsSeen(afresh);
    const auto upper2 = quartersIn(afresh, top2, (top2 + bottom2) / 2 - 8);
    EXPECT_GT(upper2[Blue], 10 * (upper2[Red] + upper2[Green]) + 200) << "the colour set again: the lower half again";
}

// A textured leaf faces the front view (its up is the camera's way): the image upright on it,
// unmirrored, base to tip; a sphere shows it too; a stem keeps it under a texture transform.
TEST(TexturedShapes, LeavesPetalsAndSpheresWearTheImage) {
    const sprout::Image leaf = renderModel("leaf.lsys", "material: 1 #ffffff texture quarters.png\nn: 0\naxiom: ;(1) ~l(4)\n");
    const auto blue = centreOf(leaf, Blue), yellow = centreOf(leaf, Yellow), red = centreOf(leaf, Red), green = centreOf(leaf, Green);
    EXPECT_LT(blue[0] + 10, yellow[0]) << "blue left of yellow";
    EXPECT_LT(red[0] + 10, green[0]) << "red left of green";
    EXPECT_GT(blue[1], red[1] + 10) << "blue below red: the base is the image's bottom";
    EXPECT_GT(yellow[1], green[1] + 10);

    const sprout::Image petal = renderModel("petal.lsys", "material: 1 #ffffff texture quarters.png\nn: 0\naxiom: ;(1) ~p(4)\n");
    const auto seen = quartersIn(petal, 0, petal.height);
    for (Quarter q : {Blue, Yellow, Red, Green}) EXPECT_GT(seen[q], 100) << kNames[q] << " on the petal";

    const sprout::Image ball = renderModel("sphere.lpy", lpyModel(",(1) @O(1)"));
    const auto onBall = quartersIn(ball, 0, ball.height);
    int kinds = 0;
    for (Quarter q : {Blue, Yellow, Red, Green}) kinds += onBall[q] > 100;
    EXPECT_GE(kinds, 3) << "the sphere shows the image round it";
}

// A polygon takes the image over its outline as cpfg gives it: s along the turtle's right
// (-L), t along its heading, from the outline's least to its most. The square drawn facing
// the front shows the four quarters in their places.
TEST(TexturedShapes, APolygonSpansTheImage) {
    const sprout::Image square =
        renderModel("square.lsys", "material: 1 #ffffff texture quarters.png\nn: 0\naxiom: ;(1) {. f(2) . -(90) f(2) . -(90) f(2) . -(90) f(2) .}\n");
    const auto [top, bottom] = rowsSeen(square);
    ASSERT_GT(bottom - top, 100);
    const auto blue = centreOf(square, Blue), yellow = centreOf(square, Yellow), red = centreOf(square, Red), green = centreOf(square, Green);
    EXPECT_LT(blue[0] + 40, yellow[0]);
    EXPECT_LT(red[0] + 40, green[0]);
    EXPECT_GT(blue[1], red[1] + 40);
    EXPECT_GT(yellow[1], green[1] + 40);
    // The image once across it: each quarter a quarter of the square.
    const auto n = quartersIn(square, 0, square.height);
    const int all = n[Blue] + n[Yellow] + n[Red] + n[Green];
    for (Quarter q : {Blue, Yellow, Red, Green}) EXPECT_NEAR(double(n[q]) / all, 0.25, 0.05) << kNames[q];
}

// PlantGL's solids given to @g wear the image with the texture coordinates PlantGL's
// Discretizer gives them: round a Sphere, a Cylinder and a Frustum, projected on a Cone and a
// Disc, each face of a Box. Each shows at least three of the image's quarters.
TEST(TexturedShapes, PlantglSolidsGivenToAtGWearTheImage) {
    const char* solids[] = {"Sphere(1)", "Cylinder(0.6, 2)", "Frustum(0.6, 2, 0.5)", "Box(0.8, 0.8, 0.8)", "Cone(1, 1.5)", "Disc(1)"};
    int k = 0;
    for (const char* solid : solids) {
        // Tilted towards the camera, so that a cone's and a disc's faces are seen.
        const sprout::Image im = renderModel("solid" + std::to_string(k++) + ".lpy", lpyModel(",(1) &(60) /(30) @g(" + std::string(solid) + ")"));
        const auto n = quartersIn(im, 0, im.height);
        int kinds = 0;
        for (Quarter q : {Blue, Yellow, Red, Green}) kinds += n[q] > 60;
        EXPECT_GE(kinds, 3) << solid << ": " << n[Blue] << " blue, " << n[Yellow] << " yellow, " << n[Red] << " red, " << n[Green] << " green";
    }
}

// A mesh's texture coordinates by face (texCoordIndexList): each face's corners take the
// entries it names, whatever the points' order. The square's image turned half round by its
// index list puts blue where green was, and red where yellow was.
TEST(TexturedShapes, AMeshsTexCoordIndexListPlacesTheImageByFace) {
    auto quadSet = [](const std::string& extra) {
        return lpyModel(",(1) @g(QuadSet([(0, -1, -1), (0, 1, -1), (0, 1, 1), (0, -1, 1)], [(0, 1, 2, 3)], "
                        "texCoordList=[(0, 0), (1, 0), (1, 1), (0, 1)]" + extra + "))");
    };
    const sprout::Image plain = renderModel("quadset.lpy", quadSet(""));
    const sprout::Image turned = renderModel("quadset_indexed.lpy", quadSet(", texCoordIndexList=[(2, 3, 0, 1)]"));
    auto near = [](std::array<double, 2> a, std::array<double, 2> b) { return std::hypot(a[0] - b[0], a[1] - b[1]) < 15; };
    EXPECT_TRUE(near(centreOf(turned, Blue), centreOf(plain, Green)));
    EXPECT_TRUE(near(centreOf(turned, Green), centreOf(plain, Blue)));
    EXPECT_TRUE(near(centreOf(turned, Red), centreOf(plain, Yellow)));
    EXPECT_FALSE(near(centreOf(plain, Blue), centreOf(plain, Green))) << "the quarters stand apart";
}

// A translucent textured polygon: its image blended by the material's transparency (its
// quarters washed towards the sky's colour, in their places), and the stem behind it seen
// through it (a darker band across the blue quarter).
TEST(TexturedShapes, ATranslucentTexturedPolygonShowsItsImageAndWhatIsBehind) {
    const sprout::Image im = renderModel("glass.lsys",
                                         "material: 1 #ffffff transparency 0.5 texture quarters.png\nmaterial: 2 #804020\nwidth: 0.3\nn: 0\n"
                                         "axiom: ;(2) [ +(90) f(0.75) -(90) f(-1) F(4) ] "
                                         "[ &(90) f(-2) ^(90) +(90) f(1.5) -(90) ;(1) {. f(3) . -(90) f(3) . -(90) f(3) . -(90) f(3) .} ]\n");
    auto rgb = [&](int x, int y) {
        const std::size_t k = (std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * 4;
        return std::array<int, 3>{im.rgba[k], im.rgba[k + 1], im.rgba[k + 2]};
    };
    auto washed = [&](int x, int y) {  // the quarter a pale pixel leans to
        const auto [r, g, b] = rgb(x, y);
        if (b > r + 40 && b > g + 40) return Blue;
        if (r > g + 40 && r > b + 30) return Red;
        if (g > r + 40 && g > b + 40) return Green;
        if (r > b + 40 && g > b + 40) return Yellow;
        return None;
    };
    std::array<double, 2> centre[4]{};
    double n[4] = {0, 0, 0, 0};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            if (const Quarter q = washed(x, y); q != None) centre[q][0] += x, centre[q][1] += y, ++n[q];
    for (int q = 0; q < 4; ++q) {
        ASSERT_GT(n[q], 300) << kNames[q] << " is seen through the glass's transparency";
        centre[q][0] /= n[q], centre[q][1] /= n[q];
    }
    EXPECT_LT(centre[Blue][0] + 40, centre[Yellow][0]);
    EXPECT_LT(centre[Red][0] + 40, centre[Green][0]);
    EXPECT_GT(centre[Blue][1], centre[Red][1] + 40);
    // Across the blue quarter's rows: the stem behind shows as a darker band.
    auto brightness = [&](int x, int y) {
        const auto [r, g, b] = rgb(x, y);
        return r + g + b;
    };
    const int y = int(centre[Blue][1]);
    int darkest = 1000, x0 = 0;
    for (int x = int(centre[Blue][0]) - 30; x <= int(centre[Blue][0]) + 30; ++x)
        if (brightness(x, y) < darkest) darkest = brightness(x, y), x0 = x;
    EXPECT_LT(darkest + 60, brightness(x0 - 20, y)) << "the stem seen through the glass";
    EXPECT_EQ(washed(x0 - 20, y), Blue) << "beside it the glass's blue";
}
