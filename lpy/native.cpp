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
//
// How a step runs fast (lpy_bench: 17-21x the Python path before, 60-64x after):
// - rules whose arguments are all x * a + b of a parameter, or constants (Expr::affine), are
//   laid out flat per class and written by loops unrolled for up to 4 modules and 4 numbers;
// - those values are not checked one by one where no number of the string is big enough for
//   one of them to reach 2^53 (a pass over the numbers first);
// - room for the new string comes from an upper bound, not a pass that counts it;
// - steps of 8 k modules or more are shared with a second thread of the process's;
// - big buffers reuse the mappings of the last derivation (core/base/huge_pages.hpp).
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>

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
    m_nativeMaxOuts = 1;
    m_nativeMaxParams = 0;
    m_flatOuts.clear();
    m_flatArgs.clear();
    for (NativeRule& r : m_native) {
        m_nativeMaxOuts = std::max(m_nativeMaxOuts, std::uint32_t(r.outs.size()));
        m_nativeMaxParams = std::max(m_nativeMaxParams, r.params);
        r.firstOut = std::uint32_t(m_flatOuts.size());
        r.firstArg = std::uint32_t(m_flatArgs.size());
        for (const NativeOut& o : r.outs) {
            m_flatOuts.push_back({o.cls, std::uint32_t(o.args.size())});
            for (const NativeArg& a : o.args) m_flatArgs.push_back({&a.expr, a.used | (std::uint64_t(a.isFloat) << 32)});
        }
    }
    m_fastOuts.clear();
    m_fastArgs.clear();
    m_fastScale = m_fastShift = 0;
    for (NativeRule& r : m_native) {
        const std::uint32_t firstOut = std::uint32_t(m_fastOuts.size());
        std::vector<FastArg> args;
        double scale = 0, shift = 0;  // the largest |mul| and |add| of its arguments
        bool fast = r.params <= 64;   // its ints are one 64-bit word
        for (const NativeOut& o : r.outs) {
            const std::uint32_t n = std::uint32_t(o.args.size());
            m_fastOuts.push_back({o.cls, std::uint32_t(args.size()), n, n >= 32 ? ~0u : (1u << n) - 1});
            for (const NativeArg& a : o.args) {
                FastArg fa{1, -0.0, a.used | (std::uint64_t(a.isFloat) << 32), 0};
                std::uint16_t slot = 0;
                if (a.expr.isConstant()) {
                    // x * 0 + c is c for every finite x, but for c = -0. A rule without
                    // parameters has no x to read.
                    fa.mul = 0;
                    fa.add = a.expr.constantValue();
                    fast &= r.arity > 0 && !(fa.add == 0 && std::signbit(fa.add));
                } else {
                    fast &= a.expr.affine(slot, fa.mul, fa.add);
                    fa.slot = slot;
                }
                scale = std::max(scale, std::fabs(fa.mul));
                shift = std::max(shift, std::fabs(fa.add));
                args.push_back(fa);
            }
        }
        if (!fast) {
            m_fastOuts.resize(firstOut);
            continue;
        }
        r.fast = true;
        r.firstFastOut = firstOut;
        r.firstFastArg = std::uint32_t(m_fastArgs.size());
        m_fastArgs.insert(m_fastArgs.end(), args.begin(), args.end());
        m_fastScale = std::max(m_fastScale, scale);
        m_fastShift = std::max(m_fastShift, shift);
    }
    m_nativeClass.assign(m_tr.classes.size(), {});
    for (size_t c = 0; c < m_nativeByClass.size(); ++c) {
        const auto& rules = m_nativeByClass[c];
        NativeClass& k = m_nativeClass[c];
        k.many = rules.size() > 1;
        if (rules.size() != 1) continue;
        const NativeRule& r = m_native[size_t(rules[0])];
        k.rule = &r;
        k.arity = std::uint32_t(r.arity);
        if (r.fast) {
            k.fast = true;
            k.fastArgs = r.params;
            k.fastOuts = std::uint32_t(r.outs.size());
            k.firstFastArg = r.firstFastArg;
            k.firstFastOut = r.firstFastOut;
        }
    }
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
    if (size_t(cls) >= m_nativeClass.size()) return nullptr;
    const NativeClass& c = m_nativeClass[size_t(cls)];
    if (c.rule) return std::uint32_t(c.rule->arity) == arity ? c.rule : nullptr;
    if (c.many)
        for (int r : m_nativeByClass[size_t(cls)])
            if (std::uint32_t(m_native[size_t(r)].arity) == arity) return &m_native[size_t(r)];
    return nullptr;
}

