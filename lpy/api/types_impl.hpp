#pragma once
// What the files of L-Py's string classes share (types.cpp: ModuleClass and these helpers;
// types_module.cpp: Module, ParamModule, NodeModule; types_lstring.cpp: AxialTree, Lstring,
// AxialTreeIterator). Not part of lpy/api's face (api.hpp).
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "lpy/engine/axial_tree.hpp"
#include "lpy/engine/lstring.hpp"

namespace sprout::lpy::types {

namespace py = pybind11;

const std::string& nameOf(int cls);
// The class a name Python gives names, added when new (a name a string could not be read
// back with, holding parentheses, commas or spaces: ValueError; '' L-Py's None module).
int internName(const std::string& name);
// A name given as a Python value: a str (else TypeError).
std::string nameText(py::handle v);
// The namespace Python values of lstrings are read in: the running engine's, or the
// process's own outside a derivation.
py::dict namespaceNow();
// `s += 'B'`, `s + other`: text is read as an lstring, anything else as produce takes it.
void extend(LString& s, py::handle v);
// L-Py's ParamModule ==: the same class and equal parameters.
bool sameModule(const LModule& a, const LModule& b);
// A module of the string `s`, as Python sees it (a ParamModule that writes into s).
PyParamModule viewOf(const std::shared_ptr<LString>& s, size_t i);
// A module of its own.
PyParamModule ownModule(LModule m);
// The scale of each class as the running model or the current context says.
tree::Scale scales();
// A module's parameter names (`module A(x, y)`), the class's own or its bases'.
const std::vector<std::string>& parameterNamesOf(int cls);
// A Python value made into one module (a module, a tuple ('A', 1), a string 'A(1)').
LModule oneModule(py::handle v);
// The module a text of one module names ('A', 'A(1)'): its class and arguments.
LModule moduleFromText(const std::string& text);
// A module of class `cls` from values[start:] (L-Py's processConstruction): `new` takes its
// name from the first value, a PackedArgs given last is unpacked.
LModule construct(int cls, const py::sequence& values, size_t start);
bool isRequest(int cls);
// (name, args) pairs: how an AxialTree or a module is pickled.
py::list stateOf(const LString& s);
LString fromState(py::handle state);

void defineModules(py::module_& m);  // types_module.cpp
void defineLstrings(py::module_& m);  // types_lstring.cpp

}  // namespace sprout::lpy::types
