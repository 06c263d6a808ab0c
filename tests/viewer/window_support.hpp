#pragma once
// What the window tests share (tests/viewer/window_test.cpp, window_lpy_test.cpp): the real
// viewer run under Xvfb, with a script, and its screenshots read back.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/image.hpp"
#include "lpy/lpy.hpp"

namespace sprout {
namespace fs = std::filesystem;

inline bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

inline int runUnderXvfb(const std::string& args, const std::string& env = "", const std::string& stdoutFile = "/dev/null",
                 const std::string& server = "-screen 0 1600x1000x24") {
    fs::path home = fs::path(testing::TempDir()) / ("sprout_window_home_" + std::to_string(::getpid()));
    fs::create_directories(home);
    std::string cmd = "cd " + home.string() + " && XDG_STATE_HOME=" + home.string() + "/state XDG_CONFIG_HOME=" + home.string() + "/config XDG_CACHE_HOME=" +
                      home.string() + "/cache " + env + " timeout 120 xvfb-run -a -s '" + server + "' " SPROUT_BINARY " " +
                      args + " >" + stdoutFile + " 2>/dev/null";
    return std::system(cmd.c_str());
}

inline Image load(const std::string& path) {
    Image img;
    std::string error;
    EXPECT_TRUE(readPng(path, img, error)) << path << ": " << error;
    return img;
}

// Mean colour of a rectangle.
inline std::array<double, 3> mean(const Image& img, int x0, int y0, int x1, int y1) {
    std::array<double, 3> m{0, 0, 0};
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++n)
            for (int c = 0; c < 3; ++c) m[size_t(c)] += img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4 + size_t(c)];
    for (auto& v : m) v /= std::max(n, 1);
    return m;
}

// How many pixels of two pictures differ clearly (red and green by more than 40 together).
inline std::size_t pixelsThatDiffer(const Image& x, const Image& y) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.rgba.size() && i < y.rgba.size(); i += 4)
        n += std::abs(int(x.rgba[i]) - int(y.rgba[i])) + std::abs(int(x.rgba[i + 1]) - int(y.rgba[i + 1])) > 40;
    return n;
}

// A file's bytes ("" when it cannot be read).
inline std::string fileText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A folder of one test's own.
inline fs::path testDir(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("sprout_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// Runs the viewer on `args` with `script` (kept in `dir`): what it printed, a line each.
inline std::vector<std::string> runScript(const fs::path& dir, const std::string& args, const std::string& script) {
    std::ofstream(dir / "script.txt") << script;
    const std::string out = (dir / "out.txt").string();
    EXPECT_EQ(runUnderXvfb(args + " --script " + (dir / "script.txt").string(), "", out), 0);
    std::ifstream in(out);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The w x h rectangle at the top left of an Xvfb screen kept in a file (-fbdir: an XWD image,
// 32 bits a pixel) as RGB, a row after another; false when the file is not such an image yet.
inline bool screenCorner(const std::string& xwd, int w, int h, std::vector<std::uint8_t>& out) {
    out.clear();
    if (xwd.size() < 100) return false;
    auto field = [&](int k) {  // XWD's header: big-endian 32-bit fields
        const auto* b = reinterpret_cast<const unsigned char*>(xwd.data()) + 4 * k;
        return std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3];
    };
    const std::uint32_t header = field(0), width = field(4), height = field(5), bitsPerPixel = field(11), bytesPerLine = field(12),
                        colours = field(19);
    const std::size_t pixels = header + std::size_t(colours) * 12;
    if (bitsPerPixel != 32 || width < std::uint32_t(w) || height < std::uint32_t(h) || xwd.size() < pixels + std::size_t(bytesPerLine) * height)
        return false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto* p = reinterpret_cast<const unsigned char*>(xwd.data()) + pixels + std::size_t(y) * bytesPerLine + 4 * x;
            out.insert(out.end(), {p[2], p[1], p[0]});  // B G R X
        }
    return true;
}

// How many pixels differ by more than 30 of 765 between two screens (screenCorner's RGB, `width`
// pixels a row) in columns [x0, x1) of rows [0, y1).
inline int screensDiffer(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int width, int x0, int x1, int y1) {
    int n = 0;
    for (int y = 0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
            if (i + 2 >= a.size() || i + 2 >= b.size()) return n + 1;
            n += std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]) > 30;
        }
    return n;
}

// How many pixels of `view` differ by more than 30 of 765 from the screen's (screenCorner's RGB,
// `width` pixels a row) where the view is shown: from column x0 of the screen's first rows.
inline int viewDiffersOnScreen(const std::vector<std::uint8_t>& screen, int width, int x0, const Image& view) {
    int differ = 0;
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x + x0)) * 3;
            if (i + 2 >= screen.size()) return view.width * view.height;
            const auto* a = &screen[i];
            const auto* b = &view.rgba[(std::size_t(y) * std::size_t(view.width) + std::size_t(x)) * 4];
            differ += std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 30;
        }
    return differ;
}

// The count of a "view_draws=N" line, -1 when it is not one.
inline long viewDraws(const std::vector<std::string>& lines, size_t k) {
    return k < lines.size() && lines[k].rfind("view_draws=", 0) == 0 ? std::stol(lines[k].substr(11)) : -1;
}

}  // namespace sprout
