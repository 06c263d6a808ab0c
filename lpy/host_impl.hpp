#pragma once
// What the host's files share (lpy/README.md): the interpreter's start, the names of module
// classes that Python's objects read, Python errors as diagnostics, the turtle's settings
// from the model's context. Included by host.cpp, python_types.cpp and session.cpp only.
#include <mutex>
#include <string>
#include <string_view>

#include <pybind11/pybind11.h>

#include "core/language/diagnostic.hpp"
#include "lpy/draw.hpp"
#include "lpy/engine.hpp"

namespace sprout::lpy {

// Starts the interpreter (or, in the `sprout` Python module, sets up the running one) and
// installs openalea.lpy and openalea.plantgl; once per process.
void start();
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
// The model's turtle settings and materials as its context holds them.
TurtleDefaults turtleDefaults(const py::module_& lpyModule);

// The scene the turtle draws from `s` with the engine's interpretation rules: a PlantGL Scene
// of shapes whose ids are the modules of `s` that drew them (L-Py's sceneInterpretation).
py::object sceneOf(Engine& engine, const LString& s);

// L-Py's query modules (?P ?H ...) given the turtle's state where they stand (each step,
// before the rules, when a rule reads one).
void fillQueries(Engine& engine, LString& s, const TurtleDefaults& d);

// The Python classes of `_sprout_lpy` (python_types.cpp: Module, ModuleClass, Lstring;
// session.cpp: _Session, which openalea.lpy's Lsystem drives).
void defineTypes(py::module_& m);
// PlantGL's curves in C++ for Sprout's Python PlantGL (pgl_native.cpp: _PglNurbs, _PglPatch),
// added by defineTypes.
void definePlantGL(py::module_& m);
// _QuantisedBase, QuantisedFunction's call in C (lpy/pgl_quantised.cpp).
void defineQuantised(py::module_& m);
void definePointGrid(py::module_& m);  // pgl_shapes.cpp: Point3Grid, AsymmetricHull
void defineSession(py::module_& m);

}  // namespace sprout::lpy
