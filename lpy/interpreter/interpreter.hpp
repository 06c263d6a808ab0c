#pragma once
// The embedded interpreter (lpy/README.md), what the files above it share: its start, the
// names of module classes that Python's objects read, the running engine, Python errors as
// diagnostics, %pastefile's files, a model's namespace.
#include <mutex>
#include <string>
#include <string_view>

#include <pybind11/pybind11.h>

#include "core/language/diagnostic.hpp"
#include "lpy/engine/engine.hpp"

namespace sprout::lpy {

// Starts the interpreter (or, in the `sprout` Python module, sets up the running one, with
// `_sprout_lpy` made by `defineModule`: lpy/api/module.cpp) and installs openalea.lpy and
// openalea.plantgl; once per process.
void start(void (*defineModule)(py::module_&));
// One model runs at a time in the program's interpreter (CLI and viewer threads).
std::mutex& runMutex();

// The process's module classes (ModuleClasses::seededFrom): every translation starts from
// them and gives back the names it made, so the Lstrings of every L-system of a process agree
// on their ids. Held with the GIL.
ModuleClasses& registry();
// The names Python's modules and Lstrings read: the running engine's, or the registry's.
ModuleClasses& names();
// The namespace an lstring's arguments are evaluated in outside a derivation.
py::dict looseNamespace();

// Makes `e` this thread's engine while it lives, the two tables of names kept in step.
class EngineScope {
public:
    explicit EngineScope(Engine* e);
    ~EngineScope();
    EngineScope(const EngineScope&) = delete;
    EngineScope& operator=(const EngineScope&) = delete;

private:
    Engine* m_engine;
    Engine* m_before;
};

// How %pastefile / %pastemodule find files: beside the model (`modelPath`), then from the
// working folder (L-Py's way), a module also along PYTHONPATH.
PasteReader pasteReader(const std::string& modelPath);

// The model's namespace made ready to run its code (L-Py's: `from openalea.lpy import *`,
// the functions the generated code calls; imports beside `path`, the file, when given).
void prepareNamespace(py::dict ns, const std::string& path);
// Where a Python error happened in the model file, and what it says.
Diagnostic describe(py::error_already_set& e, const std::string& file, std::string_view text);

}  // namespace sprout::lpy
