#pragma once
// Runs the `sprout` program as a user does: arguments, standard input, output, exit code.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace sprout_test {

struct Result {
    int code = -1;
    std::string out, err;
};

inline Result runSprout(const std::string& args, const std::string& stdinText = "") {
    // ctest runs tests in parallel processes: every call gets its own files.
    static int calls = 0;
    std::string tag = std::to_string(getpid()) + "_" + std::to_string(++calls);
    std::string errFile = testing::TempDir() + "sprout_stderr_" + tag + ".txt";
    std::string inFile = testing::TempDir() + "sprout_stdin_" + tag + ".txt";
    std::ofstream(inFile) << stdinText;
    std::string cmd = std::string(SPROUT_BINARY) + " " + args + " <" + inFile + " 2>" + errFile;
    Result r;
    FILE* p = popen(cmd.c_str(), "r");
    char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(errFile);
    r.err.assign(std::istreambuf_iterator<char>(e), {});
    std::remove(errFile.c_str());
    std::remove(inFile.c_str());
    return r;
}

inline std::string writeTemp(const std::string& name, const std::string& text) {
    std::string path = testing::TempDir() + std::to_string(getpid()) + "_" + name;
    std::ofstream(path) << text;
    return path;
}

}  // namespace sprout_test