namespace {

// A fast rule's numbers (N of them; N < 0: rule.args, in a loop) and whether each is an int.
template <int N, bool kChecked>
inline void fastValues(const Engine::FastArg* __restrict args, std::uint32_t count, const double* in, std::uint64_t notInt,
                       double* __restrict values, std::uint64_t& ints, bool& bad) {
    const std::uint32_t n = N < 0 ? count : std::uint32_t(N);
    for (std::uint32_t k = 0; k < n; ++k) {
        const Engine::FastArg& a = args[k];
        const double v = in[a.slot] * a.mul + a.add;
        const bool isInt = (a.need & notInt) == 0;
        if constexpr (kChecked) bad |= !(std::fabs(v) < (isInt ? kExactInts : std::numeric_limits<double>::infinity()));
        values[k] = v;
        ints |= std::uint64_t(isInt) << k;
    }
}

template <int N>
inline void fastModules(const Engine::FastOut* __restrict outs, std::uint32_t count, std::uint32_t at, std::uint64_t ints,
                        NumString::Module* __restrict out) {
    const std::uint32_t n = N < 0 ? count : std::uint32_t(N);
    for (std::uint32_t k = 0; k < n; ++k) {
        const Engine::FastOut& o = outs[k];
        out[k] = {o.cls, at + o.first, o.n, std::uint32_t(ints >> o.first) & o.mask};
    }
}

// A rule with arguments other than fast ones (Expr calls, always checked), out of the
// inner loop; false when a value is not one Python would give.
[[gnu::noinline]] bool generalRule(const Engine::NativeRule& hit, const Engine::Tables& t, const NumString::Module& m,
                                   const double* in, size_t j, Engine::NativeCursor& c) {
    Rng rng(0);  // the rules use no random numbers (prepareNative)
    bool bad = false;
    const Engine::FlatOut* o = t.flatOuts + hit.firstOut;
    const Engine::FlatOut* oEnd = o + hit.outs.size();
    const Engine::FlatArg* arg = t.flatArgs + hit.firstArg;
    const std::uint64_t notInt = ~std::uint64_t(m.ints);
    NumString::Module* out = c.out;
    double* values = c.values;
    std::uint32_t at = c.at;
    for (; o != oEnd; ++o) {
        const std::uint32_t n = o->n;
        std::uint32_t ints = 0;
        if (c.origin) *c.origin++ = {hit.index, std::uint32_t(j)};
        for (std::uint32_t a = 0; a < n; ++a, ++arg) {
            const double v = arg->expr->eval(in, rng);
            const bool isInt = (arg->need & notInt) == 0;
            // Python raises on a division by zero; its ints do not round past 2^53 (and a
            // NaN fails the comparison).
            bad |= !(std::fabs(v) < (isInt ? kExactInts : std::numeric_limits<double>::infinity()));
            values[a] = v;
            ints |= std::uint32_t(isInt) << a;
        }
        *out++ = {o->cls, at, n, ints};
        values += n;
        at += n;
    }
    c.out = out, c.values = values, c.at = at;
    return !bad;
}

template <bool kOrigins, bool kChecked>
bool rewriteRange(const Engine& e, const Engine::Tables& t, const NumString& cur, size_t begin, size_t end,
                  Engine::NativeCursor& c) {
    const NumString::Module* from = cur.modules.data();
    const double* params = cur.params.data();
    // Nothing written aliases the rules or the string read (the compiler would reload them
    // after every store).
    NumString::Module* __restrict out = c.out;
    double* __restrict values = c.values;
    std::uint32_t at = c.at;
    NumString::Origin* __restrict origin = c.origin;
    bool bad = false;
    for (size_t j = begin; j < end; ++j) {
        const NumString::Module m = from[j];
        const double* in = params + m.first;
        const Engine::NativeRule* hit = nullptr;
        if (size_t(m.cls) < t.classCount) {
            const Engine::NativeClass& k = t.classes[m.cls];
            if (k.fast && k.arity == m.n) {
                // Unrolled for the usual small rules: a loop of unknown length costs more
                // than the arithmetic.
                const std::uint64_t notInt = ~std::uint64_t(m.ints);
                std::uint64_t ints = 0;
                const Engine::FastArg* args = t.fastArgs + k.firstFastArg;
                const std::uint32_t nArgs = k.fastArgs, nOuts = k.fastOuts;
                switch (nArgs) {
                    case 0: break;
                    case 1: fastValues<1, kChecked>(args, 1, in, notInt, values, ints, bad); break;
                    case 2: fastValues<2, kChecked>(args, 2, in, notInt, values, ints, bad); break;
                    case 3: fastValues<3, kChecked>(args, 3, in, notInt, values, ints, bad); break;
                    case 4: fastValues<4, kChecked>(args, 4, in, notInt, values, ints, bad); break;
                    default: fastValues<-1, kChecked>(args, nArgs, in, notInt, values, ints, bad); break;
                }
                const Engine::FastOut* outs = t.fastOuts + k.firstFastOut;
                switch (nOuts) {
                    case 0: break;
                    case 1: fastModules<1>(outs, 1, at, ints, out); break;
                    case 2: fastModules<2>(outs, 2, at, ints, out); break;
                    case 3: fastModules<3>(outs, 3, at, ints, out); break;
                    case 4: fastModules<4>(outs, 4, at, ints, out); break;
                    default: fastModules<-1>(outs, nOuts, at, ints, out); break;
                }
                if constexpr (kOrigins)
                    for (std::uint32_t o = 0; o < nOuts; ++o) *origin++ = {k.rule->index, std::uint32_t(j)};
                out += nOuts;
                values += nArgs;
                at += nArgs;
                continue;
            }
            if (k.rule && k.arity == m.n) hit = k.rule;
            else if (k.many) hit = e.nativeRule(m.cls, m.n);
        }
        if (!hit) {
            *out++ = {m.cls, at, m.n, m.ints};
            if constexpr (kOrigins) *origin++ = {-1, std::uint32_t(j)};
            for (std::uint32_t a = 0; a < m.n; ++a) values[a] = in[a];
            values += m.n;
            at += m.n;
            continue;
        }
        Engine::NativeCursor g{out, values, at, origin};
        bad |= !generalRule(*hit, t, m, in, j, g);
        out = g.out, values = g.values, at = g.at, origin = g.origin;
    }
    c = {out, values, at, origin};
    return !bad;
}
}  // namespace

