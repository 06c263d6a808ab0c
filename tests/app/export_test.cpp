// `sprout export`: every format written and read back by an independent reader (the Khronos
// glTF validator through node, tinyobjloader, xmllint), counts checked against the geometry.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <tiny_obj_loader.h>

#include "app/image.hpp"
#include "tests/app/run_sprout.hpp"

namespace {
using namespace sprout_test;

std::string temp(const std::string& name) { return testing::TempDir() + std::to_string(getpid()) + "_" + name; }

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// "N triangles, M vertices" from the export summary.
std::pair<long, long> counts(const std::string& out) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(out, m, std::regex("(\\d+) triangles, (\\d+) vertices"))) << out;
    return m.size() == 3 ? std::pair{std::stol(m[1]), std::stol(m[2])} : std::pair{-1L, -1L};
}

int shell(const std::string& cmd, std::string* out = nullptr) {
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    std::string text;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) text.append(buf, n);
    int status = pclose(p);
    if (out) *out = text;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Export, OneStemIsAnExactTube) {
    // One segment with 6 sides: 2 rings of 6 plus 2 cap apexes, 6 triangles per cap and 12 on the side.
    std::string grammar = writeTemp("one.lsys", "n: 0\naxiom: F\n");
    std::string out = temp("one.ply");
    Result r = runSprout("export " + grammar + " -o " + out + " --sides 6");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(counts(r.out), std::pair(24L, 14L));
    std::string ply = slurp(out);
    const std::string end = "end_header\n";
    size_t header = ply.find(end);
    ASSERT_NE(header, std::string::npos);
    EXPECT_NE(ply.find("element vertex 14\n"), std::string::npos);
    EXPECT_NE(ply.find("element face 24\n"), std::string::npos);
    EXPECT_EQ(ply.size(), header + end.size() + 14 * 28 + 24 * 13);
    // The tube spans the segment: y from 0 to the step, apexes one radius beyond.
    float ymin = 1e9f, ymax = -1e9f;
    for (int v = 0; v < 14; ++v) {
        float p[3];
        std::memcpy(p, ply.data() + header + end.size() + v * 28, 12);
        ymin = std::min(ymin, p[1]);
        ymax = std::max(ymax, p[1]);
    }
    EXPECT_LT(ymin, 0.0f);
    EXPECT_GT(ymax, 1.0f);
    EXPECT_LT(ymax, 1.5f);
}

TEST(Export, GlbIsValidForTheKhronosValidator) {
    const std::string validator = std::string(SPROUT_TOOLS_DIR) + "/validate_gltf.js";
    ASSERT_TRUE(std::filesystem::exists(std::string(SPROUT_TOOLS_DIR) + "/node_modules/gltf-validator"))
        << "run `npm ci --prefix tests/tools` (scripts/setup.sh test does)";
    // binary_fractal_tree: ~l leaves (whose tips were NaN, 20 errors, before the unit leaf was fixed).
    for (std::string preset : {"bush_3d", "abop_1_26_flower_plant", "lparser_phyllotactic_tree_ovate_leaves", "koch", "binary_fractal_tree"}) {
        SCOPED_TRACE(preset);
        std::string out = temp(preset + ".glb");
        Result r = runSprout("export " + preset + " -o " + out);
        ASSERT_EQ(r.code, 0) << r.err;
        auto [triangles, vertices] = counts(r.out);
        std::string glb = slurp(out);
        ASSERT_GE(glb.size(), 20u);
        std::uint32_t head[3];
        std::memcpy(head, glb.data(), 12);
        EXPECT_EQ(head[0], 0x46546C67u);
        EXPECT_EQ(head[1], 2u);
        EXPECT_EQ(head[2], glb.size());
        std::string report;
        EXPECT_EQ(shell("node " + validator + " " + out, &report), 0) << report;
        EXPECT_NE(report.find("\"errors\": 0"), std::string::npos) << report;
        EXPECT_NE(report.find("\"warnings\": 0"), std::string::npos) << report;
        EXPECT_NE(report.find("\"totalTriangleCount\": " + std::to_string(triangles)), std::string::npos) << report;
        EXPECT_NE(report.find("\"totalVertexCount\": " + std::to_string(vertices)), std::string::npos) << report;
        std::remove(out.c_str());
    }
}

