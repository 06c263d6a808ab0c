// `import sprout` (issue 23): Sprout's engine for Python programs and notebooks, on pybind11
// like the L-Py host. This is the native part, `sprout._sprout`; python/sprout/__init__.py
// adds the notebook's picture and slider. It runs inside the Python process: L-Py models use
// that interpreter (lpy/ built as sprout_lpy_ext), not an embedded one.
//
// Index of this file:
//   [SECTION] Errors
//   [SECTION] LString: a derived string
//   [SECTION] Plant: a grammar and its growth
//   [SECTION] Opening and parsing
//   [SECTION] Arguments
//   [SECTION] The module
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <sstream>

#include "app/export/export.hpp"
#include "app/image.hpp"
#include "app/plant/presets.hpp"
#include "app/snapshot.hpp"
#include "app/plant/growth.hpp"
#include "app/plant/open.hpp"
#include "app/plant/source.hpp"
#include "core/derive/derive.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/grammar.hpp"
#include "core/language/import/import.hpp"
#include "core/language/module_string.hpp"
#include "lpy/lpy.hpp"

namespace py = pybind11;
using namespace sprout;

// [SECTION] Errors
namespace {

// A grammar error as Python sees it: sprout.GrammarError(message, line, col, diagnostics).
[[noreturn]] void raiseDiagnostics(const std::vector<Diagnostic>& diags, const std::string& name) {
    const Diagnostic* first = nullptr;
    py::list all;
    for (const auto& d : diags) {
        all.append(py::make_tuple(d.line, d.col, d.severity == Severity::Error ? "error" : "warning", d.message));
        if (!first && d.severity == Severity::Error) first = &d;
    }
    py::object cls = py::module_::import("sprout").attr("GrammarError");
    const std::string message = first ? formatDiagnostic(*first, name) : name + ": cannot be read";
    PyErr_SetObject(cls.ptr(), cls(message, first ? first->line : 0, first ? first->col : 0, all).ptr());
    throw py::error_already_set();
}

// [SECTION] LString: a derived string
// A string of modules, read-only and shared with the derivation (never copied): its length,
// its modules by index, its symbols and parameters as numpy arrays over the same memory.
class LString {
public:
    LString(std::shared_ptr<const ModuleString> s, std::shared_ptr<const Grammar> g) : m_s(std::move(s)), m_g(std::move(g)) {}
    size_t size() const { return m_s->size(); }
    py::tuple module(py::ssize_t i) {
        const py::ssize_t n = py::ssize_t(size());
        if (i < 0) i += n;
        if (i < 0 || i >= n) throw py::index_error("module index out of range");
        const SymbolInfo& info = m_g->alphabet[m_s->symbols.data()[i]];
        const double* p = m_s->params.data() + paramOffset(size_t(i));
        py::tuple params(info.arity);
        for (int k = 0; k < info.arity; ++k) {
            if (info.nameArgs >> k & 1 && p[k] >= 0 && p[k] < double(m_g->alphabet.strings().size()))
                params[size_t(k)] = py::str(m_g->alphabet.strings()[size_t(p[k])]);
            else
                params[size_t(k)] = py::float_(p[k]);
        }
        return py::make_tuple(info.name, params);
    }
    std::string text() const { return toString(*m_s, m_g->alphabet); }
    size_t count(const std::string& name) const {
        std::vector<bool> match(m_g->alphabet.size());
        for (size_t k = 0; k < match.size(); ++k) match[k] = m_g->alphabet[SymbolId(k)].name == name;
        size_t n = 0;
        for (size_t i = 0; i < size(); ++i) n += match[m_s->symbols.data()[i]];
        return n;
    }
    // Views of the derivation's own memory (kept alive by this object), read-only.
    py::array symbols(py::handle self) const {
        return readOnly(py::array(py::dtype::of<std::uint16_t>(), {py::ssize_t(size())}, {py::ssize_t(sizeof(SymbolId))},
                                  m_s->symbols.data(), self));
    }
    py::array params(py::handle self) const {
        return readOnly(py::array(py::dtype::of<double>(), {py::ssize_t(m_s->params.size())}, {py::ssize_t(sizeof(double))},
                                  m_s->params.data(), self));
    }
    static py::array readOnly(py::array a) {
        a.attr("setflags")(py::arg("write") = false);
        return a;
    }
    const ModuleString& string() const { return *m_s; }
    const Grammar& grammar() const { return *m_g; }
    py::list alphabet() const {
        py::list out;
        for (size_t k = 0; k < m_g->alphabet.size(); ++k) out.append(py::make_tuple(m_g->alphabet[SymbolId(k)].name, m_g->alphabet[SymbolId(k)].arity));
        return out;
    }

private:
    // Where module i's parameters start: a checkpoint every 64 modules, then a short walk.
    size_t paramOffset(size_t i) {
        if (m_s->params.size() == 0) return 0;
        if (m_marks.empty()) {
            m_marks.reserve(size() / 64 + 1);
            size_t at = 0;
            for (size_t k = 0; k < size(); ++k) {
                if (k % 64 == 0) m_marks.push_back(at);
                at += m_g->alphabet[m_s->symbols.data()[k]].arity;
            }
        }
        size_t at = m_marks[i / 64];
        for (size_t k = i / 64 * 64; k < i; ++k) at += m_g->alphabet[m_s->symbols.data()[k]].arity;
        return at;
    }
    std::shared_ptr<const ModuleString> m_s;
    std::shared_ptr<const Grammar> m_g;
    std::vector<size_t> m_marks;
};

// [SECTION] Plant: a grammar and its growth
// One plant: a grammar (any kind Sprout opens) and its derivation, step by step.
class Plant {
public:
    std::string name, text, dialect, path;  // path: the file's, for its includes and imports ("" for text)
    FileKind kind = FileKind::Lsys;
    std::shared_ptr<const Grammar> grammar;
    // An L-Py model: each step's drawing, made when geometry(), render() or export() first asks
    // for it (null until then), and each step as derived, read when derive() first asks for
    // it, both by `lpyDrawer`.
    std::vector<std::shared_ptr<const Grammar>> lpySteps;
    std::vector<std::optional<LString>> lpyDerived;
    std::shared_ptr<lpy::StepDrawer> lpyDrawer;
    std::vector<Diagnostic> warnings;
    std::string lpyString;  // an L-Py model: its last string as L-Py writes it

