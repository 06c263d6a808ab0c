// An L-system kept between calls: what openalea.lpy's Lsystem (lpy/api/lpy_lsystem.py)
// drives from a script or a notebook, as L-Py's Lsystem does (src/cpp/lsystem.cpp): the code
// read once (translated, its INITIALISATION part, the parameters given, then the rest), then
// derive, interpret and axiom as often as the caller asks, the engine and its namespace
// living as long as the Python object. The engine is Sprout's, native path included.
#include <pybind11/stl.h>

#include "core/derive/draw.hpp"
#include "core/language/module_string.hpp"
#include "lpy/api/api.hpp"
#include "lpy/draw/draw.hpp"
#include "lpy/interpreter/interpreter.hpp"
#include "lpy/translate/python2_hints.hpp"

namespace py = pybind11;

namespace sprout::lpy {
namespace {

// Python's cycle collector paused while a string of many tuples is made (lpy/interpreter/interpreter.cpp).
struct PausedCollector {
    int was = PyGC_Disable();
    ~PausedCollector() {
        if (was) PyGC_Enable();
    }
};

[[noreturn]] void raiseSyntaxError(const Diagnostic& d, const std::string& file, std::string_view code) {
    const std::string line(lineOf(code, d.line));
    py::object args = py::make_tuple(d.message, py::make_tuple(file, d.line, d.col, line));
    PyErr_SetObject(PyExc_SyntaxError, args.ptr());
    throw py::error_already_set();
}

}  // namespace

py::object sceneOf(Engine& engine, const LString& s) {
    TurtleDefaults d = turtleDefaults(py::module_::import("openalea.lpy"));
    const LString shown = engine.interpret(s);
    std::vector<std::uint32_t> from, segments, surfaces;
    auto g = drawable(shown, engine.classes(), d, nullptr, false, &from);
    Geometry geo;
    TurtleOptions t;
    t.fromTree = false;
    t.segmentModules = &segments;
    t.surfaceModules = &surfaces;
    interpret(g->axiom, *g, t, geo);
    // What drew each part: its module in `s` (L-Py's shape ids).
    auto idOf = [&](std::uint32_t drawn) -> long {
        if (drawn >= from.size() || from[drawn] >= shown.size()) return -1;
        return long(shown[from[drawn]].parent);
    };
    // Sprout's frame (y up) in L-Py's (z up): L-Py's x, y, z are Sprout's z, x, y.
    auto lpyPoint = [](const glm::vec3& v) { return py::make_tuple(double(v.z), double(v.x), double(v.y)); };
    auto rgba = [](std::uint32_t c) { return py::make_tuple(c >> 24 & 255, c >> 16 & 255, c >> 8 & 255, c & 255); };
    py::list parts;
    for (size_t k = 0; k < geo.cylinders.size(); ++k) {
        const CylinderInstance& c = geo.cylinders[k];
        parts.append(py::make_tuple("cylinder", idOf(k < segments.size() ? segments[k] : ~0u), lpyPoint(c.start), lpyPoint(c.end),
                                    double(c.startRadius), double(c.endRadius), rgba(c.colour)));
    }
    for (size_t k = 0; k < geo.surfaces.size(); ++k) {
        const SurfaceInstance& f = geo.surfaces[k];
        parts.append(py::make_tuple(f.kind == SurfaceKind::Sphere ? "sphere" : "surface", idOf(k < surfaces.size() ? surfaces[k] : ~0u),
                                    lpyPoint(f.position), lpyPoint(f.heading), double(f.size), rgba(f.colour), lpyPoint(f.up)));
    }
    if (!geo.polygons.indices.empty()) {
        // Packed (x, y, z floats in L-Py's axes; the triangles' indices), made into PlantGL's
        // lists only when the model reads them: a scene is made at every step of a model whose
        // EndEach takes one, and its crowns are tens of thousands of triangles.
        std::vector<float> points;
        points.reserve(geo.polygons.positions.size() * 3);
        for (const auto& p : geo.polygons.positions) points.insert(points.end(), {p.z, p.x, p.y});
        const size_t faces = geo.polygons.indices.size() / 3 * 3;
        parts.append(py::make_tuple("mesh", -1, py::bytes(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(float)),
                                    py::bytes(reinterpret_cast<const char*>(geo.polygons.indices.data()), faces * sizeof(std::uint32_t)),
                                    rgba(geo.polygons.colours.empty() ? 0x808080FFu : geo.polygons.colours[0])));
    }
    return py::module_::import("openalea.lpy._scene").attr("_scene")(parts);
}

namespace {

class Session {
public:
    Session(const std::string& written, const std::string& file, py::dict ns, py::dict parameters) : m_file(file), m_ns(ns) {
        std::vector<Diagnostic> pasteErrors;
        const std::string code = pasteFiles(written, pasteReader(file.empty() || file[0] == '<' ? std::string() : file), pasteErrors);
        for (const Diagnostic& d : pasteErrors) raiseSyntaxError(d, file, written);
        Translation tr = translate(code, &registry());
        for (const Diagnostic& d : tr.diagnostics)
            if (d.severity == Severity::Error) raiseSyntaxError(d, file, code);
        registry().adopt(tr.classes, false);
        std::string init = tr.initCode, main = tr.mainCode;
        ns["__builtins__"] = py::module_::import("builtins");
        ns["__file__"] = file;
        if (!ns.contains("__name__")) ns["__name__"] = "__lpy__";
        prepareNamespace(ns, file.empty() || file[0] == '<' ? std::string() : file);
        // Line for line the code's (the last line's end as the code has it).
        m_python = tr.mainCode;
        if (!m_python.empty() && m_python.back() == '\n' &&
            std::count(m_python.begin(), m_python.end(), '\n') > std::count(code.begin(), code.end(), '\n'))
            m_python.pop_back();
        for (int c : tr.declared) m_declared.push_back(tr.classes.name(c));
        m_engine = std::make_unique<Engine>(std::move(tr), ns, m_options);
        m_engine->sceneOf = [this](const LString& s) { return sceneOf(*m_engine, s); };
        m_engine->fillQueries = [this](LString& s) { fillQueries(*m_engine, s, turtleDefaults(py::module_::import("openalea.lpy"))); };
        EngineScope scope(m_engine.get());
        py::module_ builtins = py::module_::import("builtins"), lpy = py::module_::import("openalea.lpy");
        builtins.attr("exec")(builtins.attr("compile")(init, file, "exec"), ns);
        if (ns.contains("__initialiseContext__")) ns["__initialiseContext__"](lpy.attr("context")());
        // The caller's parameters come after the INITIALISATION part, before the rest
        // (extern(...) keeps them; a plain assignment in the code wins).
        for (auto item : parameters) ns[item.first] = item.second;
        builtins.attr("exec")(builtins.attr("compile")(main, file, "exec"), ns);
        m_engine->bind();
    }