TEST(Export, ObjLoadsBackWithTinyObjLoader) {
    for (std::string preset : {"bush_3d", "abop_1_26_flower_plant", "koch_islands_lakes"}) {
        SCOPED_TRACE(preset);
        std::string out = temp(preset + ".obj");
        Result r = runSprout("export " + preset + " -o " + out);
        ASSERT_EQ(r.code, 0) << r.err;
        auto [triangles, vertices] = counts(r.out);
        tinyobj::ObjReader reader;
        tinyobj::ObjReaderConfig config;
        config.triangulate = false;
        ASSERT_TRUE(reader.ParseFromFile(out, config)) << reader.Error();
        EXPECT_EQ(reader.GetAttrib().vertices.size(), size_t(vertices) * 3);
        EXPECT_EQ(reader.GetAttrib().normals.size(), size_t(vertices) * 3);
        long faces = 0;
        std::set<std::string> groups;
        for (const auto& shape : reader.GetShapes()) {
            faces += long(shape.mesh.num_face_vertices.size());
            groups.insert(shape.name);
            for (int m : shape.mesh.material_ids) ASSERT_GE(m, 0) << "a face without a material";
        }
        EXPECT_EQ(faces, triangles);
        EXPECT_TRUE(groups.count("stems")) << "stems group";
        if (preset == "abop_1_26_flower_plant") {
            EXPECT_TRUE(groups.count("petals") || groups.count("polygons"));
        }
        // The materials carry the colours (the lakes are drawn in one colour).
        std::set<std::array<float, 3>> colours;
        for (const auto& m : reader.GetMaterials()) colours.insert({m.diffuse[0], m.diffuse[1], m.diffuse[2]});
        EXPECT_GE(colours.size(), preset == "koch_islands_lakes" ? 1u : 2u);
        std::remove(out.c_str());
    }
}

