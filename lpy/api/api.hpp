#pragma once
// openalea.lpy's API in C++ (lpy/README.md): the `_sprout_lpy` module the generated code and
// openalea.lpy's Python (lpy/api/lpy*.py) import, the classes of L-Py's strings, the session
// an Lsystem drives, and the PlantGL scene a string draws.
#include <pybind11/pybind11.h>

#include "lpy/engine/engine.hpp"

namespace sprout::lpy {

// `_sprout_lpy` (module.cpp): produce and the control functions, then defineTypes and
// defineSession. The program's interpreter has it built in; the `sprout` Python module makes it
// when the interpreter starts (lpy/interpreter/interpreter.hpp's start).
void defineSproutLpy(py::module_& m);
// The Python classes of L-Py's strings (types.cpp: Module, ModuleClass, Lstring), with
// PlantGL's C++ classes (lpy/plantgl/bindings.hpp).
void defineTypes(py::module_& m);
// _Session (session.cpp), which openalea.lpy's Lsystem drives.
void defineSession(py::module_& m);

// The scene the turtle draws from `s` with the engine's interpretation rules: a PlantGL Scene
// of shapes whose ids are the modules of `s` that drew them (L-Py's sceneInterpretation).
py::object sceneOf(Engine& engine, const LString& s);
// What Scene._plant calls (lpy/plantgl/plantgl_scene.py, through `_sprout_lpy._scene_plant`):
// the `sprout` module's maker of a Plant, set by it (lpy/lpy.hpp's setScenePlantMaker).
void setScenePlant(py::object maker);

}  // namespace sprout::lpy
