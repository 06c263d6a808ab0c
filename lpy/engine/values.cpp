// Python's values in and out of L-Py's strings (lpy/engine/engine.hpp): what a rule's body or the
// axiom gives (produce, nproduce, a returned list, Lstrings, modules and module classes made in
// Python) made into modules, an Lstring's text read with its arguments evaluated in the
// model's namespace, and strings written as text (`sprout expand`) as Python writes them.
#include <charconv>
#include <cmath>
#include <string_view>

#include "core/language/module_string.hpp"
#include "lpy/engine/engine.hpp"

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

void appendPythonFloat(std::string& out, double v) {
    if (std::isnan(v)) {
        out += "nan";
        return;
    }
    if (std::isinf(v)) {
        out += v < 0 ? "-inf" : "inf";
        return;
    }
    // The shortest digits that round-trip, as d.ddde±x; then Python's layout (its
    // format_float_short, mode 'r'): value = 0.DIGITS x 10^point.
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    std::string_view sci(buf, size_t(r.ptr - buf));
    const size_t e = sci.find('e');
    std::string digits;
    bool negative = false;
    for (char c : sci.substr(0, e)) {
        if (c == '-') negative = true;
        else if (c != '.') digits += c;
    }
    int exponent = 0;
    std::from_chars(sci.data() + e + 1 + (sci[e + 1] == '+'), sci.data() + sci.size(), exponent);
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    const int point = exponent + 1, n = int(digits.size());
    if (negative) out += '-';
    if (point <= -4 || point > 16) {
        out += digits[0];
        if (n > 1) out += '.', out.append(digits, 1, std::string::npos);
        const int x = point - 1;
        out += x < 0 ? "e-" : "e+";
        if (std::abs(x) < 10) out += '0';
        out += std::to_string(std::abs(x));
    } else if (point <= 0) {
        out += "0.";
        out.append(size_t(-point), '0');
        out += digits;
    } else if (point >= n) {
        out += digits;
        out.append(size_t(point - n), '0');
        out += ".0";
    } else {
        out.append(digits, 0, size_t(point));
        out += '.';
        out.append(digits, size_t(point), std::string::npos);
    }
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
            if (m.ints >> k & 1) out += std::to_string(static_cast<long long>(v[k]));
            else appendPythonFloat(out, v[k]);
        }
        v += m.n;
        out += ')';
    }
    return out;
}

std::string Engine::text(const LString& s) const { return writeLstring(s, m_tr.classes); }

std::string writeLstring(const LString& s, const ModuleClasses& classes, bool repr) {
    std::string out;
    for (const LModule& m : s) {
        out += m.cls >= 0 && size_t(m.cls) < classes.size() ? classes.name(m.cls) : std::string("?");
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        if (n == 0) continue;
        out += '(';
        for (Py_ssize_t k = 0; k < n; ++k) {
            if (k) out += ',';
            PyObject* v = PyTuple_GET_ITEM(m.args.ptr(), k);
            if (PyFloat_CheckExact(v)) {
                appendPythonFloat(out, PyFloat_AS_DOUBLE(v));
                continue;
            }
            if (PyLong_CheckExact(v)) {
                int overflow = 0;
                const long long i = PyLong_AsLongLongAndOverflow(v, &overflow);
                if (!overflow) {
                    out += std::to_string(i);
                    continue;
                }
            }
            out += (repr ? py::repr(v) : py::str(v)).cast<std::string>();
        }
        out += ')';
    }
    return out;
}

}  // namespace sprout::lpy
