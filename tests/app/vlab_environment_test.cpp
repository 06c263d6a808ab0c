// A VLab object's environment (`cpfg -e FILE.e`, issue 50): its program answers the ?E when the
// object's folder opens, and when its L-system is opened from inside the folder; a program
// Sprout does not provide is named. The expected string is the reference cpfg's on this object.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_sprout.hpp"

namespace {

using sprout_test::Result;
using sprout_test::runSprout;

TEST(VlabObject, ItsEnvironmentProgramAnswersTheQueries) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(testing::TempDir()) / ("vlab_environment_" + std::to_string(getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "specifications") << "model:\n\tgenerate:\n\t\tcpfg -e a.e a.l\n";
    std::ofstream(folder / "a.e") << "executable: honda81 d.spec\ncommunication type: files\nturtle position: %.4f %.4f %.4f\n";
    std::ofstream(folder / "d.spec") << "radius: 0.5\n";
    std::ofstream(folder / "a.l") << "Lsystem: 1\nderivation length: 1\nAxiom: [&(90)f(1)?E(1)][f(1)?E(1)][f(2)?E(1)][^(90)f(2)?E(3)]"
                                     "[^(90)f(2.4)?E(2)]\n?E(v) --> R(v)\nendlsystem\n";
    const std::string expected = "[&(90)f(1)R(1)][f(1)R(0)][f(2)R(0)][^(90)f(2)R(1)][^(90)f(2.4)R(0)]\n";
    const Result object = runSprout("expand " + folder.string());
    EXPECT_EQ(object.code, 0) << object.err;
    EXPECT_EQ(object.out, expected);
    EXPECT_EQ(object.err, "");
    const Result inside = runSprout("expand " + (folder / "a.l").string());
    EXPECT_EQ(inside.out, expected) << inside.err;

    // A program Sprout does not provide: named, and the ?E keep their values.
    std::ofstream(folder / "a.e") << "executable: soil -e a.e d.spec\n";
    const Result unknown = runSprout("expand " + folder.string());
    EXPECT_EQ(unknown.code, 0) << unknown.err;
    EXPECT_EQ(unknown.out, "[&(90)f(1)R(1)][f(1)R(1)][f(2)R(1)][^(90)f(2)R(3)][^(90)f(2.4)R(2)]\n");
    EXPECT_NE(unknown.err.find((folder / "a.e").string() + ":1:1: warning: the environment program 'soil' is not one Sprout provides"),
              std::string::npos) << unknown.err;
    fs::remove(folder / "a.e");
    const Result missing = runSprout("expand " + folder.string());
    EXPECT_EQ(missing.code, 1);
    EXPECT_NE(missing.err.find((folder / "a.e").string() + ": the environment file cannot be read"), std::string::npos) << missing.err;
    fs::remove_all(folder);
}

}  // namespace
