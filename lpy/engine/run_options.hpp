#pragma once
// How one run of an L-Py model goes (lpy/lpy.hpp's runModel, and the engine that runs it):
// its steps, its limits, Cancel, what is kept of it.
#include <atomic>
#include <cstdint>
#include <string>

#include "core/derive/derive.hpp"

namespace sprout::lpy {

struct RunOptions {
    std::string path;                             // the file (tracebacks, imports beside it); may be empty
    int steps = -1;                               // -1: the file's derivation length
    const std::atomic<bool>* cancel = nullptr;    // set by another thread: Python stops within ~100 ms
    bool keepSteps = false;                       // keep every step's drawable (growth stepping)
    std::size_t maxModules = 50'000'000;          // a string past this ends the derivation with a message
    // The memory a step's strings may take (the one read and the one made, their Python
    // parameters measured): a step that would pass it ends the derivation with a message.
    std::uint64_t maxBytes = defaultMemoryBudget();
    bool native = true;  // produce-only arithmetic rules derive without Python (false: every match calls Python)
    // With keepSteps: nothing is drawn by the run (the `sprout` Python module: open() and derive() derive;
    // the viewer draws the step it shows); Model::later draws a step, or reads it, when asked.
    bool drawLater = false;
    // With keepSteps: the derivation record and where contexts matched (the viewer's inspector
    // and picking; the `sprout` Python module reads a step's record from Model::later when asked).
    bool keepRecord = true;
};

}  // namespace sprout::lpy
