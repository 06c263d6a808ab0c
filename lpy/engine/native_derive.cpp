// The native path of L-Py models (lpy/engine/native_deriver.hpp): rules written `A(x) --> B(x + 1) C`, whose
// bodies are only a successor with arithmetic, are compiled to Sprout's expressions and the
// model derives on plain numbers, without a Python call per match. A model takes this path
// only when every production is that simple and nothing else can see the string while it
// grows (no hooks, contexts, groups, queries, cuts, decomposition). Its string is a
// NumString: numbers in one array, drawn and written as they are (lpy/draw/draw.hpp, `sprout
// expand`), and made into Python values (integral numbers as Python ints where Python has
// ints) only for a model whose interpretation rules or growth stepping read it in Python. A
// value that is not finite (a division by zero, which Python would raise) drops the native
// run: the model runs in Python from the start instead.
//
// How a step runs fast (lpy_bench: 17-21x the Python path before, then 60-69x, now 105-140x):
// - a module is 4 bytes, its shape (class, count of numbers, which are ints), and every
//   shape the axiom's can lead to is found before the derivation with what a step does with
//   it: the inner loop reads one entry per module and copies the shapes it makes;
// - rules whose arguments are all x * a + b of a parameter, or constants (Expr::affine), are
//   laid out flat and written by loops unrolled for up to 4 modules and 4 numbers;
// - those values are not checked one by one where no number of the string is big enough for
//   one of them to reach 2^53 (bounded from the step before's where every rule is fast,
//   else a pass over the numbers first);
// - room for the new string comes from an upper bound, not a pass that counts it;
// - steps of 8 k modules or more are shared with a second thread of the process's;
// - big buffers reuse the mappings of the last derivation (core/base/huge_pages.hpp).
// This file is the derivation, with the inner loop and all it calls in one translation unit;
// what is found before it (the rules compiled, the shapes and their steps) is in
// native_rules.cpp.

// Index of this file:
//   [SECTION] the inner loop: a range of modules rewritten
//   [SECTION] a step's size, and its ranges
//   [SECTION] the second thread
//   [SECTION] a step
//   [SECTION] the derivation

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>

#include "core/base/rng.hpp"
#include "lpy/engine/growth.hpp"
#include "lpy/engine/native_deriver.hpp"

