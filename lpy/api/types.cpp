// The Python classes of L-Py's strings (lpy/interpreter/interpreter.hpp): Module (ParamModule), ModuleClass
// and Lstring (AxialTree), as L-Py defines them (src/wrapper/export_axialtree.cpp,
// export_module.cpp, export_moduleclass.cpp): inside a rule's body, in a hook, or in a
// script that drives an Lsystem. Their names are the running engine's, or the process's
// table of names outside a derivation (names()).

// Index of this file:
//   [SECTION] names, values and views
//   [SECTION] ModuleClass
//   [SECTION] Module
//   [SECTION] Lstring's axial tree
//   [SECTION] Lstring
//   [SECTION] defineTypes

#include <pybind11/stl.h>

#include <climits>

#include "lpy/api/api.hpp"
#include "lpy/interpreter/interpreter.hpp"
#include "lpy/plantgl/bindings.hpp"
#include "lpy/engine/axial_tree.hpp"

namespace py = pybind11;

namespace sprout::lpy {
namespace {

//-----------------------------------------------------------------------------
// [SECTION] names, values and views
//-----------------------------------------------------------------------------
const int kDefaultScale = INT_MAX;  // L-Py's ModuleClass.DEFAULT_SCALE

using namespace tree;

const std::string& nameOf(int cls) {
    static const std::string unknown = "?";
    const ModuleClasses& c = names();
    return cls >= 0 && size_t(cls) < c.size() ? c.name(cls) : unknown;
}

py::object moduleArg(LModule& m, py::ssize_t k) {
    const py::ssize_t n = m.args ? py::ssize_t(PyTuple_GET_SIZE(m.args.ptr())) : 0;
    if (k < 0) k += n;
    if (k < 0 || k >= n) throw py::index_error("module parameter index out of range");
    return m.args[py::size_t(k)];
}

PyModule viewOf(const std::shared_ptr<LString>& s, size_t i) {
    PyModule m;
    m.owner = s;
    m.index = i;
    return m;
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

size_t checkedIndex(const LString& s, py::ssize_t i) {
    const py::ssize_t n = py::ssize_t(s.size());
    if (i < 0) i += n;
    if (i < 0 || i >= n) throw py::index_error("Lstring index out of range");
    return size_t(i);
}

// The scale of each class as the running model or the current context says (setModuleScale,
// then `module X : scale = n`); INT_MAX: none.
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

py::object indexOrNone(long i) { return i < 0 ? py::object(py::none()) : py::object(py::int_(i)); }

py::object nodeAt(const PyModule& self, long i) {
    if (i < 0 || !self.owner) return py::none();
    return py::cast(viewOf(self.owner, size_t(i)));
}

py::list nodes(const PyModule& self, const std::vector<long>& at) {
    py::list out;
    for (long i : at) out.append(nodeAt(self, i));
    return out;
}

py::object nodesOrNone(const PyModule& self, const std::vector<long>& at) {
    if (at.empty()) return py::none();
    return nodes(self, at);
}

py::object listOrNone(const std::vector<long>& v) {
    if (v.empty()) return py::none();
    py::list out;
    for (long i : v) out.append(i);
    return out;
}

// An Lstring made from what L-Py's AxialTree takes: text, a list of modules, another Lstring.
PyLstring makeLstring(py::handle v) {
    PyLstring out{std::make_shared<LString>()};
    if (!v.is_none()) extend(out.get(), v);
    return out;
}

// The modules of s[from:to:step] (Python's slice), as a new Lstring.
PyLstring sliceOf(const PyLstring& s, const py::slice& sl) {
    size_t start = 0, stop = 0, step = 0, n = 0;
    if (!sl.compute(s.get().size(), &start, &stop, &step, &n)) throw py::error_already_set();
    PyLstring out{std::make_shared<LString>()};
    for (size_t k = 0; k < n; ++k, start += step) out.get().push_back((s.get())[start]);
    return out;
}

// (name, args) pairs: how an Lstring or a module is pickled.
py::list stateOf(const LString& s) {
    py::list out;
    for (const LModule& m : s) out.append(py::make_tuple(nameOf(m.cls), m.args ? m.args : py::tuple()));
    return out;
}

LString fromState(py::handle state) {
    LString out;
    for (py::handle item : state) {
        LModule m;
        m.cls = names().intern(item[py::int_(0)].cast<std::string>());
        m.args = py::reinterpret_borrow<py::tuple>(item[py::int_(1)]);
        out.push_back(std::move(m));
    }
    return out;
}

//-----------------------------------------------------------------------------
// [SECTION] ModuleClass
//-----------------------------------------------------------------------------
// ModuleClass, and the module functions on the table of names.
void defineModuleClass(py::module_& m) {
    py::class_<PyModuleClass>(m, "ModuleClass")
        .def_property_readonly("name", [](const PyModuleClass& c) { return nameOf(c.cls); })
        .def("__call__", [](const PyModuleClass& c, py::args args) {
            PyModule out;
            out.own = {c.cls, py::tuple(args)};
            return out;
        })
        .def("__repr__", [](const PyModuleClass& c) { return "ModuleClass(" + nameOf(c.cls) + ")"; })
        .def("__eq__", [](const PyModuleClass& a, const PyModuleClass& b) { return a.cls == b.cls; })
        .def("__hash__", [](const PyModuleClass& c) { return c.cls; })
        // L-Py's module classes by name, and their inheritance (`module B : base = A`).
        .def_static("get", [](const std::string& name) -> py::object {
            const int cls = names().find(name);
            return cls < 0 ? py::object(py::none()) : py::cast(PyModuleClass{cls});
        })
        .def("issubclass", [](const PyModuleClass& c, const PyModuleClass& base) { return names().derivesFrom(c.cls, base.cls); })
        .def_readonly_static("DEFAULT_SCALE", &kDefaultScale)
        .def_property_readonly("id", [](const PyModuleClass& c) { return c.cls; })
        .def_property_readonly("aliases", [](const PyModuleClass& c) { return names().aliasesOf(c.cls); })
        // A class's scale as the current context sees it (setModuleScale, then its declaration).
        .def_property("scale", [](const PyModuleClass& c) { return scales()(c.cls); },
                      [](const PyModuleClass& c, int scale) {
                          py::dict state = py::module_::import("openalea.lpy").attr("_state");
                          py::dict(state.attr("setdefault")("scales", py::dict()))[py::str(nameOf(c.cls))] = scale;
                          state["changes"] = py::int_(state.contains("changes") ? state["changes"].cast<long>() + 1 : 1);
                      });
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
    m.def("_declare", [](const std::string& name) { return names().intern(name); });
}

//-----------------------------------------------------------------------------
// [SECTION] Module
//-----------------------------------------------------------------------------
// Module (L-Py's ParamModule): a module of its own or a view of a string's.
void defineModule(py::module_& m) {
    py::class_<PyModule>(m, "Module")
        .def(py::init([](const std::string& name, py::args args) {
            PyModule out;
            out.own = {names().intern(name), py::tuple(args)};
            return out;
        }))
        .def(py::init([](const PyModuleClass& c, py::args args) {
            PyModule out;
            out.own = {c.cls, py::tuple(args)};
            return out;
        }))
        .def_property_readonly("name", [](PyModule& self) { return nameOf(self.get().cls); })
        .def_property_readonly("mclass", [](PyModule& self) { return PyModuleClass{self.get().cls}; })
        .def_property_readonly("args", [](PyModule& self) { return py::list(self.get().args ? self.get().args : py::tuple()); })
        .def("__len__", [](PyModule& self) { return self.get().args ? py::len(self.get().args) : 0; })
        .def("argSize", [](PyModule& self) { return self.get().args ? py::len(self.get().args) : 0; })
        .def("__getitem__", [](PyModule& self, py::ssize_t k) { return moduleArg(self.get(), k); })
        .def("__setitem__", [](PyModule& self, py::ssize_t k, py::object v) {
            LModule& mod = self.get();
            moduleArg(mod, k);  // range check
            const py::ssize_t n = py::ssize_t(PyTuple_GET_SIZE(mod.args.ptr()));
            if (k < 0) k += n;
            py::list l(mod.args);
            l[py::size_t(k)] = v;
            mod.args = py::tuple(l);
        })
        .def("append", [](PyModule& self, py::object v) {
            LModule& mod = self.get();
            py::list l(mod.args ? mod.args : py::tuple());
            l.append(v);
            mod.args = py::tuple(l);
        })
        .def("__getattr__", [](PyModule& self, const std::string& attr) -> py::object {
            LModule& mod = self.get();
            const auto& params = names().parameterNames;
            if (size_t(mod.cls) < params.size())
                for (size_t k = 0; k < params[size_t(mod.cls)].size(); ++k)
                    if (params[size_t(mod.cls)][k] == attr) return moduleArg(mod, py::ssize_t(k));
            throw py::attribute_error("module " + nameOf(mod.cls) + " has no parameter " + attr);
        })
        // `$A(a)` in a header binds a module of the string (L-Py's NodeModule): its place
        // and its tree.
        .def("position", [](PyModule& self) -> py::object {
            return self.owner ? py::object(py::int_(self.index)) : py::object(py::none());
        })
        .def("parent", [](PyModule& self) { return nodeAt(self, self.owner ? parentOf(*self.owner, self.index) : -1); })
        .def("father", [](PyModule& self) { return nodeAt(self, self.owner ? parentOf(*self.owner, self.index) : -1); })
        .def("direct_child", [](PyModule& self) { return nodeAt(self, self.owner ? directSonOf(*self.owner, self.index) : -1); })
        .def("directSon", [](PyModule& self) { return nodeAt(self, self.owner ? directSonOf(*self.owner, self.index) : -1); })
        .def("children", [](PyModule& self) { return nodesOrNone(self, self.owner ? childrenOf(*self.owner, self.index) : std::vector<long>{}); })
        .def("sons", [](PyModule& self) { return nodesOrNone(self, self.owner ? childrenOf(*self.owner, self.index) : std::vector<long>{}); })
        .def("lateral_children", [](PyModule& self) {
            return nodesOrNone(self, self.owner ? lateralSonsOf(*self.owner, self.index) : std::vector<long>{});
        })
        .def("complex", [](PyModule& self, py::object scale) {
            if (!self.owner) return py::object(py::none());
            const Scale sc = scales();
            const int at = scale.is_none() ? sc((*self.owner)[self.index].cls) + 1 : scale.cast<int>();
            return nodeAt(self, complexOf(*self.owner, self.index, at, sc));
        }, py::arg("scale") = py::none())
        .def("components", [](PyModule& self) { return nodes(self, self.owner ? componentsOf(*self.owner, self.index, scales()) : std::vector<long>{}); })
        .def("components_at_scale", [](PyModule& self, int scale) {
            return nodes(self, self.owner ? componentsOf(*self.owner, self.index, scales(), &scale) : std::vector<long>{});
        })
        .def("scale", [](PyModule& self) { return scales()(self.get().cls); })
        .def("__eq__", [](PyModule& a, py::object b) {
            if (!py::isinstance<PyModule>(b)) return false;
            return sameModule(a.get(), py::cast<PyModule&>(b).get());
        })
        .def("__copy__", [](PyModule& self) {
            PyModule out;
            out.own = self.get();
            return out;
        })
        .def(py::pickle([](PyModule& self) { return stateOf({self.get()}); },
                        [](py::list state) {
                            PyModule out;
                            LString s = fromState(state);
                            if (s.size() != 1) throw py::value_error("not a pickled module");
                            out.own = s[0];
                            return out;
                        }))
        .def("__str__", [](PyModule& self) { return writeLstring({self.get()}, names()); })
        .def("__repr__", [](PyModule& self) { return writeLstring({self.get()}, names(), true); });
}

//-----------------------------------------------------------------------------
// [SECTION] Lstring's axial tree
//-----------------------------------------------------------------------------
// Lstring's axial tree (L-Py's AxialTree): a module's parent and sons, and in multiscale
// strings complexes, components, successors and predecessors at a scale (or a level).
void defineLstringTree(py::class_<PyLstring>& lstring) {
    lstring
        .def("parent", [](const PyLstring& s, py::ssize_t i) { return indexOrNone(parentOf(s.get(), checkedIndex(s.get(), i))); })
        .def("father", [](const PyLstring& s, py::ssize_t i) { return indexOrNone(parentOf(s.get(), checkedIndex(s.get(), i))); })
        .def("direct_child", [](const PyLstring& s, py::ssize_t i) { return indexOrNone(directSonOf(s.get(), checkedIndex(s.get(), i))); })
        .def("directSon", [](const PyLstring& s, py::ssize_t i) { return indexOrNone(directSonOf(s.get(), checkedIndex(s.get(), i))); })
        .def("lateral_children", [](const PyLstring& s, py::ssize_t i) { return listOrNone(lateralSonsOf(s.get(), checkedIndex(s.get(), i))); })
        .def("lateralSons", [](const PyLstring& s, py::ssize_t i) { return listOrNone(lateralSonsOf(s.get(), checkedIndex(s.get(), i))); })
        .def("children", [](const PyLstring& s, py::ssize_t i) {
            const size_t at = checkedIndex(s.get(), i);
            std::vector<long> out = lateralSonsOf(s.get(), at);
            if (long d = directSonOf(s.get(), at); d >= 0) out.push_back(d);
            return listOrNone(out);
        })
        .def("sons", [](py::object s, py::ssize_t i) { return s.attr("children")(i); })
        // Multiscale strings (L-Py's AxialTree): complexes, components, successors and
        // predecessors at a scale (or a level).
        .def("complex", [](const PyLstring& s, py::ssize_t i, py::object scale) {
            const size_t at = checkedIndex(s.get(), i);
            const Scale sc = scales();
            return indexOrNone(complexOf(s.get(), at, scale.is_none() ? sc((s.get())[at].cls) + 1 : scale.cast<int>(), sc));
        }, py::arg("pos"), py::arg("scale") = py::none())
        .def("components", [](const PyLstring& s, py::ssize_t i) { return componentsOf(s.get(), checkedIndex(s.get(), i), scales()); })
        .def("components_at_scale", [](const PyLstring& s, py::ssize_t i, int scale) {
            return componentsOf(s.get(), checkedIndex(s.get(), i), scales(), &scale);
        })
        .def("successor_at_scale", [](const PyLstring& s, py::ssize_t i, int scale) {
            return indexOrNone(successorAtScale(s.get(), checkedIndex(s.get(), i), scale, scales()));
        })
        .def("predecessor_at_scale", [](const PyLstring& s, py::ssize_t i, int scale) {
            return indexOrNone(predecessorAtScale(s.get(), checkedIndex(s.get(), i), scale, scales()));
        })
        .def("successor_at_level", [](const PyLstring& s, py::ssize_t i, int scale) {
            return indexOrNone(successorAtLevel(s.get(), checkedIndex(s.get(), i), scale, scales()));
        })
        .def("predecessor_at_level", [](const PyLstring& s, py::ssize_t i, int scale) {
            return indexOrNone(predecessorAtLevel(s.get(), checkedIndex(s.get(), i), scale, scales()));
        });
}

//-----------------------------------------------------------------------------
// [SECTION] Lstring
//-----------------------------------------------------------------------------
// Lstring (L-Py's AxialTree): a string of modules as a Python sequence.
void defineLstring(py::module_& m) {
    py::class_<PyLstring> lstring(m, "Lstring");
    lstring
        .def(py::init([] { return PyLstring{std::make_shared<LString>()}; }))
        .def(py::init([](py::object v) { return makeLstring(v); }))
        // L-Py compares an Lstring with another or with text (`lstring == 'BSABSA'`): the same
        // modules with equal parameters.
        .def("__eq__", [](const PyLstring& s, py::object v) {
            LString other;
            try {
                extend(other, v);
            } catch (const std::exception&) {
                return false;  // not something a string is made of (a number, a dict)
            }
            if (other.size() != s.get().size()) return false;
            for (size_t k = 0; k < other.size(); ++k)
                if (!sameModule((s.get())[k], other[k])) return false;
            return true;
        })
        .def("__ne__", [](py::object s, py::object v) { return !s.attr("__eq__")(v).cast<bool>(); })
        .def("__iadd__", [](PyLstring& s, py::object v) {
            extend(s.get(), v);
            return s;
        })
        .def("__add__", [](const PyLstring& s, py::object v) {
            PyLstring out{std::make_shared<LString>(s.get())};
            extend(out.get(), v);
            return out;
        })
        .def("__radd__", [](const PyLstring& s, py::object v) {
            PyLstring out = makeLstring(v);
            out.get().insert(out.get().end(), s.get().begin(), s.get().end());
            return out;
        })
        .def("__mul__", [](const PyLstring& s, int times) {
            PyLstring out{std::make_shared<LString>()};
            for (int k = 0; k < times; ++k) out.get().insert(out.get().end(), s.get().begin(), s.get().end());
            return out;
        })
        .def("__len__", [](const PyLstring& s) { return s.size(); })
        .def("__bool__", [](const PyLstring& s) { return !s.get().empty(); })
        .def("__getitem__", [](const PyLstring& s, py::ssize_t i) { return viewOf(s.s, checkedIndex(s.get(), i)); })
        .def("__getitem__", [](const PyLstring& s, const py::slice& sl) { return sliceOf(s, sl); })
        .def("__setitem__", [](PyLstring& s, py::ssize_t i, py::object v) {
            const size_t at = checkedIndex(s.get(), i);
            LString one;
            appendValue(one, v, names().size());
            if (one.size() != 1) throw py::value_error("an Lstring item is one module");
            (s.get())[at] = one[0];
        })
        .def("__delitem__", [](PyLstring& s, py::ssize_t i) { s.get().erase(s.get().begin() + std::ptrdiff_t(checkedIndex(s.get(), i))); })
        .def("__delitem__", [](PyLstring& s, const py::slice& sl) {
            size_t start = 0, stop = 0, step = 0, n = 0;
            if (!sl.compute(s.get().size(), &start, &stop, &step, &n)) throw py::error_already_set();
            std::vector<bool> drop(s.get().size(), false);
            for (size_t k = 0; k < n; ++k, start += step) drop[start] = true;
            LString kept;
            for (size_t k = 0; k < s.get().size(); ++k)
                if (!drop[k]) kept.push_back((s.get())[k]);
            s.get() = std::move(kept);
        })
        .def("__iter__", [](const PyLstring& s) {
            py::list l;
            for (size_t i = 0; i < s.get().size(); ++i) l.append(viewOf(s.s, i));
            return py::iter(l);
        })
        .def("insertAt", [](PyLstring& s, py::ssize_t i, py::object v) {
            LString items;
            extend(items, v);
            const size_t at = size_t(std::clamp<py::ssize_t>(i, 0, py::ssize_t(s.get().size())));
            s.get().insert(s.get().begin() + std::ptrdiff_t(at), items.begin(), items.end());
        })
        .def("append", [](PyLstring& s, py::object v) { extend(s.get(), v); })
        .def("prepend", [](PyLstring& s, py::object v) {
            LString items;
            extend(items, v);
            s.get().insert(s.get().begin(), items.begin(), items.end());
        })
        .def("clear", [](PyLstring& s) { s.get().clear(); })
        .def("empty", [](const PyLstring& s) { return s.get().empty(); })
        .def("reverse", [](PyLstring& s) { std::reverse(s.get().begin(), s.get().end()); })
        // count('A') counts the modules named A; count(A(1)) those equal to a module.
        .def("count", [](const PyLstring& s, py::object what) {
            size_t n = 0;
            if (py::isinstance<py::str>(what)) {
                const int cls = names().find(what.cast<std::string>());
                for (const LModule& m : s.get()) n += m.cls == cls && cls >= 0;
            } else {
                LString one;
                appendValue(one, what, names().size());
                if (one.size() == 1)
                    for (const LModule& m : s.get()) n += sameModule(m, one[0]);
            }
            return n;
        })
        // find('C', start, end): the first module named C, or -1.
        .def("find", [](const PyLstring& s, const std::string& name, size_t start, py::object end) -> long {
            const int cls = names().find(name);
            const size_t stop = end.is_none() ? s.get().size() : std::min(s.get().size(), end.cast<size_t>());
            for (size_t i = start; i < stop && cls >= 0; ++i)
                if ((s.get())[i].cls == cls) return long(i);
            return -1;
        }, py::arg("name"), py::arg("start") = 0, py::arg("end") = py::none())
        .def("wellBracketed", [](const PyLstring& s) {
            long depth = 0;
            for (const LModule& m : s.get()) {
                depth += isPush(m) ? 1 : isPop(m) ? -1 : 0;
                if (depth < 0) return false;
            }
            return depth == 0;
        });
    defineLstringTree(lstring);
    lstring
        .def("__copy__", [](const PyLstring& s) { return PyLstring{std::make_shared<LString>(s.get())}; })
        .def("__deepcopy__", [](const PyLstring& s, py::object) { return PyLstring{std::make_shared<LString>(s.get())}; })
        .def(py::pickle([](const PyLstring& s) { return stateOf(s.get()); },
                        [](py::list state) { return PyLstring{std::make_shared<LString>(fromState(state))}; }))
        .def("__str__", [](const PyLstring& s) { return writeLstring(s.get(), names()); })
        .def("__repr__", [](const PyLstring& s) { return "AxialTree(" + writeLstring(s.get(), names(), true) + ")"; });  // as L-Py writes it
}

}  // namespace

//-----------------------------------------------------------------------------
// [SECTION] defineTypes
//-----------------------------------------------------------------------------
void defineTypes(py::module_& m) {
    definePlantGL(m);
    defineQuantised(m);
    definePointGrid(m);
    defineModuleClass(m);
    defineModule(m);
    defineLstring(m);
}

}  // namespace sprout::lpy
