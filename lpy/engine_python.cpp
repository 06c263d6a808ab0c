// Python's values in and out of L-Py's strings (lpy/engine.hpp): what a rule's body or the
// axiom gives (produce, nproduce, a returned list, Lstrings, modules and module classes made in
// Python) made into modules, an Lstring's text read with its arguments evaluated in the
// model's namespace, and strings written as text (`sprout expand`) as Python writes them.
#include "core/language/module_string.hpp"
#include "lpy/engine.hpp"

namespace sprout::lpy {

LString& PyLstring::get() const {
    if (pending) {
        *s = Engine::toL(*pending);
        pending.reset();
    }
    return *s;
}

size_t PyLstring::size() const { return pending ? pending->size() : s->size(); }

LString Engine::parse(std::string_view text) { return parseLstring(text, m_tr.classes, m_ns); }

LString parseLstring(std::string_view text, ModuleClasses& classes, py::handle ns) {
    std::vector<Diagnostic> diags;
    LString out;
    for (const auto& w : readLstring(text, classes, 0, 1, diags)) {
        LModule m;
        m.cls = w.cls;
        if (!w.args.empty()) {
            py::list args;
            for (const auto& a : w.args)
                args.append(py::reinterpret_steal<py::object>(PyRun_String(a.c_str(), Py_eval_input, ns.ptr(), ns.ptr())));
            if (PyErr_Occurred()) throw py::error_already_set();
            m.args = py::tuple(args);
        }
        if (w.cls >= 0) out.push_back(std::move(m));
    }
    if (!diags.empty()) throw py::value_error(diags[0].message);
    return out;
}

LString Engine::axiom() {
    LString out;
    if (m_tr.axiomIsBlock) {
        m_buffer.clear();
        py::object ret = m_ns["__axiom_block__"]();
        out = std::move(m_buffer);
        if (!ret.is_none()) append(out, ret);
        return out;
    }
    if (m_ns.contains("__axiom__")) append(out, m_ns["__axiom__"]);
    return out;
}

void Engine::append(LString& out, py::handle item) { appendValue(out, item, m_tr.classes.size()); }

void appendValue(LString& out, py::handle item, size_t classCount) {
    if (PyLong_Check(item.ptr())) {
        const long cls = PyLong_AsLong(item.ptr());
        if (cls < 0 || size_t(cls) >= classCount) throw py::value_error("produce: not a module");
        out.push_back({int(cls), py::tuple()});
        return;
    }
    if (PyTuple_Check(item.ptr()) && PyTuple_GET_SIZE(item.ptr()) == 2 && PyLong_Check(PyTuple_GET_ITEM(item.ptr(), 0))) {
        const long cls = PyLong_AsLong(PyTuple_GET_ITEM(item.ptr(), 0));
        py::handle args = PyTuple_GET_ITEM(item.ptr(), 1);
        if (cls < 0 || size_t(cls) >= classCount || !PyTuple_Check(args.ptr())) throw py::value_error("produce: not a module");
        // `A(*xs)`: a sequence given last is unpacked (the translation cannot tell).
        out.push_back({int(cls), py::reinterpret_borrow<py::tuple>(args)});
        return;
    }
    if (PyList_Check(item.ptr())) {
        for (py::handle h : py::reinterpret_borrow<py::list>(item)) appendValue(out, h, classCount);
        return;
    }
    if (item.is_none()) return;
    // Modules, module classes and Lstrings made in Python.
    if (py::isinstance<PyModule>(item)) {
        out.push_back(py::cast<PyModule&>(item).get());
        return;
    }
    if (py::isinstance<PyLstring>(item)) {
        const LString& s = py::cast<PyLstring&>(item).get();
        out.insert(out.end(), s.begin(), s.end());
        return;
    }
    if (py::isinstance<PyModuleClass>(item)) {
        out.push_back({py::cast<PyModuleClass&>(item).cls, py::tuple()});
        return;
    }
    throw py::type_error(std::string("produce: a ") + Py_TYPE(item.ptr())->tp_name + " is not a module (write a module name, $variable for a module held in a variable)");
}

void Engine::produce(py::handle items, bool last) {
    const size_t before = m_buffer.size();
    append(m_buffer, items);
    // `new('A', x)` (newmodule): a module whose name is its first argument.
    static thread_local int newClass = -2;
    if (newClass == -2 || newClass >= int(m_tr.classes.size())) newClass = m_tr.classes.find("new");
    for (size_t k = before; k < m_buffer.size() && newClass >= 0; ++k) {
        LModule& m = m_buffer[k];
        if (m.cls != newClass || !m.args || PyTuple_GET_SIZE(m.args.ptr()) == 0) continue;
        PyObject* name = PyTuple_GET_ITEM(m.args.ptr(), 0);
        if (!PyUnicode_Check(name)) throw py::type_error("new(name, ...): the name of the module to make, a string");
        m.cls = m_tr.classes.intern(py::reinterpret_borrow<py::str>(name).cast<std::string>());
        m.args = py::reinterpret_steal<py::tuple>(PyTuple_GetSlice(m.args.ptr(), 1, PyTuple_GET_SIZE(m.args.ptr())));
    }
    if (last) m_produced = true;
}

std::string Engine::text(const NumString& s) const {
    std::string out;
    const double* v = s.params.data();
    for (size_t j = 0; j < s.size(); ++j) {
        const NumString::Shape& m = s.shape(j);
        out += m_tr.classes.name(m.cls);
        if (m.n == 0) continue;
        out += '(';
        for (std::uint32_t k = 0; k < m.n; ++k) {
            if (k) out += ',';
            appendNumber(out, v[k]);
        }
        v += m.n;
        out += ')';
    }
    return out;
}

std::string Engine::text(const LString& s) const { return writeLstring(s, m_tr.classes); }

std::string writeLstring(const LString& s, const ModuleClasses& classes) {
    std::string out;
    for (const LModule& m : s) {
        out += m.cls >= 0 && size_t(m.cls) < classes.size() ? classes.name(m.cls) : std::string("?");
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        if (n == 0) continue;
        out += '(';
        for (Py_ssize_t k = 0; k < n; ++k) {
            if (k) out += ',';
            PyObject* v = PyTuple_GET_ITEM(m.args.ptr(), k);
            // Ints past 2^53 as Python writes them: a double would round them.
            bool smallInt = false;
            if (PyLong_Check(v) && !PyBool_Check(v)) {
                int overflow = 0;
                const long long i = PyLong_AsLongLongAndOverflow(v, &overflow);
                smallInt = !overflow && i > -(1ll << 53) && i < (1ll << 53);
            }
            if (PyFloat_Check(v) || smallInt) {
                appendNumber(out, PyFloat_Check(v) ? PyFloat_AS_DOUBLE(v) : PyLong_AsDouble(v));
            } else {
                out += py::repr(v).cast<std::string>();
            }
        }
        out += ')';
    }
    return out;
}

}  // namespace sprout::lpy