namespace sprout::lpy {

//-----------------------------------------------------------------------------
// [SECTION] the inner loop: a range of modules rewritten
//-----------------------------------------------------------------------------
namespace {

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

// A fast rule's numbers (N of them; N < 0: `count`, in a loop); checked: whether each is one
// Python would give (`ints`: those that are ints).
template <int N, bool kChecked>
inline void fastValues(const NativeDeriver::FastArg* __restrict args, std::uint32_t count, const double* in, std::uint64_t ints,
                       double* __restrict values, bool& bad) {
    const std::uint32_t n = N < 0 ? count : std::uint32_t(N);
    for (std::uint32_t k = 0; k < n; ++k) {
        const NativeDeriver::FastArg& a = args[k];
        const double v = in[a.slot] * a.mul + a.add;
        if constexpr (kChecked)
            bad |= !(std::fabs(v) < (ints >> k & 1 ? kExactInts : std::numeric_limits<double>::infinity()));
        values[k] = v;
    }
}

template <int N>
inline void copyShapes(const std::uint32_t* __restrict shapes, std::uint32_t count, std::uint32_t* __restrict out) {
    const std::uint32_t n = N < 0 ? count : std::uint32_t(N);
    for (std::uint32_t k = 0; k < n; ++k) out[k] = shapes[k];
}

// A rule with arguments other than fast ones (Expr calls, always checked), out of the
// inner loop; false when a value is not one Python would give.
[[gnu::noinline]] bool generalRule(const NativeDeriver::ShapeStep& k, const NativeDeriver::Tables& t, const double* in, size_t j,
                                   NativeDeriver::NativeCursor& c) {
    Rng rng(0);  // the rules use no random numbers (NativeDeriver::prepare)
    bool bad = false;
    const NativeDeriver::NativeRule& hit = *k.rule;
    const NativeDeriver::FlatOut* o = t.flatOuts + hit.firstOut;
    const NativeDeriver::FlatOut* oEnd = o + hit.outs.size();
    const NativeDeriver::FlatArg* arg = t.flatArgs + hit.firstArg;
    const std::uint32_t* shape = t.outShapes + k.firstOut;
    const std::uint64_t notInt = ~std::uint64_t(k.ints);
    std::uint32_t* out = c.out;
    double* values = c.values;
    for (; o != oEnd; ++o) {
        const std::uint32_t n = o->n;
        if (c.origin) *c.origin++ = {hit.index, std::uint32_t(j)};
        for (std::uint32_t a = 0; a < n; ++a, ++arg) {
            const double v = arg->expr->eval(in, rng);
            const bool isInt = (arg->need & notInt) == 0;
            // Python raises on a division by zero; its ints do not round past 2^53 (and a
            // NaN fails the comparison).
            bad |= !(std::fabs(v) < (isInt ? kExactInts : std::numeric_limits<double>::infinity()));
            values[a] = v;
        }
        *out++ = *shape++;
        values += n;
    }
    c.out = out, c.values = values;
    return !bad;
}

template <bool kOrigins, bool kChecked>
bool rewriteRange(const NativeDeriver::Tables& t, const NumString& cur, size_t begin, size_t end, NativeDeriver::NativeCursor& c) {
    const std::uint32_t* from = cur.modules.data();
    const double* in = cur.params.data() + c.in;
    // Nothing written aliases the rules or the string read (the compiler would reload them
    // after every store).
    std::uint32_t* __restrict out = c.out;
    double* __restrict values = c.values;
    NumString::Origin* __restrict origin = c.origin;
    bool bad = false;
    for (size_t j = begin; j < end; ++j) {
        const NativeDeriver::ShapeStep& k = t.steps[from[j]];
        const std::uint32_t nIn = k.n, nOuts = k.nOuts, nArgs = k.nArgs;
        const std::uint32_t* shapes = t.outShapes + k.firstOut;
        if (k.kind == NativeDeriver::ShapeStep::Fast) {
            // Unrolled for the usual small rules: a loop of unknown length costs more than
            // the arithmetic.
            const NativeDeriver::FastArg* args = t.fastArgs + k.firstArg;
            switch (nArgs) {
                case 0: break;
                case 1: fastValues<1, kChecked>(args, 1, in, k.outInts, values, bad); break;
                case 2: fastValues<2, kChecked>(args, 2, in, k.outInts, values, bad); break;
                case 3: fastValues<3, kChecked>(args, 3, in, k.outInts, values, bad); break;
                case 4: fastValues<4, kChecked>(args, 4, in, k.outInts, values, bad); break;
                default: fastValues<-1, kChecked>(args, nArgs, in, k.outInts, values, bad); break;
            }
            switch (nOuts) {
                case 0: break;
                case 1: copyShapes<1>(shapes, 1, out); break;
                case 2: copyShapes<2>(shapes, 2, out); break;
                case 3: copyShapes<3>(shapes, 3, out); break;
                case 4: copyShapes<4>(shapes, 4, out); break;
                default: copyShapes<-1>(shapes, nOuts, out); break;
            }
            if constexpr (kOrigins)
                for (std::uint32_t o = 0; o < nOuts; ++o) *origin++ = {k.rule->index, std::uint32_t(j)};
            out += nOuts;
            values += nArgs;
        } else if (k.kind == NativeDeriver::ShapeStep::Copy) {
            *out++ = *shapes;
            if constexpr (kOrigins) *origin++ = {-1, std::uint32_t(j)};
            for (std::uint32_t a = 0; a < nIn; ++a) values[a] = in[a];
            values += nIn;
        } else {
            NativeDeriver::NativeCursor g{out, values, origin, 0};
            bad |= !generalRule(k, t, in, j, g);
            out = g.out, values = g.values, origin = g.origin;
        }
        in += nIn;
    }
    c = {out, values, origin, size_t(in - cur.params.data())};
    return !bad;
}
}  // namespace

//-----------------------------------------------------------------------------
// [SECTION] a step's size, and its ranges
//-----------------------------------------------------------------------------
void NativeDeriver::nativeSize(const NumString& cur, size_t end, std::uint64_t& modules, std::uint64_t& params,
                        std::uint64_t& read) const {
    const std::uint32_t* from = cur.modules.data();
    const ShapeStep* steps = m_shapeSteps.data();
    modules = params = read = 0;
    for (size_t j = 0; j < end; ++j) {
        const ShapeStep& k = steps[from[j]];
        modules += k.nOuts;
        params += k.nArgs;
        read += k.n;
    }
}

bool NativeDeriver::nativeRange(const NumString& cur, size_t begin, size_t end, NativeCursor& c, bool checked) const {
    const Tables t{m_shapeSteps.data(), m_outShapes.data(), m_flatOuts.data(), m_flatArgs.data(), m_fastArgs.data()};
    if (c.origin)
        return checked ? rewriteRange<true, true>(t, cur, begin, end, c) : rewriteRange<true, false>(t, cur, begin, end, c);
    return checked ? rewriteRange<false, true>(t, cur, begin, end, c) : rewriteRange<false, false>(t, cur, begin, end, c);
}

//-----------------------------------------------------------------------------
// [SECTION] the second thread
//-----------------------------------------------------------------------------
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

//-----------------------------------------------------------------------------
// [SECTION] a step
//-----------------------------------------------------------------------------
bool NativeDeriver::nativeStep(const NumString& cur, NativeCursor& c, NativeHelper* helper) {
    const size_t count = cur.size();
    // The fast rules' values need no check when no number of the string is big enough for
    // one to reach 2^53 (|x * mul + add| <= max|x| * max|mul| + max|add|, with room for
    // rounding); without such values nothing is to check. Where every rule is a fast one,
    // the biggest number of a step's string is bounded by the step before's (copies keep
    // theirs), so a pass over the numbers is needed only where that bound is too loose.
    auto biggest = [&] {
        double top[4] = {0, 0, 0, 0};
        const double* p = cur.params.data();
        const size_t numbers = cur.params.size();
        size_t k = 0;
        for (; k + 4 <= numbers; k += 4)
            for (int u = 0; u < 4; ++u) top[u] = std::max(top[u], std::fabs(p[k + size_t(u)]));
        for (; k < numbers; ++k) top[0] = std::max(top[0], std::fabs(p[k]));
        return std::max(std::max(top[0], top[1]), std::max(top[2], top[3]));
    };
    bool checked = false;
    if (!m_fastArgs.empty()) {
        const double limit = kExactInts / 2;
        double most = m_bound >= 0 ? m_bound : biggest();
        if (!(most * m_fastScale + m_fastShift < limit) && m_bound >= 0) most = biggest();
        checked = !(most * m_fastScale + m_fastShift < limit);
        m_bound = m_allFast && !checked ? std::max(most, most * m_fastScale + m_fastShift) : -1;
    }
    constexpr size_t kPiece = 16384;  // modules between two looks at Cancel
    auto run = [&](size_t from, size_t to, NativeCursor& at, bool mainThread) {
        for (size_t j = from; j < to; j += kPiece) {
            if (mainThread) checkCancel(m_options);
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
        std::uint64_t modules = 0, params = 0, read = 0;
        nativeSize(cur, split, modules, params, read);
        second = {start.out + modules, start.values + params, start.origin ? start.origin + modules : nullptr,
                  start.in + read};
        secondOk = run(split, count, second, false);
    });
    struct Wait {  // the second part is done before this step's locals go (a throw included)
        NativeHelper& h;
        ~Wait() { h.wait(); }
    } wait{*helper};
    const bool firstOk = run(0, split, c, true);
    helper->wait();
    checkCancel(m_options);  // the second part stopped for it
    c = second;
    return firstOk && secondOk;
}

//-----------------------------------------------------------------------------
// [SECTION] the derivation
//-----------------------------------------------------------------------------
bool NativeDeriver::derive(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result,
                           bool origins, int& iteration) {
    NumString cur, next;
    m_shapes.clear();
    m_shapeIds.clear();
    for (size_t k = 0; k < axiom.size(); ++k) {
        const LModule& m = axiom[k];
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        NumString::Shape shape{m.cls, std::uint32_t(n), 0};
        if (origins) cur.origins.push_back({-1, std::uint32_t(k)});
        for (Py_ssize_t a = 0; a < n; ++a) {
            double v = 0;
            bool isInt = false;
            if (a >= kMaxNativeArity || !numberOf(PyTuple_GET_ITEM(m.args.ptr(), a), v, isInt)) {
                m_ok = false;
                return false;
            }
            cur.params.push_back(v);
            shape.ints |= std::uint32_t(isInt) << a;
        }
        cur.modules.push_back(shapeOf(shape));
    }
    // Every shape the string can hold, and what a step does with each, before it grows.
    if (!closeShapes()) {
        m_ok = false;
        return false;
    }
    cur.shapes = next.shapes = std::make_shared<const std::vector<NumString::Shape>>(m_shapes);
    m_bound = -1;  // the axiom's numbers: measured
    m_allFast = std::none_of(m_shapeSteps.begin(), m_shapeSteps.end(),
                             [](const ShapeStep& k) { return k.kind == ShapeStep::General; });
    if (everyStep) everyStep->push_back(cur);
    std::unique_lock<std::mutex> lease;
    NativeHelper* helper = nullptr;  // lent at the first big step
    for (int i = 0; i < steps; ++i) {
        checkCancel(m_options);
        iteration = i;
        const size_t count = cur.size();
        // Room for the new string: an upper bound from the longest successor, or the exact
        // size where that bound would be far too big.
        std::uint64_t modules = std::uint64_t(count) * m_nativeMaxOuts;
        std::uint64_t params = cur.params.size() + std::uint64_t(count) * m_nativeMaxParams;
        std::uint64_t read = 0;
        const bool exact = modules > (16u << 20) || params > (16u << 20);
        if (exact) nativeSize(cur, count, modules, params, read);
        // The step's size against the limits before it is allocated (exact where it is big;
        // the bound of a small step is checked once made, below).
        auto refuse = [&](std::uint64_t m, std::uint64_t p) {
            const std::uint64_t bytes = (cur.modules.size() + m) * 4 + (cur.params.size() + p) * 8;
            if (m <= m_options.maxModules && bytes <= m_options.maxBytes) return;
            const std::string size = humanBytes(bytes);
            const bool overModules = m > m_options.maxModules;
            throw TooBig("step " + std::to_string(i + 1) + " would make " + withThousands(m) + " modules (" + size +
                                  " with the string before it), over the " +
                                  (overModules ? "limit of " + withThousands(m_options.maxModules) + " modules" : "memory budget of " + humanBytes(m_options.maxBytes)) +
                                  "; lower the derivation length (to " + std::to_string(i) + " at most) or raise the " +
                                  (overModules ? "limit (--max-modules)" : "budget (--max-memory)"));
        };
        if (exact) refuse(modules, params);
        if (params > std::numeric_limits<std::uint32_t>::max()) throw py::value_error("the string holds too many numbers");
        next.modules.clear();  // nothing of it is kept: not copied when it grows
        next.params.clear();
        next.origins.clear();
        next.modules.resizeUninitialized(modules);
        next.params.resizeUninitialized(params);
        if (origins) next.origins.resizeUninitialized(modules);
        NativeCursor c{next.modules.data(), next.params.data(), origins ? next.origins.data() : nullptr, 0};
        if (!helper && count >= 8192) helper = NativeHelper::lend(lease);
        bool ok = nativeStep(cur, c, helper);
        if (!ok) {
            m_ok = false;
            if (everyStep) everyStep->clear();
            return false;
        }
        const size_t made = size_t(c.out - next.modules.data());
        refuse(made, std::uint64_t(c.values - next.params.data()));
        next.modules.resizeUninitialized(made);
        next.params.resizeUninitialized(size_t(c.values - next.params.data()));
        if (origins) next.origins.resizeUninitialized(made);
        cur.swap(next);
        if (everyStep) everyStep->push_back(cur);
    }
    iteration = std::max(0, steps - 1);
    result = std::move(cur);
    return true;
}

}  // namespace sprout::lpy
