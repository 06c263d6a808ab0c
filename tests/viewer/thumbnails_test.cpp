// The presets' thumbnails (app/viewer/window/thumbnails.hpp): made one at a time by a child
// process, paused while the window holds them back and going on when it lets them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "app/plant/presets.hpp"
#include "app/viewer/window/thumbnails.hpp"

namespace sprout::viewer {
namespace {

std::uintmax_t sizeOf(const std::filesystem::path& p) {
    std::error_code ec;
    const auto n = std::filesystem::file_size(p, ec);
    return ec ? 0 : n;
}

// The child is a script of the test's, run as `sprout render NAME -o PATH --size WxH` would
// be: it writes a byte beside PATH every 10 ms until it has written 100 of them.
TEST(Thumbnails, TheOneBeingMadeIsPausedWhileHeldBackAndGoesOnAfter) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sprout_thumbs_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path exe = dir / "fake_sprout";
    {
        std::ofstream f(exe);
        f << "#!/bin/sh\ni=0\nwhile [ $i -lt 100 ]; do printf x >> \"$4.ticks\"; i=$((i+1)); sleep 0.01; done\nexit 1\n";
    }
    std::filesystem::permissions(exe, std::filesystem::perms::owner_all);
    const std::vector<std::string> names = {presetNames().front()};
    std::uintmax_t ticks = 0;
    {
        Thumbnails t(exe.string(), (dir / "cache").string());
        t.poll(names, true);  // starts the one missing
        ASSERT_TRUE(t.making());
        std::filesystem::path counter;
        for (int i = 0; i < 500 && counter.empty(); ++i) {  // its first tick
            for (const auto& e : std::filesystem::directory_iterator(dir / "cache"))
                if (e.path().extension() == ".ticks") counter = e.path();
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        ASSERT_FALSE(counter.empty()) << "the child never ran";
        t.poll(names, false);  // held back
        EXPECT_TRUE(t.paused());
        std::this_thread::sleep_for(std::chrono::milliseconds(100));  // a tick in flight lands
        const std::uintmax_t held = sizeOf(counter);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        EXPECT_EQ(sizeOf(counter), held) << "it went on while held back";
        EXPECT_LT(held, 100u);
        t.poll(names, true);  // let go: it goes on, and ends
        EXPECT_FALSE(t.paused());
        for (int i = 0; i < 1000 && t.making(); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            t.poll(names, true);
        }
        EXPECT_FALSE(t.making());
        ticks = sizeOf(counter);
        EXPECT_EQ(ticks, 100u) << "it went on after";
        EXPECT_EQ(t.get(names[0]), nullptr);  // it failed (the script makes no picture)
        // Held back again with nothing being made: nothing to pause, and nothing started.
        t.poll(names, false);
        EXPECT_FALSE(t.making());
    }
    // One paused as the window closes ends all the same (it was waited for above).
    {
        std::filesystem::remove_all(dir / "cache");
        Thumbnails t(exe.string(), (dir / "cache").string());
        t.poll(names, true);
        t.poll(names, false);
        EXPECT_TRUE(t.paused());
    }  // the destructor waits for it: a stopped child that never ended would hang here
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sprout::viewer
