// What Sprout writes never hurts what is already there (core/base/atomic_file.hpp), run as a
// user runs it: through a symlink, into a FIFO, beside someone else's temporary file, several
// at once, on a full disk (a write failure injected with LD_PRELOAD), and to standard output.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/base/atomic_file.hpp"
#include "tests/app/run_sprout.hpp"

namespace {
using namespace sprout_test;
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    fs::path d = fs::path(testing::TempDir()) / ("sprout_files_" + std::to_string(getpid()) + "_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

bool isPng(const std::string& bytes) { return bytes.starts_with("\x89PNG\r\n\x1a\n"); }

// No temporary is left behind in `dir`.
int temporaries(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().find(".sprout-") != std::string::npos;
    return n;
}

TEST(Files, RenderThroughASymlinkReplacesTheFileItNames) {
    const fs::path d = freshDir("symlink");
    fs::create_directories(d / "elsewhere");
    std::ofstream(d / "elsewhere" / "real.png") << "old";
    fs::create_symlink("elsewhere/real.png", d / "link.png");
    Result r = runSprout("render koch --size 64x48 -o " + (d / "link.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(d / "link.png")) << "the link is still a link";
    EXPECT_TRUE(isPng(slurp(d / "elsewhere" / "real.png"))) << "the real file was written";
    EXPECT_EQ(temporaries(d), 0);
    EXPECT_EQ(temporaries(d / "elsewhere"), 0);
    // A dangling link: the file it names is made.
    fs::create_symlink("elsewhere/new.glb", d / "dangling.glb");
    r = runSprout("export koch --quiet -o " + (d / "dangling.glb").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(d / "dangling.glb"));
    EXPECT_TRUE(slurp(d / "elsewhere" / "new.glb").starts_with("glTF"));
}

TEST(Files, AFifoIsWrittenIntoNotReplaced) {
    const fs::path d = freshDir("fifo");
    ASSERT_EQ(::mkfifo((d / "pipe.png").c_str(), 0600), 0);
    std::string got;
    std::thread reader([&] { got = slurp(d / "pipe.png"); });
    Result r = runSprout("render koch --size 64x48 -o " + (d / "pipe.png").string());
    reader.join();
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(isPng(got));
    struct stat st{};
    ASSERT_EQ(::lstat((d / "pipe.png").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "still a FIFO, not renamed over";
}

TEST(Files, SomeoneElsesTemporaryIsNotTouched) {
    const fs::path d = freshDir("foreign");
    std::ofstream(d / "plant.png.tmp") << "someone else's";
    std::ofstream(d / ".plant.png.sprout-keepme") << "someone else's too";
    Result r = runSprout("render koch --size 64x48 -o " + (d / "plant.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(isPng(slurp(d / "plant.png")));
    EXPECT_EQ(slurp(d / "plant.png.tmp"), "someone else's");
    EXPECT_EQ(slurp(d / ".plant.png.sprout-keepme"), "someone else's too");
}

TEST(Files, ConcurrentWritesOfOneFileEachLeaveAWholeFile) {
    const fs::path d = freshDir("concurrent");
    const std::string out = (d / "same.png").string();
    std::vector<std::thread> runs;
    std::vector<int> codes(4, -1);
    for (int k = 0; k < 4; ++k)
        runs.emplace_back([&, k] { codes[size_t(k)] = runSprout("render fractal_plant -n " + std::to_string(2 + k) + " --size 96x64 -o " + out).code; });
    for (auto& t : runs) t.join();
    for (int c : codes) EXPECT_EQ(c, 0);
    EXPECT_TRUE(isPng(slurp(out)));
    EXPECT_EQ(temporaries(d), 0);
    // And the library itself: two writers of one file, interleaved, do not collide.
    std::string e1, e2;
    sprout::AtomicFile a, b;
    ASSERT_TRUE(a.open(out, e1));
    ASSERT_TRUE(b.open(out, e2));
    a.write("first", 5);
    b.write("second", 6);
    ASSERT_TRUE(a.commit(e1)) << e1;
    ASSERT_TRUE(b.commit(e2)) << e2;
    EXPECT_EQ(slurp(out), "second");
    EXPECT_EQ(temporaries(d), 0);
}

// A write that fails (disk full) leaves the old file as it was and no temporary.
TEST(Files, AFullDiskKeepsTheOldFile) {
    const fs::path d = freshDir("full");
    const std::string preload = "ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0 SPROUT_FAIL_WRITES=1 "
                                "SPROUT_FAIL_AFTER=4096 LD_PRELOAD=" SPROUT_FAIL_WRITES_LIB " ";
    auto failing = [&](const std::string& args) {
        const std::string err = (d / "err.txt").string();
        const int status = std::system((preload + SPROUT_BINARY + " " + args + " >/dev/null 2>" + err).c_str());
        return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err));
    };
    for (const std::string name : {"old.png", "old.glb", "old.ply", "old.svg", "old.obj"}) {
        SCOPED_TRACE(name);
        std::ofstream(d / name) << "the old file";
        if (name == "old.obj") std::ofstream(d / "old.mtl") << "the old materials";
        const std::string cmd = name.ends_with(".png") ? "render fractal_plant --size 320x240 -o " : "export fractal_plant --quiet -o ";
        auto [code, err] = failing(cmd + (d / name).string());
        EXPECT_EQ(code, 1);
        EXPECT_NE(err.find("No space left on device"), std::string::npos) << err;
        EXPECT_EQ(slurp(d / name), "the old file");
        if (name == "old.obj") {
            EXPECT_EQ(slurp(d / "old.mtl"), "the old materials");
        }
        EXPECT_EQ(temporaries(d), 0);
    }
    // Without the failure the same commands write.
    Result ok = runSprout("export fractal_plant --quiet -o " + (d / "old.obj").string());
    EXPECT_EQ(ok.code, 0) << ok.err;
    EXPECT_TRUE(slurp(d / "old.obj").starts_with("# Sprout"));
    EXPECT_TRUE(slurp(d / "old.mtl").starts_with("# Sprout"));
}

TEST(Files, DashIsStandardOutput) {
    Result r = runSprout("render koch --size 64x48 --stats -o -");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(isPng(r.out));
    EXPECT_NE(r.err.find("2D curve"), std::string::npos) << "the stats go to standard error";
    r = runSprout("export koch -o -");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.out.starts_with("glTF"));
    r = runSprout("export koch -o - --format obj");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.out.starts_with("# Sprout"));
    EXPECT_EQ(r.out.find("mtllib"), std::string::npos) << "no material file beside standard output";
}

}  // namespace
