// The embedded interpreter (lpy/README.md): started once, the Python modules Sprout installs,
// the process's module names, Python errors as diagnostics, %pastefile's files.
#include "lpy/interpreter/interpreter.hpp"

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

#include "lpy/translate/python2_hints.hpp"
#include "core/base/embedded_file.hpp"
#include "core/base/read_file.hpp"

namespace sprout {
std::span<const EmbeddedFile> embeddedLpyPython();
std::span<const EmbeddedFile> precompiledLpyPython();  // cmake/marshal_python.py
std::string_view precompiledLpyTag();
}

namespace py = pybind11;
using namespace sprout::lpy;

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

namespace {
// The control of a derivation (direction, group of rules, selection, frame display, iteration)
// is the current context's (openalea.lpy's LsysContext, lpy/api/lpy_context.py) and the engine's
// while the engine runs that context's model (the context's namespace is the engine's): the
// engine takes it when it starts to run, the context gets it back when the engine stops.
void shareControl(Engine* e, bool starting) {
    if (!e) return;
    try {
        py::dict state = py::module_::import("openalea.lpy").attr("_state");
        if (!state.contains("control") || !state.contains("ns") || !py::object(state["ns"]).is(e->ns())) return;
        py::dict c = state["control"];
        if (starting) {
            e->forwardDirection = c["forward"].cast<bool>();
            e->group = c["group"].cast<int>();
            e->selectionAlways = c["selectionAlways"].cast<bool>();
            e->selectionRequested = c["selectionRequested"].cast<bool>();
            return;
        }
        c["forward"] = e->forwardDirection;
        c["group"] = e->group;
        c["selectionAlways"] = e->selectionAlways;
        c["selectionRequested"] = e->selectionRequested;
        c["frame"] = e->frameDisplayed;
        c["iteration"] = e->iteration;
        c["animating"] = e->animating;
    } catch (py::error_already_set& err) {
        err.discard_as_unraisable("sharing the control of a derivation with its context");
    } catch (std::exception&) {
    }
}
}  // namespace

EngineScope::EngineScope(Engine* e) : m_engine(e), m_before(currentEngine()) {
    // The names the engine before made go to the table first, and this engine catches up.
    if (m_before) registry().adopt(m_before->classes(), false);
    if (m_engine) m_engine->classes().adopt(registry(), true);
    if (m_engine != m_before) shareControl(m_engine, true);
    setCurrentEngine(m_engine);
}