    PyLstring axiom() {
        EngineScope scope(m_engine.get());
        return PyLstring{std::make_shared<LString>(m_engine->axiom())};
    }

    // L-Py's derive(lstring, start, nb): Start at iteration 0, End at the last iteration.
    PyLstring derive(const PyLstring& s, int start, int nb, bool endEarlyReturn) {
        if (start < 0 || nb < 0) throw py::value_error("derive: a start and a count of steps from 0 on");
        EngineScope scope(m_engine.get());
        // The native path (no hooks, arithmetic rules): numbers to the end, made into modules
        // when Python reads them.
        if (m_engine->native() && start == 0 && nb == m_engine->derivationLength && !m_engine->selectionAlways && !m_engine->debugger) {
            auto numbers = std::make_shared<NumString>();
            if (m_engine->deriveNumbers(s.get(), nb, nullptr, *numbers, false))
                return PyLstring{std::make_shared<LString>(), std::move(numbers)};
        }
        PausedCollector paused;
        struct EarlyReturnOff {  // L-Py's derive leaves early_return off, however it ends (animate reads it)
            Engine& e;
            bool off;
            ~EarlyReturnOff() {
                if (off) e.stopRequested = false;
            }
        } off{*m_engine, endEarlyReturn};
        LString out = m_engine->derive(s.get(), nb, nullptr, nullptr, start, m_engine->derivationLength);
        return PyLstring{std::make_shared<LString>(std::move(out))};
    }

