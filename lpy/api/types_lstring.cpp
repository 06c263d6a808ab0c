// L-Py's strings in Python (src/wrapper/export_axialtree.cpp, export_lstring.h; src/cpp/
// abstractlstring.h, axialtree.cpp, axialtree_iter.h): AxialTree (the string of modules every
// derivation gives), Lstring (the one a script makes), AxialTreeIterator. Positions as L-Py
// reads them: an index past the string an IndexError, a slice's ends folded into it, a
// position with nothing there None. The patterns (match, find with a PatternModule, replace)
// are openalea.lpy's Python (lpy/api/lpy_strings.py).

// Index of this file:
//   [SECTION] positions
//   [SECTION] the axial tree
//   [SECTION] AxialTree
//   [SECTION] AxialTreeIterator

#include <pybind11/stl.h>

#include <climits>

#include "lpy/api/types_impl.hpp"
#include "lpy/interpreter/interpreter.hpp"

namespace sprout::lpy::types {
namespace {

using namespace tree;

//-----------------------------------------------------------------------------
// [SECTION] positions
//-----------------------------------------------------------------------------
// int_to_iter: a position in the string (its end included), negative from the end.
size_t position(const LString& s, long i) {
    const long n = long(s.size());
    if (i == INT_MAX) return s.size();
    if (i < 0) i += n;
    if (i < 0 || i > n) throw py::index_error("index out of range");
    return size_t(i);
}

// getValidIndex: a module of the string.
size_t checkedIndex(const LString& s, py::ssize_t i) {
    const py::ssize_t n = py::ssize_t(s.size());
    if (i < 0) i += n;
    if (i < 0 || i >= n) throw py::index_error("index out of range");
    return size_t(i);
}

// normedindex: a slice's ends (no step) folded into the string; `checked`: then
// getValidIndices's checks (a deletion's), else none (getRange's; an end before the start is
// the error of L-Py's std::deque).
std::pair<size_t, size_t> sliceRange(const LString& s, const py::slice& sl, bool checked = true) {
    const long n = long(s.size());
    auto normed = [n](py::object v, bool start) {
        long i = v.is_none() ? (start ? 0 : n) : v.cast<long>();
        while (i < 0 && n > 0) i += n;
        while (i > n && n > 0) i -= n;
        return i;
    };
    long i = normed(sl.attr("start"), true), j = normed(sl.attr("stop"), false);
    if (!checked) {
        if (j < i) throw std::runtime_error("cannot create std::deque larger than max_size()");
        return {size_t(i), size_t(j)};
    }
    if (i < 0) i += n;
    if (j < 0) j += n;
    if (j > n) j = n;
    if (i < 0 || i >= n || j < i) throw py::index_error("index out of range");
    return {size_t(i), size_t(j)};
}

// The members of multiscale strings read no ConsiderFilter in Sprout: one given is refused.
void noFilter(const py::object& filter, const char* member) {
    if (!filter.is_none())
        throw py::value_error(std::string("AxialTree.") + member + ": Sprout reads no ConsiderFilter here (give none)");
}

py::object indexOrNone(long i) { return i < 0 ? py::object(py::none()) : py::object(py::int_(i)); }

// veciter_to_list: none, one position, or a list of them.
py::object positions(const std::vector<long>& v) {
    if (v.empty()) return py::none();
    if (v.size() == 1) return py::int_(v[0]);
    py::list out;
    for (long i : v) out.append(i);
    return out;
}

PyLstring fresh(LString s = {}) { return PyLstring{std::make_shared<LString>(std::move(s))}; }

// What append, prepend, insertAt and + take: text, a module, a tuple ('A', 1), an AxialTree.
LString itemsOf(py::handle v) {
    LString out;
    if (py::isinstance<py::tuple>(v)) out.push_back(oneModule(v));
    else extend(out, v);
    return out;
}

bool isBracket(const LModule& m) { return isPush(m) || isPop(m) || nameOf(m.cls) == "=]"; }

std::vector<long> rootsOf(const LString& s) {
    std::vector<long> out;
    if (s.empty() || isPop(s[0])) return out;
    if (!isPush(s[0])) return {0};
    size_t i = 0;
    while (i < s.size() && isBracket(s[i])) {
        while (i < s.size() && isPush(s[i])) {
            for (long c : childrenOf(s, i)) out.push_back(c);
            long depth = 0;
            size_t j = i + 1;  // endBracket
            for (; j < s.size() && (depth > 0 || !isPop(s[j])); ++j) depth += isPush(s[j]) ? 1 : isPop(s[j]) ? -1 : 0;
            if (j >= s.size()) return out;
            i = j + 1;
        }
        if (i < s.size() && isPop(s[i])) break;
    }
    if (i < s.size() && !isPop(s[i])) out.push_back(long(i));
    return out;
}

//-----------------------------------------------------------------------------
// [SECTION] the axial tree
//-----------------------------------------------------------------------------
long endBracket(const LString& s, size_t pos, bool startingBeforePos) {
    if (pos >= s.size()) return -1;
    if (!startingBeforePos && isPush(s[pos])) ++pos;
    long depth = 0;
    while (pos < s.size() && (depth > 0 || !isPop(s[pos]))) {
        if (isPush(s[pos])) ++depth;
        else if (isPop(s[pos])) --depth;
        ++pos;
    }
    return pos < s.size() ? long(pos) : -1;
}

long beginBracket(const LString& s, size_t pos, bool startingAfterPos) {
    if (pos < s.size() && isPush(s[pos])) return long(pos);
    if (pos == 0) return -1;
    if (pos == s.size()) --pos;
    else if (!startingAfterPos && isPop(s[pos])) --pos;
    long depth = 0;
    while (pos > 0 && (depth > 0 || !isPush(s[pos]))) {
        if (isPop(s[pos])) ++depth;
        else if (isPush(s[pos])) --depth;
        --pos;
    }
    if (pos == 0) return depth == 0 && isPush(s[0]) ? 0 : -1;
    return long(pos);
}

// The tree's members: parents, children, brackets, complexes and components, successors and
// predecessors at a scale (or a level).
void defineTree(py::class_<PyLstring>& c) {
    using S = const PyLstring&;
    c.def("roots", [](S s, py::object) { return positions(rootsOf(s.get())); }, py::arg("filter") = py::none())
        .def("parent", [](S s, long i, py::object) { return indexOrNone(parentOf(s.get(), checkedIndex(s.get(), i))); },
             py::arg("pos"), py::arg("filter") = py::none())
        // children(pos[, filter]), children(pos, edge_type[, filter]): '<' the direct child,
        // '+' the lateral ones.
        .def("children", [](S s, long i, py::object edge, py::object) {
            const size_t at = checkedIndex(s.get(), i);
            if (!py::isinstance<py::str>(edge)) return positions(childrenOf(s.get(), at));
            const std::string e = edge.cast<std::string>();
            if (e == "<") return indexOrNone(directSonOf(s.get(), at));
            if (e == "+") return positions(lateralSonsOf(s.get(), at));
            throw py::value_error("invalid edge type");
        }, py::arg("pos"), py::arg("edge_type") = py::none(), py::arg("filter") = py::none())
        .def("lateral_children", [](S s, long i, py::object) { return positions(lateralSonsOf(s.get(), checkedIndex(s.get(), i))); },
             py::arg("pos"), py::arg("filter") = py::none())
        .def("direct_child", [](S s, long i, py::object) { return indexOrNone(directSonOf(s.get(), checkedIndex(s.get(), i))); },
             py::arg("pos"), py::arg("filter") = py::none())
        .def("endBracket", [](S s, long i, bool before) { return indexOrNone(endBracket(s.get(), position(s.get(), i), before)); },
             py::arg("pos"), py::arg("startingBeforePos") = false)
        .def("beginBracket", [](S s, long i, bool after) { return indexOrNone(beginBracket(s.get(), position(s.get(), i), after)); },
             py::arg("pos"), py::arg("startingAfterPos") = false)
        .def("complex", [](S s, long i, py::object scale) {
            const size_t at = checkedIndex(s.get(), i);
            const Scale sc = scales();
            return indexOrNone(complexOf(s.get(), at, scale.is_none() ? sc(s.get()[at].cls) + 1 : scale.cast<int>(), sc));
        }, py::arg("pos"), py::arg("scale") = py::none())
        .def("components", [](S s, long i, py::object filter) {
            noFilter(filter, "components");
            return positions(componentsOf(s.get(), checkedIndex(s.get(), i), scales()));
        }, py::arg("pos"), py::arg("filter") = py::none())
        .def("components_at_scale", [](S s, long i, int scale, py::object filter) {
            noFilter(filter, "components_at_scale");
            return positions(componentsOf(s.get(), checkedIndex(s.get(), i), scales(), &scale));
        }, py::arg("pos"), py::arg("scale"), py::arg("filter") = py::none())
        .def("successor_at_scale", [](S s, long i, int scale, py::object filter) {
            noFilter(filter, "successor_at_scale");
            return indexOrNone(successorAtScale(s.get(), checkedIndex(s.get(), i), scale, scales()));
        }, py::arg("pos"), py::arg("scale"), py::arg("filter") = py::none())
        .def("predecessor_at_scale", [](S s, long i, int scale, py::object filter) {
            noFilter(filter, "predecessor_at_scale");
            return indexOrNone(predecessorAtScale(s.get(), checkedIndex(s.get(), i), scale, scales()));
        }, py::arg("pos"), py::arg("scale"), py::arg("filter") = py::none())
        .def("successor_at_level", [](S s, long i, int scale, py::object filter) {
            noFilter(filter, "successor_at_level");
            return indexOrNone(successorAtLevel(s.get(), checkedIndex(s.get(), i), scale, scales()));
        }, py::arg("pos"), py::arg("level"), py::arg("filter") = py::none())
        .def("predecessor_at_level", [](S s, long i, int scale, py::object filter) {
            noFilter(filter, "predecessor_at_level");
            return indexOrNone(predecessorAtLevel(s.get(), checkedIndex(s.get(), i), scale, scales()));
        }, py::arg("pos"), py::arg("level"), py::arg("filter") = py::none())
        .def("node", [](S s, long i) {
            PyNodeModule n;
            n.owner = s.s;
            s.get();
            n.index = position(s.get(), i);
            if (n.index >= s.get().size()) throw py::index_error("index out of range");
            n.detached = true;  // a copy of the module, as L-Py's NodeModule::generate makes
            n.own = s.get()[n.index];
            return n;
        });
}

//-----------------------------------------------------------------------------
// [SECTION] AxialTree
//-----------------------------------------------------------------------------
void defineEditing(py::class_<PyLstring>& c) {
    using S = const PyLstring&;
    c.def("__getitem__", [](S s, py::ssize_t i) {
         const size_t at = checkedIndex(s.get(), i);
         return viewOf(s.s, at);
     })
        .def("__getitem__", [](S s, const py::slice& sl) {
            auto [i, j] = sliceRange(s.get(), sl, false);
            return fresh(LString(s.get().begin() + std::ptrdiff_t(i), s.get().begin() + std::ptrdiff_t(j)));
        })
        .def("__setitem__", [](S s, py::ssize_t i, py::object v) { s.get()[checkedIndex(s.get(), i)] = oneModule(v); })
        .def("__delitem__", [](S s, py::ssize_t i) { s.get().erase(s.get().begin() + std::ptrdiff_t(checkedIndex(s.get(), i))); })
        .def("__delitem__", [](S s, const py::slice& sl) {
            auto [i, j] = sliceRange(s.get(), sl);
            s.get().erase(s.get().begin() + std::ptrdiff_t(i), s.get().begin() + std::ptrdiff_t(j));
        })
        .def("append", [](S s, py::object v) {
            LString items = itemsOf(v);
            s.get().insert(s.get().end(), items.begin(), items.end());
        })
        .def("prepend", [](S s, py::object v) {
            LString items = itemsOf(v);
            s.get().insert(s.get().begin(), items.begin(), items.end());
        })
        // insertItemAt: before a module of the string (not at its end); L-Py's insertAt with a
        // tuple sets the module there instead (py_insert_ax_tuple calls setItemAt).
        .def("insertAt", [](S s, py::ssize_t i, py::object v) {
            const size_t at = checkedIndex(s.get(), i);
            if (py::isinstance<py::tuple>(v)) {
                s.get()[at] = oneModule(v);
                return;
            }
            LString items = itemsOf(v);
            s.get().insert(s.get().begin() + std::ptrdiff_t(at), items.begin(), items.end());
        })
        .def("__iadd__", [](PyLstring& s, py::object v) {
            LString items = itemsOf(v);
            s.get().insert(s.get().end(), items.begin(), items.end());
            return s;
        })
        .def("__add__", [](S s, py::object v) {
            PyLstring out = fresh(s.get());
            LString items = itemsOf(v);
            out.get().insert(out.get().end(), items.begin(), items.end());
            return out;
        })
        .def("__mul__", [](S s, int times) {
            PyLstring out = fresh();
            for (int k = 0; k < times; ++k) out.get().insert(out.get().end(), s.get().begin(), s.get().end());
            return out;
        })
        .def("__imul__", [](PyLstring& s, int times) {
            const LString once = s.get();
            s.get().clear();
            for (int k = 0; k < times; ++k) s.get().insert(s.get().end(), once.begin(), once.end());
            return s;
        })
        .def("clear", [](S s) { s.get().clear(); })
        .def("reverse", [](S s) { std::reverse(s.get().begin(), s.get().end()); });
}

void defineReading(py::class_<PyLstring>& c) {
    using S = const PyLstring&;
    auto size = [](S s) { return s.size(); };
    c.def("__len__", size)
        .def("argSize", size)
        .def("__bool__", [](S s) { return s.size() != 0; })
        .def("empty", [](S s) { return s.size() == 0; })
        // L-Py compares an AxialTree with another or with text: the same modules, equal
        // parameters.
        .def("__eq__", [](S s, py::object v) {
            if (!py::isinstance<PyLstring>(v) && !py::isinstance<py::str>(v)) return false;
            LString other;
            try {
                other = itemsOf(v);
            } catch (const std::exception&) {
                return false;  // a text that is no lstring
            }
            if (other.size() != s.get().size()) return false;
            for (size_t k = 0; k < other.size(); ++k)
                if (!sameModule(s.get()[k], other[k])) return false;
            return true;
        })
        .def("__ne__", [](py::object s, py::object v) { return !s.attr("__eq__")(v).cast<bool>(); })
        .def("wellBracketed", [](S s) {
            long depth = 0;
            for (const LModule& m : s.get()) {
                depth += isPush(m) ? 1 : isPop(m) ? -1 : 0;
                if (depth < 0) return false;
            }
            return depth == 0;
        })
        .def("isAPath", [](S s) { return std::none_of(s.get().begin(), s.get().end(), isBracket); })
        .def("hasRequestModule", [](S s) { return std::any_of(s.get().begin(), s.get().end(), [](const LModule& m) { return isRequest(m.cls); }); })
        // count('A'): the modules named A; count('A', n): with n parameters; count(module):
        // its name and number of parameters.
        .def("count", [](S s, const std::string& name) {
            return std::count_if(s.get().begin(), s.get().end(), [&](const LModule& m) { return nameOf(m.cls) == name; });
        })
        .def("count", [](S s, const std::string& name, size_t n) {
            return std::count_if(s.get().begin(), s.get().end(), [&](const LModule& m) {
                return nameOf(m.cls) == name && size_t(m.args ? py::len(m.args) : 0) == n;
            });
        })
        .def("count", [](S s, PyModule& mod) {
            const LModule& one = mod.get();
            const size_t n = one.args ? py::len(one.args) : 0;
            return std::count_if(s.get().begin(), s.get().end(), [&](const LModule& m) {
                return m.cls == one.cls && size_t(m.args ? py::len(m.args) : 0) == n;
            });
        })
        // find('C', start, end): the first module named C, or None.
        .def("find", [](S s, const std::string& name, long start, long end) {
            const size_t a = position(s.get(), start), b = position(s.get(), end);
            for (size_t i = a; i < b; ++i)
                if (nameOf(s.get()[i].cls) == name) return py::object(py::int_(i));
            return py::object(py::none());
        }, py::arg("pattern"), py::arg("start") = 0, py::arg("end") = INT_MAX)
        .def("str_slice", [](S s, long beg, long end) {
            const long n = long(s.size());
            if (beg < 0) beg += n;
            if (end < 0) end += n;
            if (end > n) end = n;
            if (beg < 0 || beg >= n || end < beg) throw py::index_error("index out of range");
            return writeLstring(LString(s.get().begin() + beg, s.get().begin() + end), names());
        })
        .def("__copy__", [](S s) { return fresh(s.get()); })
        .def("__deepcopy__", [](S s, py::object) { return fresh(s.get()); })
        .def(py::pickle([](S s) { return stateOf(s.get()); }, [](py::list state) { return fresh(fromState(state)); }))
        .def("__str__", [](S s) { return writeLstring(s.get(), names()); })
        .def("__repr__", [](S s) { return "AxialTree(" + writeLstring(s.get(), names(), true) + ")"; });  // as L-Py writes it
}

// What AxialTree(...) takes: nothing, text, a module, a list of modules, a tuple ('A', 1), an
// AxialTree.
PyLstring made(py::handle v) { return fresh(v.is_none() ? LString{} : itemsOf(v)); }

//-----------------------------------------------------------------------------
// [SECTION] AxialTreeIterator
//-----------------------------------------------------------------------------
// L-Py's PyLstringIterator: the modules of a string one by one (to its end: L-Py's iterator
// means to stop at a ']' closing the branch it started in, and does not).
struct TreeIterator {
    std::shared_ptr<LString> s;
    size_t current = 0, end = 0;
    bool started = false;