    bool isLpy() const { return !lpySteps.empty(); }
    int iterations() const { return isLpy() ? int(lpySteps.size()) - 1 : grammar->settings.iterations; }

    // Step k of an L-Py model as the turtle draws it (its interpretation rules applied).
    std::shared_ptr<const Grammar> lpyDrawn(int k) {
        if (k < 0 || k >= int(lpySteps.size())) throw py::value_error("no step " + std::to_string(k) + " in this L-Py model's run");
        if (!lpySteps[size_t(k)]) {
            std::shared_ptr<const Grammar> g;
            {
                py::gil_scoped_release release;  // the drawer takes the interpreter itself
                g = lpyDrawer->draw(k);
            }
            lpySteps[size_t(k)] = std::move(g);
        }
        return lpySteps[size_t(k)];
    }

    // Step n's string (derived as far as needed, the steps before it kept).
    LString derive(std::optional<int> n, std::optional<std::uint64_t> seed) {
        const int k = n.value_or(iterations());
        if (k < 0) throw py::value_error("the step must be 0 or more");
        if (isLpy()) {
            if (k >= int(lpySteps.size()))
                throw py::value_error("this L-Py model was run for " + std::to_string(lpySteps.size() - 1) +
                                      " steps: open it with steps=" + std::to_string(k));
            if (lpyDrawer) {
                std::optional<LString>& s = lpyDerived[size_t(k)];
                if (!s) {
                    DerivationRecord r;
                    {
                        py::gil_scoped_release release;  // the drawer takes the interpreter itself
                        r = lpyDrawer->derived(k);
                    }
                    s.emplace(r.steps.at(0), r.grammar);
                }
                return *s;
            }
            auto g = lpyDrawn(k);  // a scene's plant (_plant_of_lpy): what is drawn is all it has
            return LString(std::make_shared<const ModuleString>(g->axiom), g);
        }
        if (!m_growth || m_seed != seed) {
            DeriveOptions o;
            o.seed = seed;
            m_growth = std::make_unique<Growth>(grammar, o);
            m_seed = seed;
        }
        DeriveOutcome outcome;
        std::shared_ptr<const ModuleString> s;
        {
            py::gil_scoped_release release;
            outcome = m_growth->derive(k);
            if (outcome.ok()) s = m_growth->step(k);
        }
        if (!outcome.ok()) throw py::value_error(name + ": " + outcome.message);
        return LString(s, grammar);
    }