TEST(Export, PlyCarriesVertexColours) {
    std::string out = temp("bush.ply");
    Result r = runSprout("export bush_3d -o " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    auto [triangles, vertices] = counts(r.out);
    std::string ply = slurp(out);
    size_t header = ply.find("end_header\n") + 11;
    EXPECT_EQ(ply.size(), header + size_t(vertices) * 28 + size_t(triangles) * 13);
    std::set<std::uint32_t> colours;
    for (long v = 0; v < vertices; v += 97) {
        std::uint32_t c;
        std::memcpy(&c, ply.data() + header + v * 28 + 24, 4);
        colours.insert(c);
    }
    EXPECT_GE(colours.size(), 3u) << "the bark-to-green gradient";
    // Every face is a triangle of valid vertex indices.
    for (long f = 0; f < triangles; f += 101) {
        const char* face = ply.data() + header + vertices * 28 + f * 13;
        ASSERT_EQ(face[0], 3);
        for (int k = 0; k < 3; ++k) {
            std::uint32_t i;
            std::memcpy(&i, face + 1 + 4 * k, 4);
            ASSERT_LT(i, std::uint32_t(vertices));
        }
    }
}

TEST(Export, SvgIsValidXmlAndFramesTheCurve) {
    std::string out = temp("koch.svg");
    Result r = runSprout("export koch_curve_1_9b -o " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    std::string report;
    EXPECT_EQ(shell("xmllint --noout " + out, &report), 0) << report;
    std::string svg = slurp(out);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(svg, m, std::regex("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"")));
    const float W = std::stof(m[1]), H = std::stof(m[2]);
    EXPECT_NEAR(W, H, 1.0f) << "the square Koch island is square";
    // Every point lies inside the viewBox; the curve touches the margins on all sides.
    std::regex point("(-?[0-9.]+),(-?[0-9.]+)");
    float xmin = 1e9f, xmax = -1e9f, ymin = 1e9f, ymax = -1e9f;
    size_t points = 0, polylines = 0;
    for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) {
        ++polylines;
        size_t p0 = svg.find("points=\"", at) + 8, p1 = svg.find('"', p0);
        std::string pts = svg.substr(p0, p1 - p0);
        for (auto it = std::sregex_iterator(pts.begin(), pts.end(), point); it != std::sregex_iterator(); ++it, ++points) {
            float x = std::stof((*it)[1]), y = std::stof((*it)[2]);
            xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
        }
    }
    EXPECT_EQ(polylines, 1u) << "a closed curve without branches is one polyline";
    EXPECT_GT(points, 1000u);
    EXPECT_NEAR(xmin, 20.0f, 0.5f);
    EXPECT_NEAR(ymin, 20.0f, 0.5f);
    EXPECT_NEAR(xmax, W - 20.0f, 0.5f);
    EXPECT_NEAR(ymax, H - 20.0f, 0.5f);
}

// Texts (L-Py's @L labels) go with the model: in a .glb an empty node each, named by its text,
// where it stands (Blender makes them named empties), under a node "labels"; in an SVG a
// <text> each. Read back by the Khronos validator and xmllint.
TEST(Export, LabelsAreNamedNodesAndTexts) {
    const std::string model = writeTemp("labels.lpy", "Axiom: F(2) @L('top') [+(90) F(1) @L('a <b>', 26)]\n"
                                                       "derivation length: 0\nproduction:\nendlsystem\n");
    const std::string glb = temp("labels.glb"), svg = temp("labels.svg");
    Result r = runSprout("export " + model + " -o " + glb);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string bytes = slurp(glb);
    ASSERT_GE(bytes.size(), 20u);
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    const std::string json = bytes.substr(20, jsonLength);
    EXPECT_NE(json.find("{\"name\":\"top\",\"translation\":[0,2,0]"), std::string::npos) << json;
    EXPECT_NE(json.find("{\"name\":\"a <b>\",\"translation\":[-1,2,0]"), std::string::npos) << json;  // turned left
    EXPECT_NE(json.find("{\"name\":\"labels\",\"children\":[1,2]}"), std::string::npos) << json;
    EXPECT_NE(json.find("\"nodes\":[0,3]"), std::string::npos) << "the stems and the labels in the scene: " << json;
    const std::string validator = std::string(SPROUT_TOOLS_DIR) + "/validate_gltf.js";
    std::string report;
    EXPECT_EQ(shell("node " + validator + " " + glb, &report), 0) << report;
    EXPECT_NE(report.find("\"errors\": 0"), std::string::npos) << report;
    EXPECT_NE(report.find("\"warnings\": 0"), std::string::npos) << report;
    r = runSprout("export " + model + " -o " + svg);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(shell("xmllint --noout " + svg, &report), 0) << report;
    const std::string text = slurp(svg);
    EXPECT_NE(text.find("font-size=\"13.00\" fill=\"#c3872d\">top</text>"), std::string::npos) << text;
    EXPECT_NE(text.find(">a &lt;b&gt;</text>"), std::string::npos) << text;
    std::remove(glb.c_str());
    std::remove(svg.c_str());
}

TEST(Export, ErrorsAreMessagesNotCrashes) {
    Result r = runSprout("export koch -o out.xyz");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("use .glb, .obj, .ply or .svg"), std::string::npos) << r.err;
    r = runSprout("export koch -o /nonexistent-dir/x.glb");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("/nonexistent-dir/x.glb: No such file or directory"), std::string::npos) << r.err;
    r = runSprout("export barnsley_fern -o " + temp("f.glb"));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("not a model"), std::string::npos) << r.err;
    std::string bad = writeTemp("bad.lsys", "axiom: F\nF -> F[+F\n");
    r = runSprout("export " + bad + " -o " + temp("bad.glb"));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("bad.lsys:2:"), std::string::npos) << r.err;
}

}  // namespace

