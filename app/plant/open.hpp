#pragma once
// Opening a plant from what a source names (app/plant/source.hpp: a file of any kind, "-" for
// standard input, a preset's name): its grammar read, or an L-Py model run by its Python
// (lpy/lpy.hpp), or a forest scene built. What is wrong is said through `report`, one line at a
// time, as it is found (the CLI prints each to standard error: app/cli/).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/grammar.hpp"
#include "lpy/lpy.hpp"

namespace sprout {

// Told each diagnostic or error, written with its file (FILE:line:col: ...).
using Report = std::function<void(const std::string&)>;

struct LoadedGrammar {
    std::string displayName;  // used in FILE:line:col messages
    std::string text;         // the grammar as written
    std::shared_ptr<const Grammar> grammar;
    FileKind kind = FileKind::Lsys;  // of `text`: Lsys, Cpfg or Lpy
    std::string dialect;             // what the text was read as: ".lsys", "ABOP notation", "cpfg", "L-Py", "Lparser", "Fractint"
    // An L-Py model run by Python (lpy/): `grammar` is what it derived, to draw (no rules);
    // `derived` the string as L-Py writes it.
    bool ranPython = false;
    std::string derived;
    std::vector<std::shared_ptr<const Grammar>> steps;  // LoadOptions::keepSteps: step 0 .. n, each to draw
};

struct LoadOptions {
    int steps = -1;       // an L-Py model's derivation length (-1: the file's)
    bool python = true;   // false (--no-python): an L-Py model's Python is refused
    bool keepSteps = false;  // an L-Py model: keep every step's drawing (growth videos)
    std::uint64_t maxModules = 0, maxBytes = 0;  // an L-Py model's limits (--max-modules, --max-memory; 0: its own)
};

// A text of `kind` made a plant: its grammar parsed (any grammar kind; `path` the file it came
// from, for #include and files beside it), or an L-Py model run by its Python (lpy::runModel
// with `lpyOptions`, the file `path`). The one place a source's text becomes a grammar, for the
// command line, the viewer's worker and Python's Plant; callers decide whether an L-Py model's
// Python may run before they call it.
struct OpenedText {
    std::shared_ptr<const Grammar> grammar;  // null when it cannot be drawn (its diagnostics say why)
    std::vector<Diagnostic> diagnostics;
    std::shared_ptr<lpy::Model> model;  // an L-Py model's run: its steps, its string, what draws later
    bool ok() const { return grammar != nullptr; }
};
OpenedText openText(const std::string& text, FileKind kind, const std::string& path, const lpy::RunOptions& lpyOptions = {});

// Reports diagnostics (errors and warnings); nullopt when the grammar has errors or cannot be
// read.
std::optional<LoadedGrammar> openPlant(const std::string& source, const LoadOptions& options, const Report& report);

// What a source (file, PNG written by Sprout, preset or "-") holds, by detectFileKind():
// Lsys, Cpfg, Ifs or Forest (Lparser and Fractint files are read as the .lsys they become).
FileKind sourceKind(const std::string& source);

}  // namespace sprout
