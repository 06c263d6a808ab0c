// Issue 52: VLab's object files written as its editors write them, and read back with the same
// values: every .func, .fset, .con, .s, .mat and .map of VLab's manuals (../shared/corpus/
// vlab-manuals) is read, written and read again. Files that are their editor's own output come
// back byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/base/read_file.hpp"
#include "core/language/vlab/colours.hpp"
#include "core/language/vlab/curve_files.hpp"
#include "core/language/vlab/surface_patches.hpp"

namespace sprout {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpusFiles(const std::string& ext) {
    std::vector<fs::path> out;
    const fs::path root = fs::path(SPROUT_SHARED_DIR) / "corpus" / "vlab-manuals";
    if (!fs::exists(root)) return out;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string bytes(const fs::path& p) { return readFile(p.string()).value_or(""); }

// Floats as the file gives them: values compared exactly after a write and a read.
void expectSameFunction(const FunctionFile& a, const FunctionFile& b, const std::string& where) {
    EXPECT_EQ(a.name, b.name) << where;
    EXPECT_EQ(a.samples, b.samples) << where;
    EXPECT_EQ(a.flip, b.flip) << where;
    EXPECT_EQ(a.points, b.points) << where;
}

TEST(VlabWriters, FunctionsComeBackWithTheirValues) {
    int files = 0, same = 0;
    for (const fs::path& p : corpusFiles(".func")) {
        const std::string text = bytes(p);
        const FunctionRead a = readFunction(text, p.string(), -1);
        ASSERT_TRUE(a.ok() && a.file) << p;
        const std::string written = writeFunction(*a.file);
        const FunctionRead b = readFunction(written, p.string(), -1);
        ASSERT_TRUE(b.ok() && b.file) << p << "\n" << written;
        FunctionFile expected = *a.file;
        expected.original = false;  // the first format is written as funcedit writes it
        if (a.file->original) expected.name = b.file->name;
        expectSameFunction(expected, *b.file, p.string());
        for (double x : {0.0, 0.137, 0.5, 0.91, 1.0}) EXPECT_EQ(a.file->function(10)(x), b.file->function(10)(x)) << p << " x=" << x;
        ++files;
        same += written == text;
    }
    if (files == 0) GTEST_SKIP() << "no corpus";
    EXPECT_EQ(files, 26);
    EXPECT_EQ(same, 19) << "funcedit's own files (fver 1 1, three columns) come back byte for byte";
}

TEST(VlabWriters, FunctionSetsComeBackWithTheirValues) {
    int files = 0;
    for (const fs::path& p : corpusFiles(".fset")) {
        const FunctionSetRead a = readFunctionSet(bytes(p), p.string());
        ASSERT_TRUE(a.ok()) << p;
        const std::string written = writeFunctionSet(a.files);
        const FunctionSetRead b = readFunctionSet(written, p.string());
        ASSERT_TRUE(b.ok()) << p << "\n" << written;
        ASSERT_EQ(a.files.size(), b.files.size()) << p;
        for (size_t i = 0; i < a.files.size(); ++i) expectSameFunction(a.files[i], b.files[i], p.string());
        ++files;
    }
    if (files == 0) GTEST_SKIP() << "no corpus";
    EXPECT_EQ(files, 3);
}

TEST(VlabWriters, ContoursComeBackByteForByte) {
    int files = 0;
    for (const fs::path& p : corpusFiles(".con")) {
        const std::string text = bytes(p);
        if (text.rfind("version:", 0) == 0) {  // a curve file (cpfg's `curve:` lines), as cuspy writes 1.4
            const CurveRead a = readCurve(text, p.string(), 100);
            ASSERT_TRUE(a.ok()) << p;
            const std::string written = writeCurve(a.curve);
            EXPECT_EQ(written, text) << p;
            const CurveRead b = readCurve(written, p.string(), 100);
            EXPECT_EQ(a.curve.points(), b.curve.points()) << p;
            ++files;
            continue;
        }
        const ContourRead a = readContour(text, p.string());
        ASSERT_TRUE(a.ok() && a.file) << p;
        const std::string written = writeContour(*a.file);
        EXPECT_EQ(written, text) << p << ": cuspy's own file";
        const ContourRead b = readContour(written, p.string());
        ASSERT_TRUE(b.ok() && b.file) << p;
        EXPECT_EQ(a.file->points, b.file->points) << p;
        EXPECT_EQ(a.contour->sampled(12), b.contour->sampled(12)) << p;
        ++files;
    }
    if (files == 0) GTEST_SKIP() << "no corpus";
    EXPECT_EQ(files, 5);
}

TEST(VlabWriters, ContourSetsAndOldContoursAreWrittenAsCuspyWrites) {
    const std::string old = "5 2 closed\n0 0\n1 0\n1 0\n1 1\n0 1\n";  // the first format: point 2 repeated
    const ContourRead a = readContour(old, "leaf.con");
    ASSERT_TRUE(a.ok() && a.file);
    EXPECT_EQ(writeContour(*a.file), "cver 1 3\nname: leaf\npoints: 4 5\ntype: cr\nsamples: 8\n0.000000 0.000000 0.000000 1\n"
                                     "1.000000 0.000000 0.000000 2\n1.000000 1.000000 0.000000 1\n0.000000 1.000000 0.000000 1\n");
    const ContourRead b = readContour(writeContour(*a.file), "leaf.con");
    EXPECT_EQ(a.contour->points, b.contour->points) << "the same points once multiplicities are counted";
    const std::string set = "contourgalleryver 1 1\nitems: 2\n" + writeContour(*a.file) + writeContour(*b.file);
    const ContourSetRead s = readContourSet(set, "s.cset");
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(writeContourSet(s.files), set);
}

TEST(VlabWriters, SurfacesComeBackWithTheirValues) {
    int files = 0, patches = 0;
    for (const fs::path& p : corpusFiles(".s")) {
        const SurfacePatchesRead a = readSurfacePatches(bytes(p), p.string());
        ASSERT_TRUE(a.ok()) << p << ": " << (a.diagnostics.empty() ? "" : a.diagnostics[0].text());
        const std::string written = writeSurfacePatches(*a.surface);
        const SurfacePatchesRead b = readSurfacePatches(written, p.string());
        ASSERT_TRUE(b.ok()) << p << "\n" << written;
        const SurfacePatches &x = *a.surface, &y = *b.surface;
        EXPECT_EQ(x.contact, y.contact);
        EXPECT_EQ(x.end, y.end);
        EXPECT_EQ(x.heading, y.heading);
        EXPECT_EQ(x.up, y.up);
        EXPECT_EQ(x.size, y.size);
        ASSERT_EQ(x.patches.size(), y.patches.size()) << p;
        for (size_t i = 0; i < x.patches.size(); ++i) {
            EXPECT_EQ(x.patches[i].name, y.patches[i].name);
            EXPECT_EQ(x.patches[i].neighbours, y.patches[i].neighbours) << p << ": neighbours by name";
            EXPECT_EQ(x.patches[i].points, y.patches[i].points) << p;
            EXPECT_EQ(x.patches[i].topColour, y.patches[i].topColour);
            EXPECT_EQ(x.patches[i].topDiffuse, y.patches[i].topDiffuse);
        }
        EXPECT_EQ(writeSurfacePatches(y), written) << p << ": written again, the same bytes";
        ++files;
        patches += int(x.patches.size());
    }
    if (files == 0) GTEST_SKIP() << "no corpus";
    EXPECT_EQ(files, 12);
    EXPECT_GT(patches, 12);
}

TEST(VlabWriters, ASurfaceIsWrittenAsBeziereditWritesIt) {
    SurfacePatches s;
    s.contact = {0, -0.75f, 0}, s.end = {0, 0.75f, 0}, s.heading = {0, 1, 0}, s.up = {0, 0, -1}, s.size = 1.5f;
    SurfacePatch p;
    p.name = "Patch_0";
    for (size_t k = 0; k < 16; ++k) p.points[k] = {-0.75f + 0.5f * float(k % 4), 0.75f - 0.5f * float(k / 4), 0};
    s.patches.push_back(p);
    EXPECT_EQ(writeSurfacePatches(s), "-0.75 0.75\t-0.75 0.75\t0 0\nCONTACT POINT  X: 0 Y: -0.75 Z: 0\nEND POINT      X: 0 Y: 0.75 Z: 0\n"
                                      "HEADING        X: 0 Y: 1 Z: 0\nUP             X: 0 Y: 0 Z: -1\nSIZE: 1.5\nPatch_0\n"
                                      "TOP COLOR: 0 DIFFUSE: 0.0 BOTTOM COLOR: 0 DIFFUSE: 0.0\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n"
                                      "-0.75 0.75 0\t-0.25 0.75 0\t0.25 0.75 0\t0.75 0.75 0\t\n"
                                      "-0.75 0.25 0\t-0.25 0.25 0\t0.25 0.25 0\t0.75 0.25 0\t\n"
                                      "-0.75 -0.25 0\t-0.25 -0.25 0\t0.25 -0.25 0\t0.75 -0.25 0\t\n"
                                      "-0.75 -0.75 0\t-0.25 -0.75 0\t0.25 -0.75 0\t0.75 -0.75 0\t\n");
    std::string broken = writeSurfacePatches(s);
    broken.replace(broken.find("AL: ~"), 5, "AL: Patch_9");
    const SurfacePatchesRead r = readSurfacePatches(broken, "leaf.s");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].text().find("Patch_9"), std::string::npos);
    const SurfacePatchesRead cut = readSurfacePatches(broken.substr(0, broken.size() - 20), "leaf.s");
    ASSERT_FALSE(cut.ok());
    EXPECT_EQ(cut.diagnostics[0].line, 15) << cut.diagnostics[0].text();
}

