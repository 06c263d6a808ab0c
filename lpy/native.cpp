// The native path of L-Py models (lpy/engine.hpp): rules written `A(x) --> B(x + 1) C`, whose
// bodies are only a successor with arithmetic, are compiled to Sprout's expressions and the
// model derives on plain numbers, without a Python call per match. A model takes this path
// only when every production is that simple and nothing else can see the string while it
// grows (no hooks, contexts, groups, queries, cuts, decomposition). Its string is a
// NumString: numbers in one array, drawn and written as they are (lpy/draw.hpp, `sprout
// expand`), and made into Python values (integral numbers as Python ints where Python has
// ints) only for a model whose interpretation rules or growth stepping read it in Python. A
// value that is not finite (a division by zero, which Python would raise) drops the native
// run: the model runs in Python from the start instead.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

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

constexpr int kMaxNativeArity = 32;  // NumString::Module::ints holds a bit per parameter
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
        if (nr.arity > kMaxNativeArity) return;
        for (const WrittenModule& w : rule.successor) {
            if (!w.variable.empty() || w.cls < 0 || w.cls == ModuleClasses::kCut || w.cls == ModuleClasses::kStar ||
                w.cls == ModuleClasses::kNone || Engine::isQuery(m_tr.classes.name(w.cls)) ||
                int(w.args.size()) > kMaxNativeArity)
                return;
            NativeOut out;
            out.cls = w.cls;
            for (const std::string& a : w.args) {
                NativeArg arg;
                std::vector<int> used;
                if (!plainArithmetic(a, names, arg.isFloat, used)) return;
                for (int u : used) arg.used |= 1u << u;
                SourceLine line{rule.line, a, {}};
                DiagnosticSink sink;
                ExprScope scope;
                scope.params = &names;
                auto e = compileExpr(a, line, scope, sink);
                if (!e || e->usesRandom()) return;
                arg.expr = std::move(*e);
                out.args.push_back(std::move(arg));
            }
            nr.params += std::uint32_t(out.args.size());
            nr.outs.push_back(std::move(out));
        }
        m_native.push_back(std::move(nr));
    }
    for (size_t k = 0; k < m_native.size(); ++k) m_nativeByClass[size_t(m_native[k].cls)].push_back(int(k));
    m_nativeOk = true;
}

LString Engine::toL(const NumString& s) {
    LString out;
    out.reserve(s.size());
    for (size_t k = 0; k < s.size(); ++k) {
        const NumString::Module& m = s.modules[k];
        py::tuple args(m.n);
        for (std::uint32_t a = 0; a < m.n; ++a) {
            const double v = s.params[m.first + a];
            PyObject* o = m.ints >> a & 1 ? PyLong_FromDouble(v) : PyFloat_FromDouble(v);
            if (!o) throw py::error_already_set();
            PyTuple_SET_ITEM(args.ptr(), a, o);
        }
        LModule lm{m.cls, m.n ? std::move(args) : py::tuple()};
        if (k < s.origins.size()) lm.rule = s.origins[k].rule, lm.parent = s.origins[k].parent;
        out.push_back(std::move(lm));
    }
    return out;
}

const Engine::NativeRule* Engine::nativeRule(int cls, std::uint32_t arity) const {
    if (size_t(cls) >= m_nativeByClass.size()) return nullptr;
    for (int r : m_nativeByClass[size_t(cls)])
        if (std::uint32_t(m_native[size_t(r)].arity) == arity) return &m_native[size_t(r)];
    return nullptr;
}

bool Engine::deriveNumbers(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result,
                           bool origins) {
    NumString cur, next;
    for (size_t k = 0; k < axiom.size(); ++k) {
        const LModule& m = axiom[k];
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        NumString::Module nm{m.cls, std::uint32_t(cur.params.size()), std::uint32_t(n), 0};
        if (origins) cur.origins.push_back({-1, std::uint32_t(k)});
        for (Py_ssize_t a = 0; a < n; ++a) {
            double v = 0;
            bool isInt = false;
            if (a >= kMaxNativeArity || !numberOf(PyTuple_GET_ITEM(m.args.ptr(), a), v, isInt)) {
                m_nativeOk = false;
                return false;
            }
            cur.params.push_back(v);
            nm.ints |= std::uint32_t(isInt) << a;
        }
        cur.modules.push_back(nm);
    }
    if (everyStep) everyStep->push_back(cur);
    Rng rng(0);
    for (int i = 0; i < steps; ++i) {
        checkCancel();
        iteration = i;
        const size_t count = cur.size();
        const NumString::Module* from = cur.modules.data();
        // The new string's size first, so that it is written in place once.
        size_t modules = 0, params = 0;
        for (size_t j = 0; j < count; ++j) {
            if (const NativeRule* hit = nativeRule(from[j].cls, from[j].n)) {
                modules += hit->outs.size();
                params += hit->params;
            } else {
                modules += 1;
                params += from[j].n;
            }
        }
        if (modules > m_options.maxModules)
            throw py::value_error("the string grew past " + std::to_string(m_options.maxModules) + " modules");
        if (params > std::numeric_limits<std::uint32_t>::max()) throw py::value_error("the string holds too many numbers");
        next.modules.clear();  // nothing of it is kept: not copied when it grows
        next.params.clear();
        next.origins.clear();
        next.modules.resizeUninitialized(modules);
        next.params.resizeUninitialized(params);
        if (origins) next.origins.resizeUninitialized(modules);
        NumString::Origin* origin = next.origins.data();
        NumString::Module* out = next.modules.data();
        double* values = next.params.data();
        std::uint32_t at = 0;
        for (size_t j = 0; j < count; ++j) {
            if ((j & 16383) == 0) checkCancel();
            const NumString::Module m = from[j];
            const double* in = cur.params.data() + m.first;
            const NativeRule* hit = nativeRule(m.cls, m.n);
            if (!hit) {
                *out++ = {m.cls, at, m.n, m.ints};
                if (origins) *origin++ = {-1, std::uint32_t(j)};
                for (std::uint32_t a = 0; a < m.n; ++a) values[at++] = in[a];
                continue;
            }
            for (const NativeOut& o : hit->outs) {
                NumString::Module made{o.cls, at, std::uint32_t(o.args.size()), 0};
                if (origins) *origin++ = {hit->index, std::uint32_t(j)};
                for (size_t a = 0; a < o.args.size(); ++a) {
                    const NativeArg& arg = o.args[a];
                    const double v = arg.expr.eval(in, rng);
                    const bool isInt = !arg.isFloat && (arg.used & ~m.ints) == 0;
                    // Python raises on a division by zero; its ints do not round past 2^53.
                    if (!std::isfinite(v) || (isInt && std::fabs(v) >= kExactInts)) {
                        m_nativeOk = false;
                        if (everyStep) everyStep->clear();
                        return false;
                    }
                    values[at++] = v;
                    made.ints |= std::uint32_t(isInt) << a;
                }
                *out++ = made;
            }
        }
        cur.swap(next);
        if (everyStep) everyStep->push_back(cur);
    }
    iteration = std::max(0, steps - 1);
    ranNative = true;
    result = std::move(cur);
    return true;
}

}  // namespace sprout::lpy
