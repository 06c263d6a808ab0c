// The chaos game: 10^8 points of the Barnsley fern into a 1280x720 density image.
//
//   build/bench/ifs_bench
//
// Reported against the 1 s bar and against one thread in the same run.
#include <chrono>
#include <cstdio>
#include <thread>

#include "core/scene/ifs.hpp"

int main() {
    using namespace sprout;
    Ifs fern = *parseIfs(
                    "0 0 0 0.16 0 0 0.01\n0.85 0.04 -0.04 0.85 0 1.6 0.85\n0.2 -0.26 0.23 0.22 0 1.6 0.07\n"
                    "-0.15 0.28 0.26 0.24 0 0.44 0.07\npoints: 100000000\n")
                    .ifs;
    auto run = [&](int threads) {
        double best = 1e9;
        for (int i = 0; i < 3; ++i) {
            Density d;
            auto t0 = std::chrono::steady_clock::now();
            chaosGame(fern, 1280, 720, d, threads);
            best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        return best;
    };
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    double all = run(cores), one = run(1);
    std::printf("chaos game, 10^8 points, 1280x720: %.0f ms on %d threads (bar 1000 ms, %.2fx of the bar), "
                "%.0f ms on one thread (%.2fx speed-up); %.0f M points/s\n",
                all * 1e3, cores, all, one * 1e3, one / all, 1e8 / all / 1e6);
    return 0;
}
