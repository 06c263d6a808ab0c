// The native path of L-Py models (lpy/engine.hpp): rules written `A(x) --> B(x + 1) C`, whose
// bodies are only a successor with arithmetic, are compiled to Sprout's expressions and the
// model derives on plain numbers, without a Python call per match. A model takes this path
// only when every production is that simple and nothing else can see the string while it
// grows (no hooks, contexts, groups, queries, cuts, decomposition); its strings are handed
// back as L-Py strings (integral numbers as Python ints) for the interpretation rules, the
// drawing and `sprout expand`. A value that is not finite (a division by zero, which Python
// would raise) drops the native run: the model runs in Python from the start instead.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/base/rng.hpp"
#include "core/language/source.hpp"
#include "lpy/engine.hpp"

namespace sprout::lpy {
namespace {

// An argument Sprout's expressions compute exactly as Python does: numbers, the rule's
// parameters, + - * / and parentheses (no calls, no **, //, %, comparisons or other names).
// `isFloat`: Python gives a float whatever the parameters are (a '/' or a float literal);
// otherwise the result is an int exactly when every parameter in `used` is one.
bool plainArithmetic(std::string_view a, const std::vector<std::string>& names, bool& isFloat, std::vector<int>& used) {
    isFloat = a.find('/') != std::string_view::npos;
    used.clear();
    if (a.find("**") != std::string_view::npos || a.find("//") != std::string_view::npos) return false;
    size_t i = 0;
    bool any = false;
    while (i < a.size()) {
        const char c = a[i];
        if (c == ' ' || c == '\t' || c == '+' || c == '-' || c == '*' || c == '/' || c == '(' || c == ')') {
            ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
            while (i < a.size() && (std::isdigit(static_cast<unsigned char>(a[i])) || a[i] == '.')) isFloat |= a[i++] == '.';
            if (i < a.size() && (a[i] == 'e' || a[i] == 'E')) {
                isFloat = true;
                ++i;
                if (i < a.size() && (a[i] == '+' || a[i] == '-')) ++i;
                if (i >= a.size() || !std::isdigit(static_cast<unsigned char>(a[i]))) return false;
                while (i < a.size() && std::isdigit(static_cast<unsigned char>(a[i]))) ++i;
            }
            if (i < a.size() && (std::isalpha(static_cast<unsigned char>(a[i])) || a[i] == '_')) return false;  // 1j, 2L
            any = true;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            const size_t b = i;
            while (i < a.size() && (std::isalnum(static_cast<unsigned char>(a[i])) || a[i] == '_')) ++i;
            const auto at = std::find(names.begin(), names.end(), a.substr(b, i - b));
            if (at == names.end()) return false;
            used.push_back(int(at - names.begin()));
            size_t k = i;
            while (k < a.size() && a[k] == ' ') ++k;
            if (k < a.size() && a[k] == '(') return false;
            any = true;
        } else {
            return false;
        }
    }
    return any;
}

constexpr double kExactInts = 9007199254740992.0;  // 2^53: past it a double is not Python's int

// A Python number (not a bool), or nothing; `isInt` for an int (exact in a double).
bool numberOf(PyObject* v, double& out, bool& isInt) {
    if (PyBool_Check(v)) return false;
    isInt = PyLong_Check(v);
    if (PyFloat_Check(v)) out = PyFloat_AS_DOUBLE(v);
    else if (isInt) out = PyLong_AsDouble(v);
    else return false;
    if (PyErr_Occurred()) {
        PyErr_Clear();
        return false;
    }
    return std::isfinite(out) && (!isInt || std::fabs(out) < kExactInts);
}

}  // namespace

void Engine::prepareNative() {
    m_nativeOk = false;
    m_native.clear();
    m_nativeByClass.assign(m_tr.classes.size(), {});
    if (!m_options.native || m_queryRules || m_hasKind[int(RuleKind::Decomposition)]) return;
    for (const char* hook : {"Start", "End", "StartEach", "EndEach"})
        if (m_ns.contains(hook)) return;
    for (size_t r = 0; r < m_tr.rules.size(); ++r) {
        const Rule& rule = m_tr.rules[r];
        if (rule.kind == RuleKind::Interpretation) continue;  // run in Python on the result
        if (!rule.arrow || rule.group != 0 || rule.filter >= 0 || !rule.left.empty() || !rule.newLeft.empty() ||
            !rule.newRight.empty() || !rule.right.empty() || rule.pred.size() != 1)
            return;
        const PatternModule& p = rule.pred[0];
        if (p.cls == ModuleClasses::kStar || p.isRepeat() || !p.anyName.empty() || p.exactPop || p.cls < 0 ||
            size_t(p.cls) >= m_tr.classes.size())
            return;
        std::vector<std::string> names;
        for (const PatternArg& a : p.args) {
            if (a.kind != PatternArg::Kind::Bind) return;
            names.push_back(a.name);
        }
        NativeRule nr;
        nr.cls = p.cls;
        nr.arity = p.hasParens ? int(p.args.size()) : 0;
        nr.index = int(r);
        for (const WrittenModule& w : rule.successor) {
            if (!w.variable.empty() || w.cls < 0 || w.cls == ModuleClasses::kCut || w.cls == ModuleClasses::kStar ||
                w.cls == ModuleClasses::kNone || Engine::isQuery(m_tr.classes.name(w.cls)))
                return;
            NativeOut out;
            out.cls = w.cls;
            for (const std::string& a : w.args) {
                bool isFloat = false;
                std::vector<int> used;
                if (!plainArithmetic(a, names, isFloat, used)) return;
                out.isFloat.push_back(isFloat);
                out.used.push_back(std::move(used));
                SourceLine line{rule.line, a, {}};
                DiagnosticSink sink;
                ExprScope scope;
                scope.params = &names;
                auto e = compileExpr(a, line, scope, sink);
                if (!e || e->usesRandom()) return;
                out.args.push_back(std::move(*e));
            }
            nr.outs.push_back(std::move(out));
        }
        m_native.push_back(std::move(nr));
    }
    for (size_t k = 0; k < m_native.size(); ++k) m_nativeByClass[size_t(m_native[k].cls)].push_back(int(k));
    m_nativeOk = true;
}

bool Engine::deriveNative(const LString& axiom, int steps, std::vector<LString>* everyStep, LString& result) {
    struct M {
        int cls;
        std::uint32_t first;
        std::uint32_t n;
        std::int32_t rule;
        std::uint32_t parent;
    };
    std::vector<M> cur, next;
    // Each number with whether Python holds it as an int (ints stay ints through + - *).
    std::vector<double> par, npar;
    std::vector<std::uint8_t> ints, nints;
    for (size_t k = 0; k < axiom.size(); ++k) {
        const LModule& m = axiom[k];
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        cur.push_back({m.cls, std::uint32_t(par.size()), std::uint32_t(n), -1, std::uint32_t(k)});
        for (Py_ssize_t a = 0; a < n; ++a) {
            double v = 0;
            bool isInt = false;
            if (!numberOf(PyTuple_GET_ITEM(m.args.ptr(), a), v, isInt)) return false;
            par.push_back(v);
            ints.push_back(isInt);
        }
    }
    // Back to an L-Py string, each number as the int or float Python would hold.
    auto toL = [&](const std::vector<M>& s, const std::vector<double>& p, const std::vector<std::uint8_t>& isInt) {
        LString out;
        out.reserve(s.size());
        for (const M& m : s) {
            py::tuple args(m.n);
            for (std::uint32_t a = 0; a < m.n; ++a) {
                const double v = p[m.first + a];
                PyObject* o = isInt[m.first + a] ? PyLong_FromDouble(v) : PyFloat_FromDouble(v);
                if (!o) throw py::error_already_set();
                PyTuple_SET_ITEM(args.ptr(), a, o);
            }
            LModule lm{m.cls, m.n ? std::move(args) : py::tuple()};
            lm.rule = m.rule;
            lm.parent = m.parent;
            out.push_back(std::move(lm));
        }
        return out;
    };
    std::vector<LString> kept;
    if (everyStep) kept.push_back(axiom);
    Rng rng(0);
    for (int i = 0; i < steps; ++i) {
        checkCancel();
        iteration = i;
        next.clear();
        npar.clear();
        nints.clear();
        for (size_t j = 0; j < cur.size(); ++j) {
            if ((j & 4095) == 0) checkCancel();
            const M& m = cur[j];
            const NativeRule* hit = nullptr;
            for (int r : m_nativeByClass[size_t(m.cls)])
                if (std::uint32_t(m_native[size_t(r)].arity) == m.n) {
                    hit = &m_native[size_t(r)];
                    break;
                }
            if (!hit) {
                next.push_back({m.cls, std::uint32_t(npar.size()), m.n, -1, std::uint32_t(j)});
                npar.insert(npar.end(), par.begin() + m.first, par.begin() + m.first + m.n);
                nints.insert(nints.end(), ints.begin() + m.first, ints.begin() + m.first + m.n);
                continue;
            }
            for (const NativeOut& o : hit->outs) {
                const std::uint32_t first = std::uint32_t(npar.size());
                for (size_t a = 0; a < o.args.size(); ++a) {
                    const double v = o.args[a].eval(par.data() + m.first, rng);
                    bool isInt = !o.isFloat[a];
                    for (int u : o.used[a]) isInt = isInt && ints[m.first + std::uint32_t(u)];
                    // Python raises on a division by zero; its ints do not round past 2^53.
                    if (!std::isfinite(v) || (isInt && std::fabs(v) >= kExactInts)) return false;
                    npar.push_back(v);
                    nints.push_back(isInt);
                }
                next.push_back({o.cls, first, std::uint32_t(o.args.size()), hit->index, std::uint32_t(j)});
            }
            if (next.size() > m_options.maxModules) throw py::value_error("the string grew past " + std::to_string(m_options.maxModules) + " modules");
        }
        std::swap(cur, next);
        std::swap(par, npar);
        std::swap(ints, nints);
        if (everyStep) kept.push_back(toL(cur, par, ints));
    }
    iteration = std::max(0, steps - 1);
    result = everyStep ? kept.back() : toL(cur, par, ints);
    if (everyStep) *everyStep = std::move(kept);
    return true;
}

}  // namespace sprout::lpy