void Engine::nativeSize(const NumString& cur, size_t end, std::uint64_t& modules, std::uint64_t& params) const {
    const NumString::Module* from = cur.modules.data();
    modules = params = 0;
    for (size_t j = 0; j < end; ++j) {
        if (const NativeRule* hit = nativeRule(from[j].cls, from[j].n)) {
            modules += hit->outs.size();
            params += hit->params;
        } else {
            modules += 1;
            params += from[j].n;
        }
    }
}

bool Engine::nativeRange(const NumString& cur, size_t begin, size_t end, NativeCursor& c, bool checked) const {
    const Tables t{m_nativeClass.data(), m_nativeClass.size(), m_flatOuts.data(), m_flatArgs.data(), m_fastOuts.data(),
                   m_fastArgs.data()};
    if (c.origin)
        return checked ? rewriteRange<true, true>(*this, t, cur, begin, end, c) : rewriteRange<true, false>(*this, t, cur, begin, end, c);
    return checked ? rewriteRange<false, true>(*this, t, cur, begin, end, c) : rewriteRange<false, false>(*this, t, cur, begin, end, c);
}

// A second thread for the derivations' big steps: started once for the process, given a job
// per step, lent to one derivation at a time (another at the same time does without). Between
// steps it spins a little before it sleeps: starting, waking or joining a thread took 20-150 us
// each here, as long as an 8 k-module step.
class NativeHelper {
public:
    // The process's helper, for the derivation that holds `lease` (locked when it was free);
    // none where this process may run on one processor only, or cannot start a thread.
    static NativeHelper* lend(std::unique_lock<std::mutex>& lease) {
        static NativeHelper* shared = new NativeHelper();  // never destroyed: it sleeps at exit
        if (!shared->m_started || shared->m_pid != getpid()) return nullptr;  // a forked child has no thread
        lease = std::unique_lock<std::mutex>(shared->m_lent, std::try_to_lock);
        return lease.owns_lock() ? shared : nullptr;
    }
    void post(std::function<void()> job) {
        {
            std::lock_guard<std::mutex> lock(m_lock);
            m_job = std::move(job);
            m_busy.store(true, std::memory_order_release);
        }
        m_wake.notify_one();
    }
    void wait() {
        for (int spin = 0; m_busy.load(std::memory_order_acquire); ++spin)
            if (spin > 64) std::this_thread::yield();
    }

private:
    NativeHelper() {
        cpu_set_t cpus;
        if (sched_getaffinity(0, sizeof cpus, &cpus) != 0 || CPU_COUNT(&cpus) < 2) return;
        try {
            std::thread([this] { loop(); }).detach();
            m_started = true;
        } catch (const std::system_error&) {  // no thread to be had: the derivation's does it all
        }
    }
    void loop() {
        for (;;) {
            // 200 us at most (a pause lasts from 10 to 140 cycles, by processor).
            const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
            for (int spin = 1; !m_busy.load(std::memory_order_acquire); ++spin) {
                relax();
                if (spin % 64 == 0 && std::chrono::steady_clock::now() > until) break;
            }
            std::function<void()> job;
            {
                std::unique_lock<std::mutex> lock(m_lock);
                m_wake.wait(lock, [&] { return m_busy.load(std::memory_order_relaxed); });
                job = std::move(m_job);
            }
            job();
            m_busy.store(false, std::memory_order_release);
        }
    }
    static void relax() {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#else
        std::this_thread::yield();
#endif
    }
    bool m_started = false;
    const pid_t m_pid = getpid();
    std::mutex m_lock, m_lent;
    std::condition_variable m_wake;
    std::function<void()> m_job;
    std::atomic<bool> m_busy{false};
};