namespace {
using namespace sprout_test;

// A picture is also the recipe: the grammar (with -n and --seed) rides in an iTXt chunk.
TEST(PngRecipe, RenderThenExpandGivesTheSameString) {
    struct Case {
        std::string preset, flags;
    };
    for (const Case& c : {Case{"fractal_plant", "-n 3"}, Case{"stochastic_weed", "-n 4 --seed 5"}, Case{"abop_1_31a", ""}}) {
        SCOPED_TRACE(c.preset);
        std::string png = temp(c.preset + ".png");
        Result r = runSprout("render " + c.preset + " " + c.flags + " --size 64x64 -o " + png);
        ASSERT_EQ(r.code, 0) << r.err;
        Result fromPng = runSprout("expand " + png), original = runSprout("expand " + c.preset + " " + c.flags);
        ASSERT_EQ(fromPng.code, 0) << fromPng.err;
        EXPECT_EQ(fromPng.out, original.out);
        EXPECT_GT(original.out.size(), 20u);
        std::remove(png.c_str());
    }
    // A different seed is a different specimen, so the seed really travels.
    std::string a = temp("weed_a.png");
    ASSERT_EQ(runSprout("render stochastic_weed -n 4 --seed 6 --size 64x64 -o " + a).code, 0);
    EXPECT_NE(runSprout("expand " + a).out, runSprout("expand stochastic_weed -n 4 --seed 5").out);
    EXPECT_EQ(runSprout("expand " + a).out, runSprout("expand stochastic_weed -n 4 --seed 6").out);
}

TEST(PngRecipe, ARenderedPictureRendersAgainTheSame) {
    std::string a = temp("again_a.png"), b = temp("again_b.png");
    ASSERT_EQ(runSprout("render bush_3d -n 2 --view side --size 96x96 -o " + a).code, 0);
    Result r = runSprout("render " + a + " --size 96x96 -o " + b);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(a), slurp(b)) << "same grammar, n and view: the same file";
    // Iterated function systems and forest scenes travel the same way.
    for (std::string preset : {"barnsley_fern", "weed_field"}) {
        ASSERT_EQ(runSprout("render " + preset + " --size 96x96 -o " + a).code, 0);
        r = runSprout("render " + a + " --size 96x96 -o " + b);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(slurp(a), slurp(b)) << preset;
    }
}

TEST(PngRecipe, PicturesOfForestsExportAndPicturesOfIfsSayWhatTheyHold) {
    std::string forest = temp("forest_recipe.png"), ifs = temp("ifs_recipe.png"), glb = temp("forest_recipe.glb");
    ASSERT_EQ(runSprout("render weed_field --size 64x64 -o " + forest).code, 0);
    Result direct = runSprout("export weed_field -o " + glb);
    ASSERT_EQ(direct.code, 0) << direct.err;
    Result r = runSprout("export " + forest + " -o " + glb);
    ASSERT_EQ(r.code, 0) << r.err;
    // The same scene: the same counts in the summary line, after the file name.
    EXPECT_EQ(r.out.substr(r.out.find(':'), r.out.find(" in ") - r.out.find(':')),
              direct.out.substr(direct.out.find(':'), direct.out.find(" in ") - direct.out.find(':')));
    ASSERT_EQ(runSprout("render barnsley_fern --size 64x64 -o " + ifs).code, 0);
    r = runSprout("export " + ifs + " -o " + glb);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("is a point density, not a model"), std::string::npos) << r.err;
    r = runSprout("expand " + ifs);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("holds an iterated function system"), std::string::npos) << r.err;
    r = runSprout("expand " + forest);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("holds a forest scene"), std::string::npos) << r.err;
}

TEST(PngRecipe, PicturesWithoutAGrammarSaySo) {
    std::string notPng = writeTemp("fake.png", "hello");
    Result r = runSprout("expand " + notPng);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("fake.png: is not a PNG file"), std::string::npos) << r.err;
    // A real PNG cut short.
    std::string whole = temp("whole.png");
    ASSERT_EQ(runSprout("render koch --size 64x64 -o " + whole).code, 0);
    std::string bytes = slurp(whole);
    std::string cut = writeTemp("cut.png", bytes.substr(0, 60));
    r = runSprout("expand " + cut);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("damaged PNG"), std::string::npos) << r.err;
}

}  // namespace

namespace {
using namespace sprout_test;

std::string probe(const std::string& file) {
    std::string out;
    shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=codec_name,width,height,nb_read_frames "
          "-of csv=p=0 " + file, &out);
    return out;
}

