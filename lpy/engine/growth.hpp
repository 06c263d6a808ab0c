#pragma once
// What stops a derivation before it ends (lpy/engine/engine.hpp): the caller's Cancel, and the
// growth budget (RunOptions' maxModules, maxBytes) on the Python path: the string's bytes
// measured and checked as a pass makes it, the next step predicted from the step before, and
// before the first step the growth of the rules that always make the same successor followed
// (lpy/engine/growth.cpp). The native path checks its own steps (native_deriver.hpp).
#include <cstddef>
#include <functional>
#include <string>

#include <pybind11/pybind11.h>

#include "lpy/engine/lstring.hpp"
#include "lpy/engine/run_options.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout::lpy {

// Thrown when the caller cancels between rule calls.
struct Cancelled {};
// A step refused by the growth limits (RunOptions' maxModules, maxBytes): a ValueError in
// Python, an error at the `derivation length:` line in a file's diagnostics.
struct TooBig : py::value_error {
    using py::value_error::value_error;
};

// Throws Cancelled when the caller has asked to stop.
inline void checkCancel(const RunOptions& options) {
    if (options.cancel && options.cancel->load(std::memory_order_relaxed)) throw Cancelled{};
}

class GrowthBudget {
public:
    GrowthBudget(const Translation& tr, const RunOptions& options) : m_tr(tr), m_options(options) {}

    // The bytes a module of `s` takes, its Python parameters measured on up to 64 of its
    // modules; and the check of a growing string against RunOptions' limits (at step
    // `iteration`).
    static std::size_t moduleBytes(const LString& s);
    void check(const LString& in, const LString& out, std::size_t perModule, int iteration) const;
    // The production pass about to read `in` refused when it would grow the string as the
    // pass before did (grew) past the limits.
    void predictNextStep(const LString& in, std::size_t perModule, int iteration) const;
    // Measured on a string of some size only: what a few modules became is what one rule made
    // (an axiom's Init that makes a whole string, as L-Py's lsystem5.lpy does from an MTG), no
    // rate of growth; check() still measures the pass that follows as it makes it.
    void grew(const LString& in, const LString& out) {
        m_lastGrowth = in.size() >= 64 ? double(out.size()) / double(in.size()) : 1;
    }
    // When the model is bound: whether growth can be predicted (nothing Python may steer the
    // derivation with, no cut, rules of one module).
    void bind() { m_predictable = growthPredictable(); }
    // Before the first step: the least size of each of the next `steps` steps, followed
    // through the rules that always make the same successor; the first over RunOptions'
    // limits is refused (a ValueError naming it). Only where growth is predictable: the
    // engine calls it where no hook runs between steps. `derived(cls, base)`: module
    // inheritance, as the matcher reads it.
    void predict(const LString& s, int steps, int iteration, const std::function<bool(int, int)>& derived) const;

private:
    bool growthPredictable() const;
    const Translation& m_tr;
    const RunOptions& m_options;
    double m_lastGrowth = 1;  // the production pass before: modules made per module read
    bool m_predictable = false;
};

}  // namespace sprout::lpy