EngineScope::~EngineScope() {
    if (m_engine) registry().adopt(m_engine->classes(), false);
    if (m_before) m_before->classes().adopt(registry(), true);
    if (m_engine != m_before) shareControl(m_engine, false);
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

void start(void (*defineModule)(py::module_&)) {
    std::call_once(g_started, [defineModule] {
#ifdef SPROUT_LPY_IN_EXTENSION
        py::gil_scoped_acquire gil;
        static py::module_::module_def def;
        py::module_ native = py::module_::create_extension_module("_sprout_lpy", nullptr, &def);
        defineModule(native);
        py::module_::import("sys").attr("modules")["_sprout_lpy"] = native;
#else
        py::initialize_interpreter(false);
#endif
        {
            installModule("openalea", "", "<sprout>/openalea/__init__.py");
            // openalea.lpy's parts that need no L-system (version, options, extern), ParameterSet
            // and LsysContext (lpy/api/lpy_base.py, lpy_parameterset.py, lpy_context.py): the
            // package imports them.
            for (const auto& [name, stem] : {std::pair<const char*, const char*>{"_base", "lpy_base"},
                                             {"parameterset", "lpy_parameterset"}, {"_context", "lpy_context"}})
                installModule(std::string("openalea.lpy.") + name, embedded(stem), std::string("<sprout>/openalea/lpy/") + name + ".py");
            installModule("openalea.lpy", embedded("lpy"), "<sprout>/openalea/lpy/__init__.py");
            // Modules of L-Py's package a model may import, imported on demand: its experimental
            // string controls and its parameter sets (lpy/api/lpy_*.py).
            const std::pair<const char*, const char*> onDemand[] = {
                {"__lpyfuture__", "lpy_future"}, {"tableparameterset", "lpy_tableparameterset"}, {"lsysparameters", "lpy_lsysparameters"}};
            for (const auto& [name, stem] : onDemand)
                py::module_::import("openalea.lpy")
                    .attr("_embed")(std::string("openalea.lpy.") + name, std::string(embedded(stem)),
                                    std::string("<sprout>/openalea/lpy/") + name + ".py");
            installModule("openalea.plantgl", "", "<sprout>/openalea/plantgl/__init__.py");
            // PlantGL's parts (lpy/plantgl/plantgl_*.py), private modules that `all` gathers;
            // each imports from those before it.
            for (const char* part : {"vectors", "object", "arrays", "scene", "curves", "patches", "grids", "light"})
                installModule(std::string("openalea.plantgl._") + part, embedded(std::string("plantgl_") + part),
                              std::string("<sprout>/openalea/plantgl/_") + part + ".py");
            // PlantGL's cardinal splines (lpy/plantgl/plantgl_cspline.py), which `all` keeps as
            // `cspline` and NurbsCurve.CSpline, as PlantGL's scenegraph package does.
            installModule("openalea.plantgl.scenegraph.cspline", embedded("plantgl_cspline"),
                          "<sprout>/openalea/plantgl/scenegraph/cspline.py");
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
            // PlantGL's text scene files (lpy/plantgl/plantgl_geomfile.py): imported when a scene
            // is saved to or read from one.
            lpyEmbed.attr("_embed")("openalea.plantgl._geomfile", std::string(embedded("plantgl_geomfile")),
                                    "<sprout>/openalea/plantgl/_geomfile.py");
            // openalea.mtg (lpy/mtg/): imported on demand, a real openalea.mtg first where the
            // Python running Sprout has one (lpy/api/lpy.py's _Embedded).
            lpyEmbed.attr("_embed")("openalea.mtg", std::string(embedded("mtg_package")), "<sprout>/openalea/mtg/__init__.py");
            const std::pair<const char*, const char*> mtgParts[] = {{"mtg", "mtg_mtg"}, {"tree", "mtg_tree"},
                {"traversal", "mtg_traversal"}, {"algo", "mtg_algo"}, {"io", "mtg_io"}, {"_read", "mtg_read"}, {"_write", "mtg_write"}, {"aml", "mtg_aml"},
                {"dataframe", "mtg_dataframe"}};
            for (const auto& [name, stem] : mtgParts)
                lpyEmbed.attr("_embed")(std::string("openalea.mtg.") + name, std::string(embedded(stem)),
                                        std::string("<sprout>/openalea/mtg/") + name + ".py");
            // L-Py's Lsystem for scripts (lpy/api/lpy_lsystem.py, its scenes lpy_scene.py, its rules lpy_rules.py), part of openalea.lpy.
            installModule("openalea.lpy._scene", embedded("lpy_scene"), "<sprout>/openalea/lpy/_scene.py");
            installModule("openalea.lpy._lsystem", embedded("lpy_lsystem"), "<sprout>/openalea/lpy/_lsystem.py");
            // Its strings' and modules' names and its patterns (lpy/api/lpy_strings.py,
            // lpy_patterns.py), which _matching uses.
            installModule("openalea.lpy._strings", embedded("lpy_strings"), "<sprout>/openalea/lpy/_strings.py");
            installModule("openalea.lpy._patterns", embedded("lpy_patterns"), "<sprout>/openalea/lpy/_patterns.py");
            installModule("openalea.lpy._matching", embedded("lpy_matching"), "<sprout>/openalea/lpy/_matching.py");
            installModule("openalea.lpy._rules", embedded("lpy_rules"), "<sprout>/openalea/lpy/_rules.py");
            for (const char* part : {"openalea.lpy._lsystem", "openalea.lpy._strings", "openalea.lpy._patterns", "openalea.lpy._matching", "openalea.lpy._rules"}) {
                py::module_ lpy = py::module_::import("openalea.lpy"), api = py::module_::import(part);
                for (py::handle name : api.attr("__all__")) lpy.attr(name) = api.attr(name);
            }
            py::module_ sys = py::module_::import("sys");
            // PlantGL's light package and its modules (lpy/plantgl/plantgl_light.py, in `all`).
            for (const char* alias : {"openalea.plantgl.math", "openalea.plantgl.scenegraph", "openalea.plantgl.light",
                                      "openalea.plantgl.light.light", "openalea.plantgl.light.sky", "openalea.plantgl.light.sun",
                                      "openalea.plantgl.light.utils"})
                sys.attr("modules")[alias] = sys.attr("modules")["openalea.plantgl.all"];
            py::module_ openalea = py::module_::import("openalea");
            openalea.attr("lpy") = sys.attr("modules")["openalea.lpy"];
            openalea.attr("plantgl") = sys.attr("modules")["openalea.plantgl"];
            sys.attr("modules")["openalea.plantgl"].attr("all") = sys.attr("modules")["openalea.plantgl.all"];
        }
#ifndef SPROUT_LPY_IN_EXTENSION
        // A model's Python cannot end Sprout: in Sprout's own process (not a user's Python, where
        // the `sprout` Python module runs), the calls that would end it raise instead, an error at the
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

// A line of Python 2 is said to be one (lpy/translate/python2_hints.hpp), not left as a bare SyntaxError.
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
            if (std::optional<std::string> text = readFile(p)) return text;
        }
        return std::nullopt;
    };
}


}  // namespace sprout::lpy