    PyParamModule processNext() { return viewOf(s, current); }
    PyParamModule next(bool) {
        if (current >= end) throw py::stop_iteration();
        if (started) {
            if (++current >= end) throw py::stop_iteration();
        } else {
            started = true;
        }
        return processNext();
    }
};

void defineIterator(py::module_& m) {
    py::class_<TreeIterator>(m, "AxialTreeIterator")
        .def(py::init([](const PyLstring& s) {
            s.get();
            return TreeIterator{s.s, 0, s.size()};
        }))
        .def("next", &TreeIterator::next, py::arg("onlyConsidered") = false)
        .def("__next__", &TreeIterator::next, py::arg("onlyConsidered") = false)
        .def("current", [](TreeIterator& it) {
            if (it.current >= it.end) throw py::index_error("");
            return viewOf(it.s, it.current);
        })
        .def("__length_hint__", [](TreeIterator& it) { return it.end - it.current; })
        .def("__iter__", [](TreeIterator& it) { return it; })
        .def("toEndBracket", [](TreeIterator& it, bool before) {
            if (it.current >= it.end) throw py::stop_iteration();
            const long e = endBracket(*it.s, it.current, before);
            it.current = e < 0 ? it.s->size() : size_t(e);
            if (it.current >= it.end) throw py::index_error("");
            return it.processNext();
        }, py::arg("startingBeforePos") = false);
}

}  // namespace

void defineLstrings(py::module_& m) {
    py::class_<PyLstring> tree(m, "AxialTree");
    tree.def(py::init([] { return fresh(); })).def(py::init([](py::object v) { return made(v); }));
    defineEditing(tree);
    defineReading(tree);
    defineTree(tree);
    tree.def("__iter__", [](const PyLstring& s) {
        s.get();
        return TreeIterator{s.s, 0, s.size()};
    });
    defineIterator(m);
    // L-Py's Lstring (openalea/lpy/__init__.py): an AxialTree made in the context given.
    py::class_<PyLstringMade, PyLstring>(m, "Lstring")
        .def(py::init([](py::object input, py::object context) {
            if (!context.is_none()) context.attr("makeCurrent")();
            PyLstringMade out;
            out.s = std::make_shared<LString>(input.is_none() || !py::bool_(input) ? LString{} : itemsOf(input));
            return out;
        }), py::arg("input") = py::none(), py::arg("lsyscontext") = py::none())
        .def(py::pickle([](const PyLstringMade& s) { return stateOf(s.get()); },
                        [](py::list state) {
                            PyLstringMade out;
                            out.s = std::make_shared<LString>(fromState(state));
                            return out;
                        }));
    // Sprout's own Python reads and makes AxialTrees under the old name.
    m.attr("_Lstring") = m.attr("Lstring");
    m.attr("Lstring") = m.attr("AxialTree");
    // L-Py's deprecated names (openalea/lpy/__init__.py).
    py::object cls = m.attr("AxialTree");
    cls.attr("father") = cls.attr("parent");
    cls.attr("sons") = cls.attr("children");
    cls.attr("lateralSons") = cls.attr("lateral_children");
    cls.attr("directSon") = cls.attr("direct_child");
}

}  // namespace sprout::lpy::types
