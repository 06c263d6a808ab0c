#pragma once
// lpy's public face: L-Py models run by an embedded CPython (lpy/README.md). The file is
// translated (lpy/translate/translate.hpp), its Python runs in a namespace of its own, and the derivation follows
// L-Py's semantics (L-Py's src/cpp/lsystem.cpp): rules tried in order with their Python
// bodies, contexts on the axial tree, hooks, groups, direction, decomposition and
// interpretation. What it derives is handed to Sprout's turtle as a string in Sprout's
// vocabulary (lpy/draw/draw.hpp), so pictures, exports and the viewer work as for every grammar.
//
// Python in a file is a program: callers decide whether a file may run (the viewer asks the
// user; `sprout render | expand | export` run it as `python3 FILE` would, unless --no-python).
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/language/diagnostic.hpp"
#include "core/derive/derive.hpp"
#include "core/derive/provenance.hpp"
#include "core/language/grammar.hpp"
#include "lpy/engine/run_options.hpp"

namespace sprout::lpy {


// A Python error in an interpretation rule, met while a step is drawn later: what() is the
// diagnostic written with its file.
struct DrawError : std::runtime_error {
    Diagnostic diagnostic;
    DrawError(Diagnostic d, const std::string& file) : std::runtime_error(formatDiagnostic(d, file)), diagnostic(std::move(d)) {}
};

// A run kept to draw its steps later (RunOptions::drawLater): the model's engine and namespace
// live with it. draw() takes the interpreter itself: call it without holding the GIL. Throws
// DrawError (a Python error, at its line) or std::out_of_range.
class StepDrawer {
public:
    virtual ~StepDrawer() = default;
    virtual int steps() const = 0;  // step 0 (the axiom) .. steps() - 1
    // `from`, when given: for each module the drawing's axiom holds, the module of the step
    // that it draws (picking). `cancel`, set by another thread, stops it: nullptr is returned.
    virtual std::shared_ptr<const Grammar> draw(int step, std::vector<std::uint32_t>* from = nullptr,
                                                const std::atomic<bool>* cancel = nullptr) = 0;
    // Step `step` as derived: a record of that step alone (its grammar names the modules).
    virtual DerivationRecord derived(int step) = 0;
    // Step `step` as L-Py writes it.
    virtual std::string text(int step) = 0;
};

struct Model {
    std::vector<Diagnostic> diagnostics;
    // What the turtle draws: a Grammar with no rules whose axiom is the final string with the
    // interpretation rules applied, in Sprout's turtle vocabulary, and L-Py's turtle defaults
    // (60 degree turns, materials as the palette).
    std::shared_ptr<const Grammar> drawable;
    std::vector<std::shared_ptr<const Grammar>> steps;  // keepSteps, not drawLater: step 0 (the axiom) .. n
    // keepSteps, for "why this branch?" and the derivation inspector: each step's modules (by
    // name, their numbers; NaN for other Python values) and where each came from (the rule,
    // whose line the record's grammar keeps; its module in the step before), and per step,
    // for each module of its drawing's axiom, the module of that step it draws.
    DerivationRecord record;
    std::vector<std::shared_ptr<const std::vector<std::uint32_t>>> drawnFrom;
    std::string derived;         // the final string as L-Py writes it (drawLater: Model::later's text)
    int derivationLength = 0;    // as the file says
    int stepsDone = 0;
    bool cancelled = false;
    bool ranNative = false;  // derived by the native path (lpy/engine/native_derive.cpp)
    double deriveSeconds = 0;  // the derivation alone (its rules), without setup and drawing
    // drawLater: what draws each step (`drawable` then holds only the turtle's settings).
    std::shared_ptr<StepDrawer> later;
    bool ok() const { return drawable != nullptr; }
};

// False when Sprout was built without Python (then .lpy files are read by the cpfg reader).
bool pythonAvailable();

Model runModel(std::string_view text, const RunOptions& options);

// What Sprout's turtle draws of an Lstring of a Python script's Lsystem (its `_Session`,
// lpy/api/session.cpp, and the Lstring, as Python objects): for `sprout`'s pictures and exports
// of a scene. Throws std::invalid_argument for objects of other kinds.
std::shared_ptr<const Grammar> drawingOf(void* session, void* lstring);

// What makes a Scene an Lsystem drew into a picture or a model (its render, export and
// _repr_png_): the `sprout` module hands its Plant maker down (python/), a Python callable
// (session, lstring) -> sprout.Plant given as a PyObject*; lpy's Python imports nothing above it.
void setScenePlantMaker(void* maker);

// Points along an L-Py model's 2D curve as PlantGL evaluates it (lpy/plantgl/curves.hpp), for
// the panel's curve editor: kind 0 a NURBS of `degree` on uniform clamped knots, 1 a Bezier
// (one span of all its points), 2 the polyline itself; `ctrl` is (x, y, weight) a point.
// `samples` points from the first knot to the last (the polyline's own points for kind 2).
std::vector<std::array<double, 2>> curveSamples(int kind, int degree, const std::vector<std::array<double, 3>>& ctrl, int samples);
// Points of an L-Py model's NurbsPatch as PlantGL evaluates it, for the panel's surface editor:
// `rows` its [u][v] control points (x, y, z, w) on uniform clamped knots of the degrees;
// `samples` x `samples` points, [u][v], from the first knots to the last (empty where the
// points do not make a patch).
std::vector<std::vector<std::array<double, 3>>> patchSamples(const std::vector<std::vector<std::array<double, 4>>>& rows, int udegree,
                                                             int vdegree, int samples);

// Installs Sprout's openalea.lpy and openalea.plantgl (L-Py's Python API, lpy/api/session.cpp)
// into the running interpreter: `sprout.use_as_openalea()`.
void installOpenalea();

}  // namespace sprout::lpy