TEST(VlabWriters, MaterialsAndColourMapsComeBackByteForByte) {
    int maps = 0, materials = 0;
    for (const fs::path& p : corpusFiles(".map")) {
        std::string error;
        const std::string b = bytes(p);
        const auto m = vlab::readColourMap(b, error);
        ASSERT_TRUE(m) << p << ": " << error;
        EXPECT_EQ(vlab::writeColourMap(*m), b) << p;
        ++maps;
    }
    for (const fs::path& p : corpusFiles(".mat")) {
        std::string error;
        const std::string b = bytes(p);
        const auto m = vlab::readMaterials(b, error);
        ASSERT_TRUE(m) << p << ": " << error;
        EXPECT_EQ(vlab::writeMaterials(*m), b) << p << ": medit's records, truncated as medit does";
        ++materials;
    }
    if (maps + materials == 0) GTEST_SKIP() << "no corpus";
    EXPECT_EQ(maps, 11);
    EXPECT_EQ(materials, 18);
    // Every byte survives a read and a write (medit's (char)(v * 255) of v = b / 255).
    std::string all;
    for (int b = 0; b < 256; ++b) all += {char(b), char(b), char(b), char(b), char(b), char(b), char(b), char(b), char(b), char(b),
                                          char(b), char(b), char(b), char(b), char(b)};
    std::string error;
    EXPECT_EQ(vlab::writeMaterials(*vlab::readMaterials(all, error)), all);
}

}  // namespace
}  // namespace sprout