    PyLstring partial(const PyLstring& s, size_t beg, size_t size) {
        EngineScope scope(m_engine.get());
        return PyLstring{std::make_shared<LString>(m_engine->partialDerivation(s.get(), beg, size))};
    }

    // L-Py's Lsystem.turtle_interpretation: the string's query modules filled in place.
    void fillQueriesOf(const PyLstring& s) {
        EngineScope scope(m_engine.get());
        m_engine->fillQueries(s.get());
    }
    // L-Py's stepInterpretation plots as its turtle passes each predefined module of the
    // interpreted string: the module of `s` each of those comes from.
    std::vector<long> predefinedOrigins(const PyLstring& s) {
        EngineScope scope(m_engine.get());
        const LString shown = m_engine->interpret(s.get());
        std::vector<long> out;
        for (const LModule& m : shown)
            if (m_engine->classes().isPredefined(m.cls)) out.push_back(long(m.parent));
        return out;
    }

    PyLstring interpret(const PyLstring& s) {
        EngineScope scope(m_engine.get());
        return PyLstring{std::make_shared<LString>(m_engine->interpret(s.get()))};
    }

    // The scene the turtle draws (the interpretation rules applied): sceneInterpretation.
    py::object scene(const PyLstring& s) {
        EngineScope scope(m_engine.get());
        return sceneOf(*m_engine, s.get());
    }
    std::shared_ptr<const Grammar> drawing(const LString& s) {
        EngineScope scope(m_engine.get());
        TurtleDefaults d = turtleDefaults(py::module_::import("openalea.lpy"));
        return drawable(m_engine->interpret(s), m_engine->classes(), d);
    }
    // While animating: EndEach gets a scene at every step.
    void setAnimating(bool on) { m_engine->animating = on; }
    bool animating() const { return m_engine->animating; }
    py::object lastScene() const { return m_engine->lastScene ? m_engine->lastScene : py::none(); }

    void setDebugger(py::object d) { m_engine->debugger = d.is_none() ? py::object() : d; }
    py::object debugger() const { return m_engine->debugger ? m_engine->debugger : py::none(); }
    int derivationLength() const { return m_engine->derivationLength; }
    void setDerivationLength(int n) {
        if (n < 0) throw py::value_error("derivationLength: a count of steps from 0 on");
        m_engine->derivationLength = n;
    }
    int iteration() const { return m_engine->iteration; }
    // L-Py's early_return: a derivation stops after the step it is set in (Stop()).
    bool earlyReturn() const { return m_engine->stopRequested; }
    void setEarlyReturn(bool on) { m_engine->stopRequested = on; }
    int maxDepth(int kind) const { return m_engine->maxDepth(RuleKind(kind)); }
    void setMaxDepth(int kind, int depth) {
        if (depth < 0) throw py::value_error("a maximum depth from 0 on");
        m_engine->maxDepth(RuleKind(kind)) = depth;
    }
    void setRuleObject(py::object f) { m_engine->ruleObject = f.is_none() ? py::object() : f; }
    // L-Py's LsysRule.__call__: the body of rule `i` called on `args` (its production, or None).
    py::object apply(size_t i, py::tuple args) {
        EngineScope scope(m_engine.get());
        return m_engine->applyRule(i, args);
    }
    size_t rules(int kind, int group) const {
        size_t n = 0;
        for (const Rule& r : m_engine->translation().rules) n += int(r.kind) == kind && (group < 0 || r.group == group);
        return n;
    }
    std::vector<int> groups() const {
        std::vector<int> out;
        for (const Rule& r : m_engine->translation().rules)
            if (std::find(out.begin(), out.end(), r.group) == out.end()) out.push_back(r.group);
        return out;
    }

