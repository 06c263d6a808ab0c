#include "lpy/host.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "lpy/host_impl.hpp"
#include "lpy/python2.hpp"
#include "core/base/embedded_file.hpp"
#include "core/derive/draw.hpp"

namespace sprout {
std::span<const EmbeddedFile> embeddedLpyPython();
std::span<const EmbeddedFile> precompiledLpyPython();  // cmake/marshal_python.py
std::string_view precompiledLpyTag();
}

namespace py = pybind11;
using namespace sprout::lpy;

namespace {

Engine& engine() {
    Engine* e = currentEngine();
    if (!e) throw py::value_error("no L-Py model is running");
    return *e;
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
// program's embedded interpreter, or made by start() inside a Python process (the `sprout`
// Python module, compiled with SPROUT_LPY_IN_EXTENSION: that interpreter is already running).
static void defineSproutLpy(py::module_& m);
#ifndef SPROUT_LPY_IN_EXTENSION
PYBIND11_EMBEDDED_MODULE(_sprout_lpy, m) { defineSproutLpy(m); }
#endif
static void defineSproutLpy(py::module_& m) {
    // produce and nproduce run once a match: plain CPython functions, without pybind11's
    // dispatch (a third of a produce-only rule's cost).
    static PyMethodDef produceDefs[] = {{"__lpy_produce", rawProduce<true>, METH_O, nullptr},
                                        {"__lpy_nproduce", rawProduce<false>, METH_O, nullptr}};
    for (PyMethodDef& def : produceDefs) m.attr(def.ml_name) = py::reinterpret_steal<py::object>(PyCFunction_New(&def, nullptr));
    m.def("nsproduce", [](py::handle items) { engine().produce(items, false); });
    m.def("Stop", [] { engine().stopRequested = true; });
    m.def("forward", [] { engine().forwardDirection = true; });
    m.def("backward", [] { engine().forwardDirection = false; });
    m.def("isForward", [] { return engine().forwardDirection; });
    m.def("useGroup", [](int g) { engine().group = std::max(0, g); });
    m.def("getGroup", [] { return engine().group; });
    m.def("getIterationNb", [] { return engine().iteration; });
    m.def("setSelectionAlwaysRequired", [](bool on) { engine().selectionAlways = on; }, py::arg("enabled") = true);
    m.def("isSelectionAlwaysRequired", [] { return currentEngine() && currentEngine()->selectionAlways; });
    m.def("requestSelection", [](py::object) { engine().selectionRequested = true; }, py::arg("message") = py::none());
    m.def("isAnimationEnabled", [] { return currentEngine() && currentEngine()->animating; });
    m.def("isFrameDisplayed", [] { return currentEngine() && currentEngine()->frameDisplayed; });
    // InLeftContext / InRightContext in a rule's body (lpy/translate_contexts.cpp).
    m.def("__lpy_in_context", [](size_t index, bool left, py::handle dict) { return engine().inContext(index, left, dict); });
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

    defineTypes(m);
    defineSession(m);
}

namespace sprout::lpy {
namespace {

std::once_flag g_started;
std::mutex g_run;  // one model runs at a time (the interpreter is shared)

void installModule(const std::string& name, std::string_view source, const std::string& file) {
    py::module_ types = py::module_::import("types");
    py::module_ sys = py::module_::import("sys");
    py::object mod = types.attr("ModuleType")(name);
    mod.attr("__file__") = file;
    if (name.find('.') == std::string::npos || name == "openalea.plantgl" || name == "openalea.lpy") mod.attr("__path__") = py::list();
    sys.attr("modules")[py::str(name)] = mod;
    py::module_ builtins = py::module_::import("builtins");
    // Compiled at build time, when this is the interpreter that compiled it (the same cache
    // tag): a start compiles none of the modules it installs.
    static const bool same = py::str(sys.attr("implementation").attr("cache_tag")).cast<std::string>() == precompiledLpyTag();
    py::object code;
    for (const auto& f : precompiledLpyPython())
        if (same && f.stem == file) code = py::module_::import("marshal").attr("loads")(py::bytes(f.data.data(), f.data.size()));
    if (!code) code = builtins.attr("compile")(std::string(source), file, "exec");
    builtins.attr("exec")(code, mod.attr("__dict__"));
}

std::string_view embedded(std::string_view stem) {
    for (const auto& f : embeddedLpyPython())
        if (f.stem == stem) return f.data;
    return {};
}

}  // namespace

std::mutex& runMutex() { return g_run; }

ModuleClasses& registry() {
    static ModuleClasses* table = new ModuleClasses();  // with the interpreter: never destroyed
    return *table;
}

ModuleClasses& names() {
    Engine* e = currentEngine();
    return e ? e->classes() : registry();
}

py::dict looseNamespace() {
    static py::dict* ns = nullptr;  // with the interpreter: never destroyed
    if (!ns) {
        ns = new py::dict();
        (*ns)["__builtins__"] = py::module_::import("builtins");
        py::exec("from openalea.lpy import *\nfrom openalea.plantgl.all import *\n", *ns);
    }
    return *ns;
}

EngineScope::EngineScope(Engine* e) : m_engine(e), m_before(currentEngine()) {
    // The names the engine before made go to the table first, and this engine catches up.
    if (m_before) registry().adopt(m_before->classes(), false);
    if (m_engine) m_engine->classes().adopt(registry(), true);
    setCurrentEngine(m_engine);
}

EngineScope::~EngineScope() {
    if (m_engine) registry().adopt(m_engine->classes(), false);
    if (m_before) m_before->classes().adopt(registry(), true);
    setCurrentEngine(m_before);
}

void prepareNamespace(py::dict ns, const std::string& path) {
    py::module_ native = py::module_::import("_sprout_lpy");
    py::exec("from openalea.lpy import *\nfrom openalea.plantgl.all import *\n", ns);
    for (const char* name : {"__lpy_produce", "__lpy_nproduce", "__lpy_module_class", "__lpy_in_context", "__lpy_kwargs"})
        ns[name] = native.attr(name);
    if (!path.empty()) {
        // Imports beside the file (a model's own grid.py), as `python3 FILE` finds them.
        py::module_ sys = py::module_::import("sys");
        py::module_ os = py::module_::import("os");
        py::object folder = os.attr("path").attr("dirname")(os.attr("path").attr("abspath")(path));
        if (!sys.attr("path").contains(folder)) sys.attr("path").attr("insert")(0, folder);
    }
}

void start() {
    std::call_once(g_started, [] {
#ifdef SPROUT_LPY_IN_EXTENSION
        py::gil_scoped_acquire gil;
        static py::module_::module_def def;
        py::module_ native = py::module_::create_extension_module("_sprout_lpy", nullptr, &def);
        defineSproutLpy(native);
        py::module_::import("sys").attr("modules")["_sprout_lpy"] = native;
#else
        py::initialize_interpreter(false);
#endif
        {
            installModule("openalea", "", "<sprout>/openalea/__init__.py");
            installModule("openalea.lpy", embedded("lpy"), "<sprout>/openalea/lpy/__init__.py");
            // Modules of L-Py's package a model may import, imported on demand: its experimental
            // string controls and its parameter sets (lpy/python/lpy_*.py).
            const std::pair<const char*, const char*> onDemand[] = {
                {"__lpyfuture__", "lpy_future"}, {"tableparameterset", "lpy_tableparameterset"}, {"parameterset", "lpy_parameterset"},
                {"lsysparameters", "lpy_lsysparameters"}};
            for (const auto& [name, stem] : onDemand)
                py::module_::import("openalea.lpy")
                    .attr("_embed")(std::string("openalea.lpy.") + name, std::string(embedded(stem)),
                                    std::string("<sprout>/openalea/lpy/") + name + ".py");
            installModule("openalea.plantgl", "", "<sprout>/openalea/plantgl/__init__.py");
            // PlantGL's parts (lpy/python/plantgl_*.py), private modules that `all` gathers;
            // each imports from those before it.
            for (const char* part : {"vectors", "scene", "curves", "grids", "drawing"})
                installModule(std::string("openalea.plantgl._") + part, embedded(std::string("plantgl_") + part),
                              std::string("<sprout>/openalea/plantgl/_") + part + ".py");
            installModule("openalea.plantgl.all", embedded("plantgl"), "<sprout>/openalea/plantgl/all.py");
            // PlantGL's scenegraph package: the same names as all, and two modules of its own
            // that models import by name.
            py::module_::import("openalea.plantgl.all").attr("__path__") = py::list();
            py::module_ lpyEmbed = py::module_::import("openalea.lpy");
            lpyEmbed.attr("_embed")("openalea.plantgl.scenegraph.interpolated_profile", std::string(embedded("plantgl_profile")),
                                    "<sprout>/openalea/plantgl/scenegraph/interpolated_profile.py");
            lpyEmbed.attr("_embed")("openalea.plantgl.scenegraph.nurbspatch_nd",
                                    "from openalea.plantgl.all import NurbsPatch3D, Vector3, Vector4\n",
                                    "<sprout>/openalea/plantgl/scenegraph/nurbspatch_nd.py");
            // L-Py's Lsystem for scripts (lpy/python/lpy_lsystem.py), part of openalea.lpy.
            installModule("openalea.lpy._lsystem", embedded("lpy_lsystem"), "<sprout>/openalea/lpy/_lsystem.py");
            installModule("openalea.lpy._matching", embedded("lpy_matching"), "<sprout>/openalea/lpy/_matching.py");
            for (const char* part : {"openalea.lpy._lsystem", "openalea.lpy._matching"}) {
                py::module_ lpy = py::module_::import("openalea.lpy"), api = py::module_::import(part);
                for (py::handle name : api.attr("__all__")) lpy.attr(name) = api.attr(name);
            }
            py::module_ sys = py::module_::import("sys");
            for (const char* alias : {"openalea.plantgl.math", "openalea.plantgl.scenegraph", "openalea.plantgl.light",
                                      "openalea.plantgl.light.light"})
                sys.attr("modules")[alias] = sys.attr("modules")["openalea.plantgl.all"];
            py::module_ openalea = py::module_::import("openalea");
            openalea.attr("lpy") = sys.attr("modules")["openalea.lpy"];
            openalea.attr("plantgl") = sys.attr("modules")["openalea.plantgl"];
            sys.attr("modules")["openalea.plantgl"].attr("all") = sys.attr("modules")["openalea.plantgl.all"];
        }
#ifndef SPROUT_LPY_IN_EXTENSION
        // A model's Python cannot end Sprout: in Sprout's own process (not a user's Python, where
        // `import sprout` runs), the calls that would end it raise instead, an error at the
        // model's line (sys.exit's SystemExit is turned into the same error where it is caught).
        py::exec(R"PY(
import os, posix, signal
class ModelExit(BaseException):
    """A model tried to end Sprout's process."""
def _refuse(name, real, own=None):
    def guarded(*args, **kwargs):
        if own is None or own(*args):
            raise ModelExit("a model cannot end Sprout (%s)" % name)
        return real(*args, **kwargs)
    guarded.__name__ = getattr(real, "__name__", name)
    return guarded
def _own_pid(pid, *rest):
    return pid in (0, -1, os.getpid(), -os.getpgrp())
os._exit = posix._exit = _refuse("os._exit", os._exit)
os.abort = posix.abort = _refuse("os.abort", os.abort)
os.kill = posix.kill = _refuse("os.kill", os.kill, _own_pid)
os.killpg = posix.killpg = _refuse("os.killpg", os.killpg, lambda group, *rest: group in (0, os.getpgrp()))
signal.raise_signal = _refuse("signal.raise_signal", signal.raise_signal)
signal.pthread_kill = _refuse("signal.pthread_kill", signal.pthread_kill)
)PY", py::dict());
        PyEval_SaveThread();  // the GIL is taken by whichever thread runs a model
#endif
    });
}

namespace {

// A column Python counted on the translated line (a `-->` rule became a longer function on
// its line) that lies past the end of the line as written: the successor's first column.
void fitColumn(Diagnostic& d, std::string_view text) {
    if (d.line <= 0 || d.col <= 0) return;
    size_t start = 0;
    for (int n = 1; n < d.line && start != std::string_view::npos; ++n) {
        start = text.find('\n', start);
        if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos) return;
    std::string_view line = text.substr(start, text.find('\n', start) - start);
    if (size_t(d.col) <= line.size()) return;
    const size_t arrow = line.find("-->");
    size_t at = arrow == std::string_view::npos ? 0 : arrow + 3;
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    d.col = int(std::min(at, line.size())) + 1;
}

// A line of Python 2 is said to be one (lpy/python2.hpp), not left as a bare SyntaxError.
Diagnostic python2(Diagnostic d, std::string_view text) {
    if (d.line > 0)
        if (auto said = python2Message(d.message, lineOf(text, d.line))) d.message = *said;
    return d;
}

}  // namespace

Diagnostic describe(py::error_already_set& e, const std::string& file, std::string_view text) {
    Diagnostic d;
    const std::string type = py::str(e.type().attr("__name__"));
    d.message = type + ": " + std::string(py::str(e.value()));
    if (type == "ModelExit") d.message = py::str(e.value());  // os._exit and the like (start())
    else if (e.matches(PyExc_SystemExit)) d.message = "a model cannot end Sprout (sys.exit)";
    if (e.matches(PyExc_SyntaxError)) {
        py::object v = e.value();
        if (py::hasattr(v, "lineno") && !v.attr("lineno").is_none()) d.line = v.attr("lineno").cast<int>();
        if (py::hasattr(v, "offset") && !v.attr("offset").is_none()) d.col = v.attr("offset").cast<int>();
        if (py::hasattr(v, "msg")) d.message = "SyntaxError: " + std::string(py::str(v.attr("msg")));
        fitColumn(d, text);
        return python2(d, text);
    }
    if (!e.trace()) return d;
    py::object frames = py::module_::import("traceback").attr("extract_tb")(e.trace());
    for (py::handle f : frames) {
        if (std::string(py::str(f.attr("filename"))) != file) continue;
        d.line = f.attr("lineno").cast<int>();
        if (py::hasattr(f, "colno") && !f.attr("colno").is_none()) d.col = f.attr("colno").cast<int>() + 1;
    }
    fitColumn(d, text);
    return python2(d, text);
}

namespace {

std::uint32_t materialColour(py::handle m) {
    try {
        py::object c = m.attr("diffuseColor")();
        const double t = m.attr("transparency").cast<double>();
        auto ch = [](double x) { return std::uint32_t(std::clamp(x, 0.0, 255.0)); };
        return ch(c[py::int_(0)].cast<double>()) << 24 | ch(c[py::int_(1)].cast<double>()) << 16 |
               ch(c[py::int_(2)].cast<double>()) << 8 | ch(std::round((1 - t) * 255));
    } catch (py::error_already_set&) {
        return 0x808080FF;
    }
}

}  // namespace

TurtleDefaults turtleDefaults(const py::module_& lpyModule) {
    TurtleDefaults d;
    py::dict state = lpyModule.attr("_state");
    if (!state["angle"].is_none()) d.angle = state["angle"].cast<double>();
    d.materials = defaultMaterials();
    for (auto item : py::dict(state["materials"])) {
        const int i = item.first.cast<int>();
        if (i < 0 || i > 255) continue;
        if (size_t(i) >= d.materials.size()) d.materials.resize(size_t(i) + 1, 0xA0A0A0FF);
        d.materials[size_t(i)] = materialColour(item.second);
    }
    return d;
}

// L-Py's query pre-pass (src/cpp/lsystem.cpp `__step`, module.cpp `_setValues`): the string
// with its interpretation rules drawn by a turtle that keeps no picture, and each query
// module given the turtle's state where it stands, in L-Py's axes (Sprout's y is L-Py's z).
// The k-th query module of the interpreted string is the k-th of the string.
namespace {
void fillQueriesOnce(Engine& engine, LString& s, const TurtleDefaults& d);
}  // namespace

void fillQueries(Engine& engine, LString& s, const TurtleDefaults& d) {
    // L-Py's turtle fills each query module as it passes it, and the interpretation rules after
    // it see its value. Sprout interprets first, then walks: where a query module had no value
    // yet and an interpretation rule reads one, the walk is made again with the values filled.
    bool bare = false;
    for (const LModule& m : s)
        if (Engine::isQuery(engine.translation().classes.name(m.cls)) && (!m.args || PyTuple_GET_SIZE(m.args.ptr()) == 0)) bare = true;
    fillQueriesOnce(engine, s, d);
    if (bare && engine.interpretationReadsQueries) fillQueriesOnce(engine, s, d);
}

namespace {
void fillQueriesOnce(Engine& engine, LString& s, const TurtleDefaults& d) {
    const ModuleClasses& classes = engine.translation().classes;
    // The string drawn, each module knowing its module in `s` (an interpretation rule's
    // modules come from the module it rewrote): the turtle's k-th query frame is the k-th query
    // module drawn, which is written back where that module is one of `s` copied as it is. A
    // query module an interpretation rule rewrites is not passed by L-Py's turtle: it keeps its values.
    const LString shown = engine.interpret(s);  // (Engine::interpret sets parent and rule so)
    auto g = drawable(shown, classes, d, nullptr, true);
    Geometry geo;
    TurtleOptions t;
    t.fromTree = false;
    t.meshes = false;  // only the frames are read
    std::vector<QueryFrame> frames;
    t.queries = &frames;
    interpret(g->axiom, *g, t, geo);
    py::object vector3 = py::module_::import("openalea.plantgl.all").attr("Vector3");
    auto lpyVector = [&](const glm::vec3& v) { return vector3(double(v.z), double(v.x), double(v.y)); };
    size_t k = 0;
    for (const LModule& drawn : shown) {
        if (!Engine::isQuery(classes.name(drawn.cls))) continue;
        if (k >= frames.size()) break;
        const QueryFrame& f = frames[k++];
        if (drawn.rule != -1 || drawn.parent >= s.size() || s[drawn.parent].cls != drawn.cls) continue;
        LModule& m = s[drawn.parent];
        const std::string& name = classes.name(m.cls);
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        if (name[1] == 'F') {
            m.args = py::make_tuple(lpyVector(f.position), lpyVector(f.heading), lpyVector(f.up), lpyVector(f.left));
            continue;
        }
        const glm::vec3 v = name[1] == 'P' ? f.position : name[1] == 'H' ? f.heading : name[1] == 'U' ? f.up : name[1] == 'L' ? f.left : -f.left;
        // As L-Py's ParamModule::_setValues: three values or more, the first three are x, y, z;
        // two, x and y; one number, x; one other value (a Vector3, a list), its first items
        // set in place; none, a Vector3.
        const double xyz[3] = {double(v.z), double(v.x), double(v.y)};
        if (n >= 2) {
            py::list args(m.args);
            for (Py_ssize_t k = 0; k < std::min<Py_ssize_t>(n, 3); ++k) args[size_t(k)] = py::float_(xyz[k]);
            m.args = py::tuple(args);
        } else if (n == 1) {
            py::object arg = py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(m.args.ptr(), 0));
            if (PyFloat_Check(arg.ptr()) || PyLong_Check(arg.ptr())) {
                m.args = py::make_tuple(xyz[0]);
            } else {
                const Py_ssize_t size = PyObject_Length(arg.ptr());
                if (size < 0) throw py::error_already_set();
                for (Py_ssize_t k = 0; k < std::min<Py_ssize_t>(size, 3); ++k) arg.attr("__setitem__")(k, xyz[k]);
            }
        } else {
            m.args = py::make_tuple(lpyVector(v));
        }
    }
}
}  // namespace


bool pythonAvailable() { return true; }

void installOpenalea() { start(); }

PasteReader pasteReader(const std::string& modelPath) {
    namespace fs = std::filesystem;
    const fs::path folder = modelPath.empty() ? fs::path() : fs::absolute(fs::path(modelPath)).parent_path();
    return [folder](const std::string& name, bool module) -> std::optional<std::string> {
        std::string relative = name;
        if (module) {
            std::replace(relative.begin(), relative.end(), '.', '/');
            relative += ".lpy";
        }
        std::vector<fs::path> places;
        if (!folder.empty()) places.push_back(folder / relative);
        places.push_back(fs::path(relative));
        if (module)
            if (const char* env = std::getenv("PYTHONPATH"))
                for (std::string_view rest(env); !rest.empty();) {
                    const size_t colon = rest.find(':');
                    places.push_back(fs::path(std::string(rest.substr(0, colon))) / relative);
                    rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
                }
        for (const fs::path& p : places) {
            std::error_code ec;
            if (!fs::is_regular_file(p, ec)) continue;
            std::ifstream in(p, std::ios::binary);
            std::ostringstream text;
            text << in.rdbuf();
            if (in) return text.str();
        }
        return std::nullopt;
    };
}


}  // namespace sprout::lpy
