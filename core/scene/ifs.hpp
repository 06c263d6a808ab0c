#pragma once
// Iterated function systems (seed document 000, section 2.2): affine maps with
// probabilities, drawn by the chaos game into a density image.
//
// An .ifs file: one map per line, `a b c d e f p` for x' = a x + b y + e, y' = c x + d y + f
// chosen with probability p; settings `points: 100000000`, `seed: 1`, `colour: #2f6e2a`;
// `#` comments.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout {

struct AffineMap {
    double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0, p = 0;
};

struct Ifs {
    std::vector<AffineMap> maps;
    std::uint64_t points = 100'000'000;
    std::uint64_t seed = 1;
    std::uint32_t colour = 0x2F6E2AFF;  // 0xRRGGBBAA: the densest pixels
};

struct IfsParseResult {
    std::optional<Ifs> ifs;
    std::vector<Diagnostic> diagnostics;
};
IfsParseResult parseIfs(std::string_view text);

struct Density {
    int width = 0, height = 0;
    std::vector<std::uint32_t> counts;  // row 0 at the top
    double minX = 0, maxX = 1, minY = 0, maxY = 1;  // the plane area shown
    std::uint64_t points = 0;
};

// Plays the chaos game with `threads` threads (each its own seeded stream, so the image is
// the same for a seed and a thread count), the attractor fitted to the image with a margin.
// Returns false when cancelled.
bool chaosGame(const Ifs& ifs, int width, int height, Density& out, int threads = 2,
               const std::atomic<bool>* cancel = nullptr);

// Log tone mapping: 0xRRGGBBAA pixels, the background where nothing landed.
std::vector<std::uint8_t> toneMap(const Density& d, std::uint32_t colour, std::uint32_t background);

}  // namespace sprout