    // L-Py's LsysRule: what a rule's header holds, and whether it matches at a place.
    py::dict rule(size_t i) const {
        const auto& rules = m_engine->translation().rules;
        if (i >= rules.size()) throw py::index_error("no such rule");
        const Rule& r = rules[i];
        py::dict out;
        out["kind"] = int(r.kind);
        out["group"] = r.group;
        out["line"] = r.line;
        out["header"] = r.header;
        out["left"] = !r.left.empty();
        out["newLeft"] = !r.newLeft.empty();
        out["right"] = !r.right.empty();
        out["newRight"] = !r.newRight.empty();
        out["parameters"] = r.params.size();
        out["names"] = r.params;
        out["function"] = r.function;
        return out;
    }
    py::object match(size_t rule, const PyLstring& s, long at, bool forward) {
        EngineScope scope(m_engine.get());
        return m_engine->matchRule(rule, s.get(), at, forward);
    }
    size_t ruleCount() const { return m_engine->translation().rules.size(); }

    // The model's own module classes (not L-Py's predefined ones), as they came.
    std::vector<std::string> moduleNames() const {
        std::vector<std::string> out;
        const ModuleClasses& c = m_engine->classes();
        for (size_t i = 0; i < c.size(); ++i)
            if (!c.isPredefined(int(i)) && c.used(int(i))) out.push_back(c.name(int(i)));
        return out;
    }
    const std::string& python() const { return m_python; }  // the code as Python runs it (set(code, debug=True))
    const std::vector<std::string>& declared() const { return m_declared; }

private:
    std::string m_python;
    std::vector<std::string> m_declared;
    std::string m_file;
    py::dict m_ns;
    RunOptions m_options;  // the engine keeps a reference
    std::unique_ptr<Engine> m_engine;
};

}  // namespace

std::shared_ptr<const Grammar> drawingOf(void* session, void* lstring) {
    py::handle s(static_cast<PyObject*>(session)), l(static_cast<PyObject*>(lstring));
    if (!py::isinstance<Session>(s) || !py::isinstance<PyLstring>(l)) throw std::invalid_argument("not an Lsystem's string");
    return py::cast<Session&>(s).drawing(py::cast<PyLstring&>(l).get());
}

void defineSession(py::module_& m) {
    py::class_<Session>(m, "_Session")
        .def(py::init<const std::string&, const std::string&, py::dict, py::dict>(), py::arg("code"), py::arg("file"), py::arg("ns"),
             py::arg("parameters"))
        .def("axiom", &Session::axiom)
        .def("derive", &Session::derive, py::arg("lstring"), py::arg("start"), py::arg("nb"), py::arg("endEarlyReturn") = true)
        .def("interpret", &Session::interpret)
        .def("partial", &Session::partial)
        .def("fillQueries", &Session::fillQueriesOf)
        .def("predefinedOrigins", &Session::predefinedOrigins)
        .def("scene", &Session::scene)
        .def_property("debugger", &Session::debugger, &Session::setDebugger)
        .def_property("animating", &Session::animating, &Session::setAnimating)
        .def_property_readonly("lastScene", &Session::lastScene)
        .def_property("derivationLength", &Session::derivationLength, &Session::setDerivationLength)
        .def_property_readonly("iteration", &Session::iteration)
        .def_property("earlyReturn", &Session::earlyReturn, &Session::setEarlyReturn)
        .def("maxDepth", &Session::maxDepth)
        .def("setMaxDepth", &Session::setMaxDepth)
        .def("setRuleObject", &Session::setRuleObject)
        .def("apply", &Session::apply)
        .def("rules", &Session::rules, py::arg("kind"), py::arg("group") = -1)
        .def("groups", &Session::groups)
        .def("rule", &Session::rule)
        .def("ruleCount", &Session::ruleCount)
        .def("match", &Session::match)
        .def_property_readonly("python", &Session::python)
        .def("declared", &Session::declared)
        .def("moduleNames", &Session::moduleNames);
}

}  // namespace sprout::lpy
