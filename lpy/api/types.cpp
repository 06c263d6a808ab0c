// The Python classes of L-Py's strings (lpy/interpreter/interpreter.hpp), as L-Py defines them
// (src/wrapper/export_moduleclass.cpp, export_module.cpp, export_nodemodule.cpp,
// export_axialtree.cpp): inside a rule's body, in a hook, or in a script that drives an
// Lsystem. Their names are the running engine's, or the process's table of names outside a
// derivation (names()). This file: what the others share (types_impl.hpp) and ModuleClass;
// types_module.cpp: Module, ParamModule, NodeModule; types_lstring.cpp: AxialTree, Lstring,
// AxialTreeIterator.

// Index of this file:
//   [SECTION] names, values and views
//   [SECTION] ModuleClass
//   [SECTION] defineTypes

#include <pybind11/stl.h>

#include <cctype>
#include <climits>

#include "lpy/api/api.hpp"
#include "lpy/api/types_impl.hpp"
#include "lpy/interpreter/interpreter.hpp"
#include "lpy/plantgl/bindings.hpp"

namespace sprout::lpy {
namespace types {

//-----------------------------------------------------------------------------
// [SECTION] names, values and views
//-----------------------------------------------------------------------------
using namespace tree;

const std::string& nameOf(int cls) {
    static const std::string unknown = "?";
    const ModuleClasses& c = names();
    return cls >= 0 && size_t(cls) < c.size() ? c.name(cls) : unknown;
}

PyParamModule viewOf(const std::shared_ptr<LString>& s, size_t i) {
    PyParamModule m;
    m.owner = s;
    m.index = i;
    return m;
}

PyParamModule ownModule(LModule mod) {
    PyParamModule m;
    m.own = std::move(mod);
    return m;
}

std::string nameText(py::handle v) {
    if (!py::isinstance<py::str>(v)) throw py::type_error(std::string("a module's name is a str, not a ") + Py_TYPE(v.ptr())->tp_name);
    return v.cast<std::string>();
}

int internName(const std::string& name) {
    if (name.empty()) return ModuleClasses::kNone;  // L-Py's None module is named ''
    for (char c : name)
        if (c == '(' || c == ')' || c == ',' || std::isspace(static_cast<unsigned char>(c)))
            throw py::value_error("'" + name + "' cannot name a module: a name holds no parentheses, commas or spaces");
    return names().intern(name);
}

py::dict namespaceNow() {
    Engine* e = currentEngine();
    return e ? e->ns() : looseNamespace();
}

// `s += 'B'`, `s + other`: text is read as an lstring, a tuple ('A', x, y) is the module
// A(x, y) (L-Py's ParamModule(tuple)), anything else as produce takes it.
void extend(LString& s, py::handle v) {
    if (py::isinstance<py::str>(v)) {
        LString more = parseLstring(v.cast<std::string>(), names(), namespaceNow());
        s.insert(s.end(), more.begin(), more.end());
    } else if (PyTuple_Check(v.ptr()) && PyTuple_GET_SIZE(v.ptr()) > 0 && PyUnicode_Check(PyTuple_GET_ITEM(v.ptr(), 0))) {
        const int cls = names().intern(py::reinterpret_borrow<py::str>(PyTuple_GET_ITEM(v.ptr(), 0)).cast<std::string>());
        s.push_back({cls, py::reinterpret_steal<py::tuple>(PyTuple_GetSlice(v.ptr(), 1, PyTuple_GET_SIZE(v.ptr())))});
    } else {
        appendValue(s, v, names().size());
    }
}

bool sameModule(const LModule& a, const LModule& b) {
    const bool noneA = !a.args || py::len(a.args) == 0, noneB = !b.args || py::len(b.args) == 0;
    if (a.cls != b.cls || noneA != noneB) return false;
    return noneA || a.args.equal(b.args);
}

LModule moduleFromText(const std::string& text) {
    LString one = parseLstring(text, names(), namespaceNow());
    if (one.size() != 1) throw py::value_error("'" + text + "' is not one module");
    return one[0];
}

// What ParamModule(...) and AxialTree items take: a module, ('A', args...), 'A(1)'.
LModule oneModule(py::handle v) {
    if (py::isinstance<PyModule>(v)) return py::cast<PyModule&>(v).get();
    if (py::isinstance<py::str>(v)) return moduleFromText(v.cast<std::string>());
    if (py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v)) {
        py::sequence t = py::reinterpret_borrow<py::sequence>(v);
        if (py::len(t) == 0) throw py::index_error("tuple index out of range");
        py::object head = t[0];
        if (!PyLong_Check(head.ptr())) return construct(internName(nameText(head)), t, 1);
        const long cls = head.cast<long>();
        if (cls < 0 || size_t(cls) >= names().size()) throw py::value_error("no module class of id " + std::to_string(cls));
        return construct(int(cls), t, 1);
    }
    LString one;
    appendValue(one, v, names().size());
    if (one.size() != 1) throw py::type_error("not a module");
    return one[0];
}

bool isRequest(int cls) {
    const std::string& n = nameOf(cls);
    return !n.empty() && n[0] == '?' && n != "?I";
}

const std::vector<std::string>& parameterNamesOf(int cls) {
    static const std::vector<std::string> none;
    const auto& params = names().parameterNames;
    return cls >= 0 && size_t(cls) < params.size() ? params[size_t(cls)] : none;
}

Scale scales() {
    if (Engine* e = currentEngine()) return [e](int cls) { return e->classScale(cls); };
    const ModuleClasses& c = names();
    auto table = std::make_shared<std::vector<int>>(c.size(), INT_MAX);
    for (size_t k = 0; k < c.size(); ++k)
        if (c.scales[k] >= 0) (*table)[k] = c.scales[k];
    py::dict state = py::module_::import("openalea.lpy").attr("_state");
    if (state.contains("scales"))
        for (auto item : py::dict(state["scales"]))
            if (int cls = c.find(item.first.cast<std::string>()); cls >= 0) (*table)[size_t(cls)] = item.second.cast<int>();
    return [table](int cls) { return cls >= 0 && size_t(cls) < table->size() ? (*table)[size_t(cls)] : INT_MAX; };
}

py::list stateOf(const LString& s) {
    py::list out;
    for (const LModule& m : s) out.append(py::make_tuple(nameOf(m.cls), m.args ? m.args : py::tuple()));
    return out;
}

LString fromState(py::handle state) {
    LString out;
    for (py::handle item : state) {
        LModule m;
        m.cls = internName(item[py::int_(0)].cast<std::string>());
        m.args = py::reinterpret_borrow<py::tuple>(item[py::int_(1)]);
        out.push_back(std::move(m));
    }
    return out;
}

namespace {

//-----------------------------------------------------------------------------
// [SECTION] ModuleClass
//-----------------------------------------------------------------------------
const int kDefaultScale = INT_MAX;  // L-Py's ModuleClass.DEFAULT_SCALE
const size_t kNoPos = size_t(-1);   // L-Py's ModuleClass::NOPOS

size_t positionIn(const std::vector<std::string>& params, const std::string& name) {
    for (size_t k = 0; k < params.size(); ++k)
        if (params[k] == name) return k;
    return kNoPos;
}

// ModuleClass (export_moduleclass.cpp), and the module functions on the table of names.
void defineModuleClass(py::module_& m) {
    py::class_<PyModuleClass> mc(m, "ModuleClass");
    mc.def_property_readonly("name", [](const PyModuleClass& c) { return nameOf(c.cls); })
        // L-Py's openalea.lpy: ModuleClass.__call__ = ParamModule(mclass, params); `new`
        // (newmodule) names the module by its first parameter.
        .def("__call__", [](const PyModuleClass& c, py::args args) { return ownModule(construct(c.cls, args, 0)); })
        .def("__repr__", [](const PyModuleClass& c) {
            std::string out = "ModuleClass('" + nameOf(c.cls) + "'," + std::to_string(c.cls);
            const std::vector<std::string> aliases = names().aliasesOf(c.cls);
            for (size_t k = 0; k < aliases.size(); ++k) out += (k ? "','" : ",['") + aliases[k];
            return out + (aliases.empty() ? ")" : "'])");
        })
        .def("__eq__", [](const PyModuleClass& a, py::object b) {
            return py::isinstance<PyModuleClass>(b) && a.cls == py::cast<const PyModuleClass&>(b).cls;
        })
        .def("__hash__", [](const PyModuleClass& c) { return c.cls; })
        // L-Py's module classes by name, and their inheritance (`module B : base = A`).
        .def_static("get", [](const std::string& name) -> py::object {
            const int cls = names().find(name);
            return cls < 0 ? py::object(py::none()) : py::cast(PyModuleClass{cls});
        }, py::arg("name"))
        .def("issubclass", [](const PyModuleClass& c, const PyModuleClass& base) { return names().derivesFrom(c.cls, base.cls); })
        .def_readonly_static("DEFAULT_SCALE", &kDefaultScale)
        .def_property_readonly("id", [](const PyModuleClass& c) { return c.cls; })
        .def_property_readonly("aliases", [](const PyModuleClass& c) { return names().aliasesOf(c.cls); })
        .def("isPredefined", [](const PyModuleClass& c) { return names().isPredefined(c.cls); })
        // Declared parameter names (`module A(x, y)`), in their order; set: declared anew.
        .def_property("parameterNames", [](const PyModuleClass& c) { return parameterNamesOf(c.cls); },
                      [](const PyModuleClass& c, std::vector<std::string> params) {
                          auto& all = names().parameterNames;
                          if (all.size() <= size_t(c.cls)) all.resize(size_t(c.cls) + 1);
                          all[size_t(c.cls)] = std::move(params);
                      })
        .def("getParameterPosition", [](const PyModuleClass& c, const std::string& name) { return positionIn(parameterNamesOf(c.cls), name); })
        .def("hasParameter", [](const PyModuleClass& c, const std::string& name) { return positionIn(parameterNamesOf(c.cls), name) != kNoPos; })
        .def("getNamedParameterNb", [](const PyModuleClass& c) { return parameterNamesOf(c.cls).size(); })
        .def_property("bases", [](const PyModuleClass& c) {
                          py::list out;
                          const auto& b = names().bases;
                          if (size_t(c.cls) < b.size())
                              for (int base : b[size_t(c.cls)]) out.append(PyModuleClass{base});
                          return out;
                      },
                      [](const PyModuleClass& c, py::iterable bases) {
                          std::vector<int> ids;
                          for (py::handle b : bases) ids.push_back(py::cast<const PyModuleClass&>(b).cls);
                          auto& all = names().bases;
                          if (all.size() <= size_t(c.cls)) all.resize(size_t(c.cls) + 1);
                          all[size_t(c.cls)] = std::move(ids);
                      });
    // A class's scale as the current context sees it (setModuleScale, then its declaration);
    // L-Py's `category` is its scale too (export_moduleclass.cpp binds getScale to both).
    auto scaleOf = [](const PyModuleClass& c) { return scales()(c.cls); };
    auto setScale = [](const PyModuleClass& c, int scale) {
        py::dict state = py::module_::import("openalea.lpy").attr("_state");
        py::dict(state.attr("setdefault")("scales", py::dict()))[py::str(nameOf(c.cls))] = scale;
        state["changes"] = py::int_(state.contains("changes") ? state["changes"].cast<long>() + 1 : 1);
    };
    mc.def_property("scale", scaleOf, setScale).def_property("category", scaleOf, setScale);
    // L-Py's use_count of the class: here the Python handles on it (L-Py's also counts its C++
    // holders: a predefined class's own pointer, the modules of its strings).
    mc.def("getReferenceCount", [](const PyModuleClass& c) { return PyModuleClass::handles(c.cls); });
    m.def("_class_count", [] { return names().size(); });
    m.def("__lpy_module_class", [](int cls) { return PyModuleClass{cls}; });
    // An lstring as written: each module's name and its arguments' texts (lstring2py).
    m.def("_written", [](const std::string& text) {
        std::vector<Diagnostic> diags;
        py::list out;
        for (const WrittenModule& w : readLstring(text, names(), 0, 1, diags))
            if (w.cls >= 0) out.append(py::make_tuple(nameOf(w.cls), w.args));
        if (!diags.empty()) throw py::value_error(diags[0].message);
        return out;
    });
    // Names declared for the strings read outside a model (LsysContext.declare, declare()).
    m.def("_declare", [](const std::string& name) { return internName(name); });
    // ModuleClassTable.remove(name or class) and whether a class still has a name.
    m.def("_forget", [](const std::string& name) { return names().forget(name); });
    m.def("_forget_class", [](int cls) { return names().forget(cls); });
    m.def("_named", [](int cls) { return names().named(cls); });
}

}  // namespace
}  // namespace types

//-----------------------------------------------------------------------------
// [SECTION] defineTypes
//-----------------------------------------------------------------------------
void defineTypes(py::module_& m) {
    definePlantGL(m);
    defineQuantised(m);
    definePointGrid(m);
    types::defineModuleClass(m);
    types::defineModules(m);
    types::defineLstrings(m);
}

}  // namespace sprout::lpy
