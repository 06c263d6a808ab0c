// L-Py's modules in Python (src/wrapper/export_module.cpp, export_module.h,
// export_nodemodule.cpp; src/cpp/module.h): Module (a name), ParamModule (its parameters,
// by position and by the names its class declares), NodeModule (a module in its string: its
// parent, children, complex and components), and PackedArgs. Every module Python gets from
// a string or makes is a ParamModule; `$A(a)` in a header and AxialTree.node give NodeModules.

// Index of this file:
//   [SECTION] parameters
//   [SECTION] Module
//   [SECTION] ParamModule
//   [SECTION] NodeModule

#include <pybind11/stl.h>

#include "lpy/api/types_impl.hpp"
#include "lpy/interpreter/interpreter.hpp"

namespace sprout::lpy::types {
namespace {

using namespace tree;

//-----------------------------------------------------------------------------
// [SECTION] parameters
//-----------------------------------------------------------------------------
const size_t kNoPos = size_t(-1);  // L-Py's ModuleClass::NOPOS

// L-Py's PackedArgs: a list (or a dict of named parameters) given last to ParamModule(...),
// its items taken as the module's parameters.
struct PackedArgs {
    py::object args;
};

py::ssize_t argCount(const LModule& m) { return m.args ? py::ssize_t(PyTuple_GET_SIZE(m.args.ptr())) : 0; }

size_t validIndex(const LModule& m, py::ssize_t i) {
    const py::ssize_t n = argCount(m);
    if (i < 0) i += n;
    if (i < 0 || i >= n) throw py::index_error("index out of range");
    return size_t(i);
}

// A slice of the parameters as L-Py reads it (ParamModule::getValidIndices): no step, an end
// past the last one is the last one, a start outside them an IndexError.
std::pair<size_t, size_t> validRange(const LModule& m, const py::slice& sl) {
    const py::ssize_t n = argCount(m);
    py::object a = sl.attr("start"), b = sl.attr("stop");
    py::ssize_t i = a.is_none() ? 0 : a.cast<py::ssize_t>(), j = b.is_none() ? n : b.cast<py::ssize_t>();
    if (i < 0) i += n;
    if (j < 0) j += n;
    if (j > n) j = n;
    if (i < 0 || i >= n || j < i) throw py::index_error("index out of range");
    return {size_t(i), size_t(j)};
}

void setArgs(LModule& m, const py::list& l) { m.args = py::tuple(l); }
py::list argList(const LModule& m) { return m.args ? py::list(m.args) : py::list(); }

size_t positionInClass(int cls, const std::string& name) {
    const auto& params = parameterNamesOf(cls);
    for (size_t k = 0; k < params.size(); ++k)
        if (params[k] == name) return k;
    return kNoPos;
}

// ParamModule::getParameterPosition: named parameters are the last ones (in size_t, as L-Py).
size_t parameterPosition(const LModule& m, const std::string& name) {
    const long first = std::max<long>(0, long(argCount(m)) - long(parameterNamesOf(m.cls).size()));
    return size_t(first) + positionInClass(m.cls, name);
}

size_t validParameterPosition(const LModule& m, const std::string& name) {
    const size_t pos = parameterPosition(m, name);
    if (pos == kNoPos) throw py::value_error("Invalid parameter name '" + name + "' for module '" + nameOf(m.cls) + "'.");
    if (pos >= size_t(argCount(m)))
        throw py::value_error("Inexisting value for parameter '" + name + " '(" + std::to_string(pos) + ") for module '" + nameOf(m.cls) + "'.");
    return pos;
}

// processArgList (src/cpp/module.cpp): a PackedArgs' dict, by the class's parameter names.
void namedArgs(int cls, py::list& args, const py::dict& named) {
    const size_t given = py::len(args), wanted = parameterNamesOf(cls).size();
    if (given + py::len(named) < wanted)
        throw py::value_error(nameOf(cls) + " takes exactly " + std::to_string(wanted) + " (" + std::to_string(given + py::len(named)) + " given)");
    std::vector<bool> missing;
    for (auto item : named) {
        const std::string pname = item.first.cast<std::string>();
        const size_t pos = positionInClass(cls, pname);
        if (pos == kNoPos) throw py::value_error("Invalid parameter name '" + pname + "' for module '" + nameOf(cls) + "'.");
        if (pos < given) throw py::value_error(nameOf(cls) + " got multiple values for parameter '" + pname + "'.");
        while (py::len(args) <= pos) {
            missing.resize(py::len(args) + 1, false);
            missing[py::len(args)] = true;
            args.append(py::none());
        }
        args[pos] = item.second;
        if (pos < missing.size()) missing[pos] = false;
    }
    const size_t nMissing = size_t(std::count(missing.begin(), missing.end(), true));
    if (nMissing) throw py::value_error(nameOf(cls) + " takes exactly " + std::to_string(wanted) + " (" + std::to_string(nMissing) + " missing)");
}

// processConstruction: `new` takes its name from the first value; a PackedArgs given last is
// unpacked.
}  // namespace

LModule construct(int cls, const py::sequence& values, size_t start) {
    LModule m{cls, py::tuple()};
    const size_t n = py::len(values);
    if (cls == names().find("new")) {
        if (start >= n) throw py::index_error("tuple index out of range");
        py::object name = values[start];
        if (!py::isinstance<py::str>(name)) throw py::type_error("newmodule(name, ...): the name of the module, a str, not a " + std::string(Py_TYPE(name.ptr())->tp_name));
        m.cls = internName(name.cast<std::string>());
        ++start;
    }
    py::list args;
    for (size_t k = start; k < n; ++k) {
        py::object v = values[k];
        if (k + 1 == n && py::isinstance<PackedArgs>(v)) {
            py::object packed = py::cast<const PackedArgs&>(v).args;
            if (py::isinstance<py::dict>(packed)) namedArgs(m.cls, args, packed);
            else
                for (py::handle h : packed) args.append(h);
        } else {
            args.append(v);
        }
    }
    m.args = py::tuple(args);
    return m;
}

namespace {

LModule fromSequence(const py::sequence& t) {
    if (py::len(t) == 0) throw py::index_error("tuple index out of range");
    py::object head = t[0];
    int cls;
    if (PyLong_Check(head.ptr())) {
        const long id = head.cast<long>();
        if (id < 0 || size_t(id) >= names().size()) throw py::value_error("no module class of id " + std::to_string(id));
        cls = int(id);
    } else {
        cls = internName(nameText(head));
    }
    return construct(cls, t, 1);
}

py::object considerFilterTest(PyModule& self, py::object filter, const char* test) {
    if (filter.is_none()) throw py::type_error(std::string("Module.") + test + ": a ConsiderFilter, not None");
    return filter.attr(test)(py::cast(PyModuleClass{self.get().cls}));
}

//-----------------------------------------------------------------------------
// [SECTION] Module
//-----------------------------------------------------------------------------
void defineModule(py::module_& m) {
    py::class_<PackedArgs>(m, "PackedArgs").def(py::init([](py::list args) { return PackedArgs{args}; }));
    py::class_<PyModule>(m, "Module")
        .def(py::init([](const std::string& name) {
            PyModule out;
            out.own = {internName(name), py::tuple()};
            return out;
        }))
        .def(py::init([](PyModule& other) {
            PyModule out;
            out.own = other.get();
            return out;
        }))
        .def(py::init([](const PyModuleClass& c) {
            PyModule out;
            out.own = {c.cls, py::tuple()};
            return out;
        }))
        .def_property("name", [](PyModule& self) { return nameOf(self.get().cls); },
                      [](PyModule& self, const std::string& name) { self.get().cls = internName(name); })
        .def_property_readonly("mclass", [](PyModule& self) { return PyModuleClass{self.get().cls}; })
        .def("isLeftBracket", [](PyModule& self) { return self.get().cls == ModuleClasses::kPush; })
        .def("isRightBracket", [](PyModule& self) { return self.get().cls == ModuleClasses::kPop; })
        .def("isBracket", [](PyModule& self) {
            const int c = self.get().cls;
            return c == ModuleClasses::kPush || c == ModuleClasses::kPop || nameOf(c) == "=]";
        })
        .def("isRequest", [](PyModule& self) { return isRequest(self.get().cls); })
        .def("isNull", [](PyModule& self) { return self.get().cls == ModuleClasses::kNone || self.get().cls == ModuleClasses::kStar; })
        .def("isCut", [](PyModule& self) { return self.get().cls == ModuleClasses::kCut; })
        .def("scale", [](PyModule& self) { return scales()(self.get().cls); })
        .def("isinstance", [](PyModule& self, const PyModuleClass& c) { return names().derivesFrom(self.get().cls, c.cls); })
        .def("isConsidered", [](PyModule& self, py::object filter) { return considerFilterTest(self, filter, "isConsidered"); })
        .def("isIgnored", [](PyModule& self, py::object filter) { return considerFilterTest(self, filter, "isIgnored"); })
        // Module == Module: the same class (ParamModule's compares the parameters too).
        .def("__eq__", [](PyModule& a, py::object b) {
            return py::isinstance<PyModule>(b) && a.get().cls == py::cast<PyModule&>(b).get().cls;
        })
        .def("__ne__", [](PyModule& a, py::object b) { return !py::cast(a).attr("__eq__")(b).cast<bool>(); })
        .def("__hash__", [](PyModule& self) { return py::hash(py::str(nameOf(self.get().cls))); })
        .def("__str__", [](PyModule& self) { return writeLstring({self.get()}, names()); })
        .def("__repr__", [](PyModule& self) { return writeLstring({self.get()}, names(), true); });
}

//-----------------------------------------------------------------------------
// [SECTION] ParamModule
//-----------------------------------------------------------------------------
PyParamModule made(LModule m) { return ownModule(std::move(m)); }

void defineParamModuleInit(py::class_<PyParamModule, PyModule>& c) {
    // ParamModule('A(1,2)'), ParamModule(module), ParamModule(('A', 1, 2)), ParamModule(mclass,
    // (1, 2)), ParamModule(['A', 1]), ParamModule('A', 1, 2) (five values at most, as L-Py).
    c.def(py::init([](const std::string& text) {
         const size_t open = text.find('(');
         if (open == std::string::npos) return made({internName(text), py::tuple()});
         return made(moduleFromText(text));
     }))
        .def(py::init([](PyModule& other) { return made(other.get()); }))
        .def(py::init([](py::tuple t) { return made(fromSequence(t)); }))
        .def(py::init([](py::list t) { return made(fromSequence(t)); }))
        .def(py::init([](const PyModuleClass& cls, py::tuple t) { return made(construct(cls.cls, t, 0)); }))
        .def(py::init([](const std::string& name, py::args values) {
            if (py::len(values) > 5) throw py::type_error("ParamModule(name[,args]): five parameters at most");
            return made(construct(internName(name), values, 0));
        }));
}

void defineParamModuleArgs(py::class_<PyParamModule, PyModule>& c) {
    auto size = [](PyParamModule& self) { return argCount(self.get()); };
    c.def("argSize", size)
        .def("__len__", size)
        .def("empty", [](PyParamModule& self) { return argCount(self.get()) == 0; })
        .def("hasArg", [](PyParamModule& self) { return argCount(self.get()) != 0; })
        .def("__tuple__", [](PyParamModule& self) {
            py::list out;
            out.append(nameOf(self.get().cls));
            for (py::handle h : argList(self.get())) out.append(h);
            return py::tuple(out);
        })
        .def("__getitem__", [](PyParamModule& self, py::ssize_t i) { return self.get().args[validIndex(self.get(), i)]; })
        .def("__getitem__", [](PyParamModule& self, const py::slice& sl) {
            auto [i, j] = validRange(self.get(), sl);
            py::list out;
            for (size_t k = i; k < j; ++k) out.append(self.get().args[k]);
            return out;
        })
        .def("__setitem__", [](PyParamModule& self, py::ssize_t i, py::object v) {
            py::list l = argList(self.get());
            l[validIndex(self.get(), i)] = v;
            setArgs(self.get(), l);
        })
        .def("__delitem__", [](PyParamModule& self, py::ssize_t i) {
            py::list l = argList(self.get());
            l.attr("__delitem__")(validIndex(self.get(), i));
            setArgs(self.get(), l);
        })
        .def("__delitem__", [](PyParamModule& self, const py::slice& sl) {
            auto [i, j] = validRange(self.get(), sl);
            py::list l = argList(self.get());
            l.attr("__delitem__")(py::slice(py::ssize_t(i), py::ssize_t(j), 1));
            setArgs(self.get(), l);
        })
        .def("append", [](PyParamModule& self, py::object v) {
            py::list l = argList(self.get());
            l.append(v);
            setArgs(self.get(), l);
        })
        .def("prepend", [](PyParamModule& self, py::object v) {
            py::list l = argList(self.get());
            l.insert(0, v);
            setArgs(self.get(), l);
        })
        .def_property("args", [](PyParamModule& self) { return argList(self.get()); },
                      [](PyParamModule& self, py::iterable v) { setArgs(self.get(), py::list(v)); })
        .def("match", [](PyParamModule& self, const std::string& name, size_t n) {
            return nameOf(self.get().cls) == name && size_t(argCount(self.get())) == n;
        });
}

void defineParamModuleNames(py::class_<PyParamModule, PyModule>& c) {
    // L-Py binds getParameterNames with a return type Boost.Python cannot convert: it always
    // raises (ModuleClass.parameterNames gives the names).
    c.def("getParameterNames", [](PyParamModule&) -> py::object {
         throw py::type_error("No to_python (by-value) converter found for C++ type: std::vector<std::string> "
                              "(L-Py's ParamModule.getParameterNames; ModuleClass.parameterNames gives them)");
     })
        .def("getNamedParameterNb", [](PyParamModule& self) { return parameterNamesOf(self.get().cls).size(); })
        .def("getParameterPosition", [](PyParamModule& self, const std::string& n) { return parameterPosition(self.get(), n); })
        .def("hasParameter", [](PyParamModule& self, const std::string& n) { return positionInClass(self.get().cls, n) != kNoPos; })
        .def("getParameter", [](PyParamModule& self, const std::string& n) { return self.get().args[validParameterPosition(self.get(), n)]; })
        .def("setParameter", [](PyParamModule& self, const std::string& n, py::object v) {
            const size_t pos = validParameterPosition(self.get(), n);
            py::list l = argList(self.get());
            l[pos] = v;
            setArgs(self.get(), l);
        })
        .def("getNamedParameters", [](PyParamModule& self, py::dict receiver, size_t fromIndex) {
            const LModule& mod = self.get();
            const auto& params = parameterNamesOf(mod.cls);
            const size_t first = size_t(std::max<long>(0, long(argCount(mod)) - long(params.size())));
            for (size_t k = fromIndex; k < params.size(); ++k) {
                if (first + k >= size_t(argCount(mod))) throw py::index_error("index out of range");
                receiver[py::str(params[k])] = mod.args[first + k];
            }
        }, py::arg("receiver"), py::arg("fromIndex") = 0)
        // openalea.lpy's ParamModule.__getattr__ / __setattr__: a declared parameter by name,
        // anything else an attribute of the object.
        .def("__getattr__", [](PyParamModule& self, const std::string& n) -> py::object {
            if (positionInClass(self.get().cls, n) != kNoPos) return self.get().args[validParameterPosition(self.get(), n)];
            throw py::attribute_error("'ParamModule' object has no attribute '" + n + "'");
        })
        .def("__setattr__", [](py::object self, py::str n, py::object v) {
            PyParamModule& mod = py::cast<PyParamModule&>(self);
            if (positionInClass(mod.get().cls, n.cast<std::string>()) != kNoPos) {
                self.attr("setParameter")(n, v);
                return;
            }
            // L-Py's __mod_setattr__ writes self.__dict__: `m.args = ...`, `m.name = ...` leave
            // the module as it is.
            self.attr("__dict__")[n] = v;
        });
}

void defineParamModule(py::module_& m) {
    py::class_<PyParamModule, PyModule> c(m, "ParamModule", py::dynamic_attr());
    defineParamModuleInit(c);
    defineParamModuleArgs(c);
    defineParamModuleNames(c);
    c.def("__eq__", [](PyParamModule& a, py::object b) {
         if (py::isinstance<py::str>(b)) return nameOf(a.get().cls) == b.cast<std::string>();
         return py::isinstance<PyModule>(b) && sameModule(a.get(), py::cast<PyModule&>(b).get());
     })
        .def("__ne__", [](PyParamModule& a, py::object b) { return !py::cast(a).attr("__eq__")(b).cast<bool>(); })
        .def("__hash__", [](PyParamModule& self) { return py::hash(py::str(nameOf(self.get().cls))); })
        .def("__copy__", [](PyParamModule& self) { return made(self.get()); })
        .def(py::pickle([](PyParamModule& self) { return stateOf({self.get()}); },
                        [](py::list state) {
                            LString s = fromState(state);
                            if (s.size() != 1) throw py::value_error("not a pickled module");
                            return made(s[0]);
                        }));
}

//-----------------------------------------------------------------------------
// [SECTION] NodeModule
//-----------------------------------------------------------------------------
py::object nodeAt(const PyModule& self, long i) {
    if (i < 0 || !self.owner) return py::none();
    PyNodeModule n;
    n.owner = self.owner;
    n.index = size_t(i);
    n.detached = true;
    n.own = (*self.owner)[n.index];
    return py::cast(std::move(n));
}

py::object nodesOrNone(const PyModule& self, const std::vector<long>& at) {
    if (at.empty()) return py::none();
    py::list out;
    for (long i : at) out.append(nodeAt(self, i));
    return out;
}

// A module bound in its string (`$A(a)`, AxialTree.node(i)): its place and its tree.
void defineNodeModule(py::module_& m) {
    using N = PyNodeModule;
    py::class_<N, PyParamModule> node(m, "NodeModule", py::dynamic_attr());
    node.def("position", [](N& self) -> py::object { return self.owner ? py::object(py::int_(self.index)) : py::object(py::none()); })
        .def("isValid", [](N& self) { return bool(self.owner); })
        .def("isRoot", [](N& self) { return self.owner && parentOf(*self.owner, self.index) < 0; })
        .def("parent", [](N& self) { return nodeAt(self, self.owner ? parentOf(*self.owner, self.index) : -1); })
        .def("direct_child", [](N& self) { return nodeAt(self, self.owner ? directSonOf(*self.owner, self.index) : -1); })
        .def("children", [](N& self) { return nodesOrNone(self, self.owner ? childrenOf(*self.owner, self.index) : std::vector<long>{}); })
        .def("lateral_children", [](N& self) {
            return nodesOrNone(self, self.owner ? lateralSonsOf(*self.owner, self.index) : std::vector<long>{});
        })
        .def("complex", [](N& self) {
            if (!self.owner) return py::object(py::none());
            const Scale sc = scales();
            return nodeAt(self, complexOf(*self.owner, self.index, sc((*self.owner)[self.index].cls) + 1, sc));
        })
        .def("complex", [](N& self, int scale) { return nodeAt(self, self.owner ? complexOf(*self.owner, self.index, scale, scales()) : -1); })
        .def("components", [](N& self) { return nodesOrNone(self, self.owner ? componentsOf(*self.owner, self.index, scales()) : std::vector<long>{}); })
        .def("components_at_scale", [](N& self, int scale) {
            return nodesOrNone(self, self.owner ? componentsOf(*self.owner, self.index, scales(), &scale) : std::vector<long>{});
        });
    // Pickled, it keeps its module (not its place).
    node.def(py::pickle([](N& self) { return stateOf({self.get()}); },
                        [](py::list state) {
                            LString s = fromState(state);
                            if (s.size() != 1) throw py::value_error("not a pickled module");
                            N out;
                            out.own = s[0];
                            return out;
                        }));
    // L-Py's deprecated names (openalea/lpy/__init__.py).
    py::object cls = m.attr("NodeModule");
    cls.attr("father") = cls.attr("parent");
    cls.attr("sons") = cls.attr("children");
    cls.attr("lateralSons") = cls.attr("lateral_children");
    cls.attr("directSon") = cls.attr("direct_child");
}

}  // namespace

void defineModules(py::module_& m) {
    defineModule(m);
    defineParamModule(m);
    defineNodeModule(m);
}

}  // namespace sprout::lpy::types