TEST(Animation, GrowthAndTurntableVideosHaveTheirFrames) {
    ASSERT_EQ(shell("command -v ffmpeg && command -v ffprobe"), 0) << "scripts/setup.sh test installs ffmpeg";
    std::string grow = temp("grow.mp4"), turn = temp("turn.mp4");
    Result r = runSprout("render fractal_plant -n 4 --animate growth --fps 10 --size 320x240 -o " + grow);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("21 frames"), std::string::npos) << r.out;  // half a second per step, axiom to step 4
    EXPECT_EQ(probe(grow), "h264,320,240,21\n");
    // Odd sizes are made even for H.264.
    r = runSprout("render bush_3d -n 2 --animate turntable --frames 12 --size 201x151 -o " + turn);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(probe(turn), "h264,200,150,12\n");
    std::remove(grow.c_str());
    std::remove(turn.c_str());
}

TEST(Animation, PngFramesWithoutFfmpegShowThePlantGrowing) {
    // No ffmpeg on the PATH: the frames are written as numbered PNGs, each carrying the grammar.
    std::string base = temp("growth");
    std::string cmd = "env PATH=/nonexistent " + std::string(SPROUT_BINARY) +
                      " render fractal_plant -n 4 --animate growth --frames 5 --size 160x120 -o " + base + ".mp4";
    std::string out;
    ASSERT_EQ(shell(cmd, &out), 0) << out;
    EXPECT_NE(out.find("ffmpeg is not installed"), std::string::npos) << out;
    std::vector<::sprout::Image> frames(5);
    for (int k = 0; k < 5; ++k) {
        std::string frame = base + "_000" + std::to_string(k + 1) + ".png", error;
        ASSERT_TRUE(::sprout::readPng(frame, frames[k], error)) << frame << ": " << error;
        EXPECT_EQ(runSprout("expand " + frame).out, runSprout("expand fractal_plant -n 4").out) << "frames carry the recipe";
        std::filesystem::remove(frame);
    }
    // Frame 1 is the axiom (nothing drawn); each later frame covers more of the picture, the
    // camera does not move, so the plant grows in place.
    std::vector<long> plant;
    for (const auto& f : frames) {
        long differ = 0;
        for (size_t i = 0; i < f.rgba.size(); i += 4)
            differ += std::abs(int(f.rgba[i]) - int(frames[0].rgba[i])) + std::abs(int(f.rgba[i + 1]) - int(frames[0].rgba[i + 1])) > 30;
        plant.push_back(differ);
    }
    EXPECT_EQ(plant[0], 0);
    for (int k = 1; k < 5; ++k) EXPECT_GT(plant[k], plant[k - 1]) << "frame " << k + 1;
    EXPECT_GT(plant[4], 300);
}

// An L-Py model grows through the steps its run kept (its Python runs once, not per frame).
TEST(Animation, AnLpyModelGrowsThroughItsSteps) {
    std::string base = temp("lpy_growth");
    Result r = runSprout("render lpy_flowering_plant --animate growth --frames 4 --size 160x120 -o " + base + ".png");
    ASSERT_EQ(r.code, 0) << r.err;
    std::vector<::sprout::Image> frames(4);
    for (int k = 0; k < 4; ++k) {
        std::string frame = base + "_000" + std::to_string(k + 1) + ".png", error;
        ASSERT_TRUE(::sprout::readPng(frame, frames[size_t(k)], error)) << frame << ": " << error;
        std::filesystem::remove(frame);
    }
    std::vector<long> grown;
    for (const auto& f : frames) {
        long differ = 0;
        for (size_t i = 0; i < f.rgba.size(); i += 4)
            differ += std::abs(int(f.rgba[i]) - int(frames[0].rgba[i])) + std::abs(int(f.rgba[i + 1]) - int(frames[0].rgba[i + 1])) > 30;
        grown.push_back(differ);
    }
    for (int k = 1; k < 4; ++k) EXPECT_GT(grown[size_t(k)], grown[size_t(k - 1)]) << "frame " << k + 1;
    EXPECT_GT(grown[3], 300);
}

}  // namespace