bool Engine::nativeStep(const NumString& cur, NativeCursor& c, NativeHelper* helper) {
    const size_t count = cur.size();
    // The fast rules' values need no check when no number of the string is big enough for
    // one to reach 2^53 (|x * mul + add| <= max|x| * max|mul| + max|add|, with room for
    // rounding); without such values nothing is to check.
    double biggest[4] = {0, 0, 0, 0};
    const double* p = cur.params.data();
    const size_t numbers = m_fastArgs.empty() ? 0 : cur.params.size();
    size_t k = 0;
    for (; k + 4 <= numbers; k += 4)
        for (int u = 0; u < 4; ++u) biggest[u] = std::max(biggest[u], std::fabs(p[k + size_t(u)]));
    for (; k < numbers; ++k) biggest[0] = std::max(biggest[0], std::fabs(p[k]));
    const double most = std::max(std::max(biggest[0], biggest[1]), std::max(biggest[2], biggest[3]));
    const bool checked = !(most * m_fastScale + m_fastShift < kExactInts / 2);
    constexpr size_t kPiece = 16384;  // modules between two looks at Cancel
    auto run = [&](size_t from, size_t to, NativeCursor& at, bool mainThread) {
        for (size_t j = from; j < to; j += kPiece) {
            if (mainThread) checkCancel();
            else if (m_options.cancel && m_options.cancel->load(std::memory_order_relaxed)) return true;
            if (!nativeRange(cur, j, std::min(to, j + kPiece), at, checked)) return false;
        }
        return true;
    };
    // A big step is shared with a second thread, which writes the end of the new string: it
    // first counts what the first part makes (a look-up per module), so its part is smaller.
    constexpr size_t kShareFrom = 8192;
    if (count < kShareFrom || !helper) return run(0, count, c, true);
    const size_t split = count * 9 / 16;
    const NativeCursor start = c;  // c moves on as the first part is written
    NativeCursor second = c;
    bool secondOk = true;
    helper->post([&] {
        std::uint64_t modules = 0, params = 0;
        nativeSize(cur, split, modules, params);
        second = {start.out + modules, start.values + params, start.at + std::uint32_t(params),
                  start.origin ? start.origin + modules : nullptr};
        secondOk = run(split, count, second, false);
    });
    struct Wait {  // the second part is done before this step's locals go (a throw included)
        NativeHelper& h;
        ~Wait() { h.wait(); }
    } wait{*helper};
    const bool firstOk = run(0, split, c, true);
    helper->wait();
    checkCancel();  // the second part stopped for it
    c = second;
    return firstOk && secondOk;
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
    std::unique_lock<std::mutex> lease;
    NativeHelper* helper = nullptr;  // lent at the first big step
    for (int i = 0; i < steps; ++i) {
        checkCancel();
        iteration = i;
        const size_t count = cur.size();
        // Room for the new string: an upper bound from the longest successor, or the exact
        // size where that bound would be far too big.
        std::uint64_t modules = std::uint64_t(count) * m_nativeMaxOuts;
        std::uint64_t params = cur.params.size() + std::uint64_t(count) * m_nativeMaxParams;
        if (modules > (16u << 20) || params > (16u << 20)) nativeSize(cur, count, modules, params);
        if (params > std::numeric_limits<std::uint32_t>::max()) throw py::value_error("the string holds too many numbers");
        next.modules.clear();  // nothing of it is kept: not copied when it grows
        next.params.clear();
        next.origins.clear();
        next.modules.resizeUninitialized(modules);
        next.params.resizeUninitialized(params);
        if (origins) next.origins.resizeUninitialized(modules);
        NativeCursor c{next.modules.data(), next.params.data(), 0, origins ? next.origins.data() : nullptr};
        if (!helper && count >= 8192) helper = NativeHelper::lend(lease);
        bool ok = nativeStep(cur, c, helper);
        if (!ok) {
            m_nativeOk = false;
            if (everyStep) everyStep->clear();
            return false;
        }
        const size_t made = size_t(c.out - next.modules.data());
        if (made > m_options.maxModules)
            throw py::value_error("the string grew past " + std::to_string(m_options.maxModules) + " modules");
        next.modules.resizeUninitialized(made);
        next.params.resizeUninitialized(c.at);
        if (origins) next.origins.resizeUninitialized(made);
        cur.swap(next);
        if (everyStep) everyStep->push_back(cur);
    }
    iteration = std::max(0, steps - 1);
    ranNative = true;
    result = std::move(cur);
    return true;
}

}  // namespace sprout::lpy
