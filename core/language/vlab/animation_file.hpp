#pragma once
// A VLab object's animation file (`.a`), read as cpfg reads it (VLab's cpfg/animparam.c,
// ReadAnimData): which derivation steps an animation shows (first frame, last frame, step, or
// frame intervals) and how (double buffer, clearing, scaling and centring between frames,
// swap interval). cpfg skips a command it does not know; Sprout warns at its line.
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"

namespace sprout::vlab {

// `frame intervals: 1-10 step 2, 12, 20-30 rotate 0 10 0`
struct FrameInterval {
    int from = -1, to = -1, step = -1;
    int function = 0;  // 0 none, 1 rotate, 2 scale (by `data`)
    double data[3] = {0, 0, 0};
};

struct AnimationFile {
    int first = 1;   // `first frame:` (negative reads as 0)
    int last = 1;    // `last frame:`; -1: the L-system's derivation length
    int step = 1;    // `step:` (0 or less reads as 1)
    int swapInterval = 1;
    bool doubleBuffer = true, clearBetweenFrames = true, scaleBetweenFrames = false;
    bool newViewBetweenFrames = false, centerBetweenFrames = false, hcenterBetweenFrames = false;
    std::vector<FrameInterval> intervals;  // when given, first and last come from them
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return !hasErrors(diagnostics); }
    // The derivation steps the animation shows, given the L-system's derivation length.
    std::vector<int> frames(int derivationLength) const;
};

AnimationFile readAnimationFile(std::string_view text);

}  // namespace sprout::vlab