    // The grammar to draw for step n (an L-Py step is its own) and the options that draw it.
    std::shared_ptr<const Grammar> drawn(std::optional<int> n, std::optional<std::uint64_t> seed, SnapshotOptions& o) {
        const int k = n.value_or(iterations());
        if (isLpy()) return lpyDrawn(k);
        o.iterations = k;
        o.seed = seed;
        return grammar;
    }

    // The turtle's drawing of step n, from the string derive() keeps (not derived again).
    Geometry geometry(std::optional<int> n, std::optional<std::uint64_t> seed) {
        Geometry out;
        if (isLpy()) {  // an L-Py step is drawn as it is
            auto g = lpyDrawn(n.value_or(iterations()));
            py::gil_scoped_release release;
            drawAsIs(g->axiom, *g, {0, seed.value_or(g->settings.seed)}, out);
            return out;
        }
        LString s = derive(n, seed);
        py::gil_scoped_release release;
        drawAsIs(s.string(), s.grammar(), {n.value_or(iterations()), seed.value_or(s.grammar().settings.seed)}, out);
        return out;
    }

private:
    std::unique_ptr<Growth> m_growth;
    std::optional<std::uint64_t> m_seed;
};

// [SECTION] Opening and parsing
Plant parsed(std::string text, FileKind kind, const std::string& path, const std::string& name, bool python, int steps) {
    Plant p;
    p.name = name;
    p.kind = kind;
    if (kind == FileKind::Ifs || kind == FileKind::Forest)
        throw py::value_error(name + ": holds " + (kind == FileKind::Ifs ? "an iterated function system" : "a forest scene") +
                              ", not one grammar: `sprout render` draws it");
    if (kind == FileKind::Lpy && lpy::pythonAvailable()) {
        if (!python) throw py::value_error(name + ": an L-Py model runs Python; python=False refuses to run it");
        lpy::RunOptions ro;
        ro.steps = steps;
        ro.keepSteps = true;
        ro.drawLater = true;  // open() and derive() derive; a step is drawn when it is asked for
        ro.keepRecord = false;  // and read when it is asked for
        OpenedText opened;
        {
            py::gil_scoped_release release;  // the model takes the GIL itself, and can be cancelled
            opened = openText(text, kind, path, ro);
        }
        lpy::Model& m = *opened.model;
        if (!m.ok()) raiseDiagnostics(m.diagnostics, name);
        p.grammar = m.drawable;
        p.lpyDrawer = std::move(m.later);
        if (p.lpyDrawer && p.lpyDrawer->steps() > 0) {
            p.lpySteps.assign(size_t(p.lpyDrawer->steps()), nullptr);
            p.lpyDerived.resize(p.lpySteps.size());
        } else {
            p.lpyDrawer = nullptr;
            p.lpySteps.assign(1, m.drawable);  // nothing kept: what was drawn is all there is
        }
        p.dialect = "L-Py";
        p.lpyString = std::move(m.derived);  // empty: written by the drawer when asked for
        p.warnings = m.diagnostics;
        p.text = std::move(text);
        p.path = path;
        return p;
    }
    OpenedText r = openText(text, kind, path);
    if (!r.ok()) raiseDiagnostics(r.diagnostics, name);
    p.grammar = r.grammar;
    p.dialect = r.grammar->dialect;
    p.warnings = r.diagnostics;
    p.text = std::move(text);
    p.path = path;
    return p;
}

FileKind kindNamed(const std::string& kind) {
    static const std::pair<const char*, FileKind> kinds[] = {
        {"lsys", FileKind::Lsys}, {"abop", FileKind::Lsys}, {"cpfg", FileKind::Cpfg}, {"lpy", FileKind::Lpy},
        {"lparser", FileKind::Lparser}, {"fractint", FileKind::Fractint}};
    for (const auto& [n, k] : kinds)
        if (kind == n) return k;
    throw py::value_error("kind must be one of lsys, abop, cpfg, lpy, lparser, fractint (or None to detect it)");
}

// sprout.parse(text, kind=None)
Plant parseText(const std::string& text, std::optional<std::string> kind, bool python, int steps) {
    FileKind k = kind ? kindNamed(*kind) : detectFileKind("", text);
    std::string t = text;
    std::string dialect;
    if (k == FileKind::Lparser || k == FileKind::Fractint) {
        ImportResult imported = k == FileKind::Lparser ? importLparser(text, "text") : importFractint(text, "");
        if (!imported.ok()) raiseDiagnostics(imported.diagnostics, "<text>");
        dialect = k == FileKind::Lparser ? "Lparser" : "Fractint";
        t = imported.text;
        k = imported.kind;
    }
    Plant p = parsed(t, k, "", "<text>", python, steps);
    if (!dialect.empty()) p.dialect = dialect;
    return p;
}

// sprout.open(source): a file of any kind Sprout opens (FILE.l:System picks a Fractint system),
// a PNG written by Sprout, or a preset's name, read as the CLI reads it (app/plant/source.hpp).
Plant openSource(const std::string& source, bool python, int steps) {
    SourceText read = readSource(source);
    if (hasErrors(read.diagnostics)) raiseDiagnostics(read.diagnostics, read.diagnosticsName);
    if (!read.error.empty()) throw py::value_error(read.error + " (sprout.presets() lists the presets)");
    Plant p = parsed(std::move(read.text), read.kind, read.includePath, read.displayName, python, steps);
    if (!read.dialect.empty()) p.dialect = read.dialect;
    return p;
}

// [SECTION] Arguments
render::ViewPreset viewNamed(const std::optional<std::string>& view) {
    if (!view || *view == "auto") return render::ViewPreset::Auto;
    if (*view == "front") return render::ViewPreset::Front;
    if (*view == "side") return render::ViewPreset::Side;
    if (*view == "top") return render::ViewPreset::Top;
    if (*view == "iso") return render::ViewPreset::Iso;
    throw py::value_error("view must be auto, front, side, top or iso");
}

template <class T>
py::array_t<T> owned(std::vector<T>&& data, std::vector<py::ssize_t> shape) {
    auto* v = new std::vector<T>(std::move(data));
    py::capsule free(v, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(shape, v->data(), free);
}

}  // namespace

namespace {

// [SECTION] The module
void defineLString(py::module_& m) {
    py::class_<LString>(m, "LString", "A derived string: a read-only sequence of (name, params) modules, shared with the derivation")
        .def("__len__", &LString::size)
        .def("__getitem__", &LString::module)
        .def("__str__", &LString::text)
        .def("__repr__", [](const LString& s) { return "<sprout.LString of " + std::to_string(s.size()) + " modules>"; })
        .def("count", &LString::count, py::arg("name"), "How many modules of this name the string holds")
        .def_property_readonly("symbols", [](py::object self) { return self.cast<const LString&>().symbols(self); },
                               "Each module's symbol (numpy uint16, no copy): an index into `alphabet`")
        .def_property_readonly("params", [](py::object self) { return self.cast<const LString&>().params(self); },
                               "Every parameter, module after module (numpy float64, no copy)")
        .def_property_readonly("alphabet", &LString::alphabet, "(name, parameter count) of each symbol");
}

void definePlant(py::module_& m) {
    py::class_<Plant>(m, "Plant", "A grammar of any kind Sprout opens, ready to derive, draw, render and export")
        .def_readonly("name", &Plant::name)
        .def_readonly("text", &Plant::text)
        .def(
            "_set_text",
            [](Plant& p, const std::string& text) {
                Plant again = parsed(text, p.kind, p.path, p.name, true, -1);  // raises, the plant unchanged, on errors
                again.dialect = p.dialect;
                p = std::move(again);
            },
            py::arg("text"), "The plant made again from new text (plant.parameters writes through it)")
        .def_readonly("dialect", &Plant::dialect, "What the text was read as: .lsys, ABOP notation, cpfg, L-Py, Lparser, Fractint")
        .def_property_readonly("n", &Plant::iterations, "The derivation length the grammar sets")
        .def_property_readonly(
            "lpy_string",
            [](Plant& p) {
                if (p.lpyString.empty() && p.lpyDrawer) {
                    py::gil_scoped_release release;  // the drawer takes the interpreter itself
                    p.lpyString = p.lpyDrawer->text(p.lpyDrawer->steps() - 1);
                }
                return p.lpyString;
            },
            "An L-Py model: its last string as L-Py writes it (derive() gives its modules)")
        .def_property_readonly("angle", [](const Plant& p) { return p.grammar->settings.angle.mean; })
        .def_property_readonly("seed", [](const Plant& p) { return p.grammar->settings.seed; })
        .def_property_readonly("defines", [](const Plant& p) { return p.grammar->defines; }, "The grammar's named constants")
        .def_property_readonly("warnings", [](const Plant& p) {
            py::list out;
            for (const auto& d : p.warnings) out.append(py::make_tuple(d.line, d.col, d.message));
            return out;
        })
        .def("derive", &Plant::derive, py::arg("n") = py::none(), py::arg("seed") = py::none(),
             "The string of step n (default: the grammar's n); the steps before it are kept, so stepping is cheap")
        .def(
            "geometry",
            [](Plant& p, std::optional<int> n, std::optional<std::uint64_t> seed) {
                Geometry g = p.geometry(n, seed);
                const size_t c = g.cylinders.size();
                std::vector<float> seg(c * 6), radii(c * 2);
                std::vector<std::uint8_t> col(c * 4);
                for (size_t i = 0; i < c; ++i) {
                    const auto& s = g.cylinders[i];
                    for (int k = 0; k < 3; ++k) seg[i * 6 + size_t(k)] = s.start[k], seg[i * 6 + 3 + size_t(k)] = s.end[k];
                    radii[i * 2] = s.startRadius, radii[i * 2 + 1] = s.endRadius;
                    for (int k = 0; k < 4; ++k) col[i * 4 + size_t(k)] = std::uint8_t(s.colour >> (24 - 8 * k));
                }
                const size_t t = g.polygons.indices.size() / 3;
                std::vector<float> tri(t * 9);
                std::vector<std::uint8_t> tcol(t * 4);
                for (size_t i = 0; i < t; ++i) {
                    for (int v = 0; v < 3; ++v) {
                        const glm::vec3& q = g.polygons.positions[g.polygons.indices[i * 3 + size_t(v)]];
                        for (int k = 0; k < 3; ++k) tri[i * 9 + size_t(v) * 3 + size_t(k)] = q[k];
                    }
                    const std::uint32_t cc = g.polygons.colours.empty() ? 0xffffffffu : g.polygons.colours[g.polygons.indices[i * 3]];
                    for (int k = 0; k < 4; ++k) tcol[i * 4 + size_t(k)] = std::uint8_t(cc >> (24 - 8 * k));
                }
                const size_t l = g.surfaces.size();
                std::vector<float> leaves(l * 10);
                std::vector<std::uint8_t> lcol(l * 4);
                for (size_t i = 0; i < l; ++i) {
                    const auto& s = g.surfaces[i];
                    for (int k = 0; k < 3; ++k)
                        leaves[i * 10 + size_t(k)] = s.position[k], leaves[i * 10 + 3 + size_t(k)] = s.heading[k],
                                    leaves[i * 10 + 6 + size_t(k)] = s.up[k];
                    leaves[i * 10 + 9] = s.size;
                    for (int k = 0; k < 4; ++k) lcol[i * 4 + size_t(k)] = std::uint8_t(s.colour >> (24 - 8 * k));
                }
                py::dict out;
                out["segments"] = owned(std::move(seg), {py::ssize_t(c), 2, 3});
                out["radii"] = owned(std::move(radii), {py::ssize_t(c), 2});
                out["colors"] = owned(std::move(col), {py::ssize_t(c), 4});
                out["triangles"] = owned(std::move(tri), {py::ssize_t(t), 3, 3});
                out["triangle_colors"] = owned(std::move(tcol), {py::ssize_t(t), 4});
                out["leaves"] = owned(std::move(leaves), {py::ssize_t(l), 10});
                out["leaf_colors"] = owned(std::move(lcol), {py::ssize_t(l), 4});
                out["bounds"] = py::make_tuple(py::make_tuple(g.bounds.min.x, g.bounds.min.y, g.bounds.min.z),
                                               py::make_tuple(g.bounds.max.x, g.bounds.max.y, g.bounds.max.z));
                return out;
            },
            py::arg("n") = py::none(), py::arg("seed") = py::none(),
            "The turtle's drawing as numpy arrays: segments (N,2,3) with radii (N,2) and colors (N,4 RGBA), "
            "polygon triangles (M,3,3) with triangle_colors, leaves (K,10: position, heading, up, size) with leaf_colors")
        .def(
            "render",
            [](Plant& p, std::optional<int> n, int width, int height, std::optional<std::uint64_t> seed, std::optional<std::string> view,
               std::optional<float> yaw, std::optional<float> pitch, bool ground, bool shadows, std::optional<std::string> path) {
                SnapshotOptions o;
                o.width = width;
                o.height = height;
                o.view = viewNamed(view);
                o.yaw = yaw;
                o.pitch = pitch;
                o.render.ground = ground;
                o.render.shadows = shadows;
                auto g = p.drawn(n, seed, o);
                if (width < 1 || height < 1 || width > 16384 || height > 16384) throw py::value_error("width and height must be 1 to 16384");
                Snapshot shot;
                std::string error;
                bool ok;
                {
                    py::gil_scoped_release release;
                    ok = renderSnapshot(g, o, shot, error);
                }
                if (!ok) throw std::runtime_error(p.name + ": " + error);
                if (path) {
                    shot.image.text.emplace_back("lsys", p.text);
                    shot.image.text.emplace_back("Software", "Sprout " SPROUT_VERSION);
                    if (!writePng(*path, shot.image, error)) throw std::runtime_error(*path + ": " + error);
                }
                return owned(std::move(shot.image.rgba), {height, width, 4});
            },
            py::arg("n") = py::none(), py::arg("width") = 640, py::arg("height") = 480, py::arg("seed") = py::none(),
            py::arg("view") = py::none(), py::arg("yaw") = py::none(), py::arg("pitch") = py::none(), py::arg("ground") = true,
            py::arg("shadows") = true, py::arg("path") = py::none(),
            "A headless picture (OSMesa) as a numpy array (height, width, 4 RGBA); with path=, also a PNG carrying the grammar")
        .def(
            "export",
            [](Plant& p, const std::string& path, std::optional<int> n, std::optional<std::uint64_t> seed, int sides) {
                auto format = exporter::formatFromPath(path);
                if (!format) throw py::value_error(path + ": the extension must be .glb, .obj, .ply or .svg");
                Geometry g = p.geometry(n, seed);
                exporter::ExportOptions eo;
                eo.sides = sides;
                eo.generator = "Sprout " SPROUT_VERSION;
                exporter::ExportStats stats;
                std::string error;
                bool ok;
                {
                    py::gil_scoped_release release;
                    ok = exporter::exportGeometry(g, path, *format, eo, stats, error);
                }
                if (!ok) throw std::runtime_error(path + ": " + error);
                py::dict out;
                out["vertices"] = stats.vertices;
                out["triangles"] = stats.triangles;
                out["bytes"] = stats.bytes;
                return out;
            },
            py::arg("path"), py::arg("n") = py::none(), py::arg("seed") = py::none(), py::arg("sides") = 0,
            "Writes a glTF binary, OBJ + MTL, PLY or SVG of step n");
}

}  // namespace

void bindModelObjects(py::module_& m);  // sprout_objects.cpp

PYBIND11_MODULE(_sprout, m) {
    m.doc() = "Sprout's L-system engine: grammars of every kind Sprout opens, derivation, the turtle, pictures and models";
    m.attr("__version__") = SPROUT_VERSION;

    defineLString(m);
    definePlant(m);

    m.def("_install_openalea", &lpy::installOpenalea);
    // A scene of an L-Py script's Lsystem (openalea.lpy, sceneInterpretation) as a plant that
    // renders and exports like any other.
    m.def("_plant_of_lpy", [](py::object session, py::object lstring) {
        Plant p;
        p.name = "<Lsystem>";
        p.kind = FileKind::Lpy;
        p.dialect = "L-Py";
        p.grammar = lpy::drawingOf(session.ptr(), lstring.ptr());
        if (!p.grammar) throw py::value_error("this Sprout was built without Python");
        p.lpySteps.push_back(p.grammar);
        return p;
    });
    // openalea.plantgl's Scene draws itself through it (lpy/ imports nothing of `sprout`).
    lpy::setScenePlantMaker(m.attr("_plant_of_lpy").ptr());
    m.def("open", &openSource, py::arg("source"), py::arg("python") = true, py::arg("steps") = -1,
          "A file of any kind Sprout opens (.lsys, ABOP notation, cpfg .l, .lpy, Lparser .ls, Fractint .l or FILE.l:System, "
          "a PNG written by Sprout) or a preset's name. An L-Py model is a Python program: it runs here as `python3 FILE` "
          "would (python=False refuses); steps= sets its derivation length");
    m.def("parse", &parseText, py::arg("text"), py::arg("kind") = py::none(), py::arg("python") = true, py::arg("steps") = -1,
          "A grammar from text; kind is lsys, abop, cpfg, lpy, lparser or fractint (None: detected from the text)");
    m.def("presets", &presetNames, "The built-in presets' names");
    bindModelObjects(m);  // sprout_objects.cpp
}
