// The `_sprout_lpy` module: the functions L-Py's generated code and model files call
// (produce, the control functions, the context tests of a rule's body) and, from types.cpp and
// session.cpp, the classes of L-Py's strings and the session openalea.lpy's Lsystem drives.
#include <algorithm>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "lpy/api/api.hpp"
#include "lpy/interpreter/interpreter.hpp"
#include "lpy/translate/turtle_vocabulary.hpp"

namespace py = pybind11;
using namespace sprout::lpy;

namespace {

Engine& engine() {
    Engine* e = currentEngine();
    if (!e) throw py::value_error("no L-Py model is running");
    return *e;
}

py::object*& scenePlant() {
    static py::object* maker = nullptr;
    return maker;
}

template <bool Last>
PyObject* rawProduce(PyObject*, PyObject* items) {
    try {
        engine().produce(py::handle(items), Last);
    } catch (py::error_already_set& e) {
        e.restore();
        return nullptr;
    } catch (py::builtin_exception& e) {
        e.set_error();
        return nullptr;
    } catch (std::exception& e) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
        return nullptr;
    }
    Py_RETURN_NONE;
}

}  // namespace

// The functions and classes L-Py's generated code and model files call: a module built into the
// program's embedded interpreter, or made by lpy/interpreter's start() inside a Python process (the `sprout`
// Python module, compiled with SPROUT_LPY_IN_EXTENSION: that interpreter is already running).
#ifndef SPROUT_LPY_IN_EXTENSION
PYBIND11_EMBEDDED_MODULE(_sprout_lpy, m) { sprout::lpy::defineSproutLpy(m); }
#endif
void sprout::lpy::defineSproutLpy(py::module_& m) {
    // produce and nproduce run once a match: plain CPython functions, without pybind11's
    // dispatch (a third of a produce-only rule's cost).
    static PyMethodDef produceDefs[] = {{"__lpy_produce", rawProduce<true>, METH_O, nullptr},
                                        {"__lpy_nproduce", rawProduce<false>, METH_O, nullptr}};
    for (PyMethodDef& def : produceDefs) m.attr(def.ml_name) = py::reinterpret_steal<py::object>(PyCFunction_New(&def, nullptr));
    m.def("_nsproduce", [](py::handle items) { engine().produce(items, false); });
    // (PglTurtle's method, its module) of the turtle's vocabulary: lpy.py's interpretation turtle.
    m.def("_turtle_methods", [] {
        std::vector<std::pair<std::string, std::string>> out;
        for (const TurtleWord& w : kTurtleVocabulary)
            if (w.method) out.emplace_back(w.method, w.names[0]);
        return out;
    });
    // A model file's bytes as L-Py's Python decodes them (translate.hpp): Lsystem(file).
    m.def("_model_text", [](const py::bytes& data) { return modelTextAsUtf8(std::string(data)); });
    // The running engine's control state, which openalea.lpy's LsysContext reads and sets while
    // the engine runs its model (lpy/api/lpy.py; outside a run a context keeps its own):
    // _control(name) gives a value, _control(name, value) sets it; None when no model runs.
    m.def("_control", [](const std::string& name, py::object value) -> py::object {
        Engine* e = currentEngine();
        if (!e) return py::none();
        const bool set = !value.is_none();
        if (name == "forward") {
            if (set) e->forwardDirection = value.cast<bool>();
            return py::bool_(e->forwardDirection);
        }
        if (name == "group") {
            if (set) e->group = std::max(0, value.cast<int>());
            return py::int_(e->group);
        }
        if (name == "frame") {
            if (set) e->frameDisplayed = value.cast<bool>();
            return py::bool_(e->frameDisplayed);
        }
        if (name == "selectionAlways") {
            if (set) e->selectionAlways = value.cast<bool>();
            return py::bool_(e->selectionAlways);
        }
        if (name == "selectionRequested") {
            if (set) e->selectionRequested = value.cast<bool>();
            return py::bool_(e->selectionRequested);
        }
        if (name == "stop") {
            if (set) e->stopRequested = value.cast<bool>();
            return py::bool_(e->stopRequested);
        }
        if (name == "iteration") return py::int_(e->iteration);
        if (name == "animating") return py::bool_(e->animating);
        throw py::key_error(name);
    }, py::arg("name"), py::arg("value") = py::none());
    // The getters a model's rules call at each match: the running engine's value at once,
    // otherwise the current context's (openalea.lpy's functions of the same names).
    auto getter = [&m](const char* name, py::object (*ofEngine)(Engine&)) {
        m.def(name, [name, ofEngine]() -> py::object {
            if (Engine* e = currentEngine()) return ofEngine(*e);
            return py::module_::import("openalea.lpy._context").attr("_current").attr(name)();
        });
    };
    getter("getIterationNb", [](Engine& e) -> py::object { return py::int_(e.iteration); });
    getter("getGroup", [](Engine& e) -> py::object { return py::int_(e.group); });
    getter("isForward", [](Engine& e) -> py::object { return py::bool_(e.forwardDirection); });
    getter("isFrameDisplayed", [](Engine& e) -> py::object { return py::bool_(e.frameDisplayed); });
    getter("isAnimationEnabled", [](Engine& e) -> py::object { return py::bool_(e.animating); });
    getter("isSelectionAlwaysRequired", [](Engine& e) -> py::object { return py::bool_(e.selectionAlways); });
    // InLeftContext / InRightContext in a rule's body (lpy/translate/contexts.cpp).
    m.def("__lpy_in_context", [](size_t index, bool left, py::handle dict) { return engine().inContext(index, left, dict); });
    // inLeftContext('A(x)', d) with a pattern made at run time (lpy/api/lpy.py).
    m.def("_in_context_text", [](const std::string& text, bool left, py::handle dict) { return engine().inContextText(text, left, dict); });
    // `produce A(**p)`: p's values in the order of A's declared parameters.
    m.def("__lpy_kwargs", [](int cls, py::dict values) {
        const ModuleClasses& classes = engine().translation().classes;
        const auto& names = classes.parameterNames[size_t(cls)];
        py::list out;
        for (const std::string& n : names) {
            if (!values.contains(n)) break;  // the declared parameters given, from the first
            out.append(values[py::str(n)]);
        }
        if (py::len(out) != py::len(values)) {
            std::string declared;
            for (const std::string& n : names) declared += (declared.empty() ? "" : ", ") + n;
            throw py::type_error("produce " + classes.name(cls) + "(**...): its keys must be the first of its declared parameters (" +
                                 declared + "), each once");
        }
        return out;
    });

    // A scene's picture and model: the maker the `sprout` module set (setScenePlant), or None.
    m.def("_scene_plant", [] { return scenePlant() ? *scenePlant() : py::object(py::none()); });

    defineTypes(m);
    defineSession(m);
}

void sprout::lpy::setScenePlant(py::object maker) {
    if (!scenePlant()) scenePlant() = new py::object();  // with the interpreter: never destroyed
    *scenePlant() = std::move(maker);
}

