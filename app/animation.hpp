#pragma once
// Growth and turntable videos, headless: frames rendered through OSMesa and piped to ffmpeg
// (MP4, H.264), or written as a PNG sequence when ffmpeg is absent or asked for.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/snapshot.hpp"

namespace sprout {

enum class AnimationKind { Growth, Turntable };

struct AnimationOptions {
    AnimationKind kind = AnimationKind::Growth;
    int frames = 0;  // 0: growth half a second per step, turntable 5 seconds
    int fps = 24;
    std::string recipe;  // grammar text each PNG frame carries
    // An L-Py model's kept steps (step 0 .. n, each a grammar whose axiom is the string to
    // draw): growth shows them in turn instead of deriving `grammar`.
    std::vector<std::shared_ptr<const Grammar>> steps;
    // Growth shows these derivation steps, one a frame (a VLab object's animation file: first
    // frame to last by step); empty: from the axiom to step n, growing smoothly.
    std::vector<int> shownSteps;
    std::function<void(int frame, int frames)> progress;
};

struct AnimationResult {
    int frames = 0;
    bool video = false;        // false: PNG frames
    std::string firstFrame;    // the first PNG of a sequence
    std::string note;          // e.g. why a PNG sequence was written instead of a video
};

// `out` ending in .mp4 (also .mkv, .webm, .mov) makes a video, in .png a numbered sequence
// (out_0001.png ...). False with a message on failure.
bool renderAnimation(std::shared_ptr<const Grammar> grammar, const SnapshotOptions& snapshot, const AnimationOptions& options,
                     const std::string& out, AnimationResult& result, std::string& error);

// Whether `ffmpeg` can be run.
bool haveFfmpeg();

}  // namespace sprout
