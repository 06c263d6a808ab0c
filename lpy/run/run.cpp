// runModel (lpy/lpy.hpp): an L-Py model file read, run and drawn for the CLI, the viewer and
// the `sprout` Python module. The interpreter's start, the names and the Python side of the engine are
// interpreter.cpp's; this file is one run, from the text to what the turtle draws.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <span>
#include <thread>

#include <pybind11/stl.h>

#include "core/derive/draw.hpp"
#include "lpy/lpy.hpp"
#include "lpy/api/api.hpp"
#include "lpy/draw/draw.hpp"
#include "lpy/interpreter/interpreter.hpp"

namespace sprout::lpy {
namespace {
// Interrupts Python on the running thread when `cancel` is set (an endless loop in a rule).
// The flag is looked at every 2 ms (a drag's step cancels the one running: at 10 ms, the
// next waited 5 ms on average for its turn); the run's end wakes the watcher at once (it
// slept its poll out before: each run and each drawing of a step waited for it).
class CancelWatch {
public:
    CancelWatch(const std::atomic<bool>* cancel) : m_cancel(cancel) {
        if (!m_cancel) return;
        m_thread = PyThread_get_thread_ident();
        m_watch = std::thread([this] {
            std::unique_lock lock(m_mutex);
            while (!m_done) {
                if (m_cancel->load()) {
                    lock.unlock();
                    py::gil_scoped_acquire gil;
                    lock.lock();
                    if (!m_done) PyThreadState_SetAsyncExc(m_thread, PyExc_KeyboardInterrupt);
                    return;
                }
                m_wake.wait_for(lock, std::chrono::milliseconds(2));
            }
        });
    }
    ~CancelWatch() {
        if (!m_watch.joinable()) return;
        {
            std::lock_guard lock(m_mutex);
            m_done = true;
        }
        m_wake.notify_all();
        {
            py::gil_scoped_release release;  // the watcher may be waiting for the GIL
            m_watch.join();
        }
        // An interrupt that arrived as the run ended must not hit the next run.
        PyThreadState_SetAsyncExc(m_thread, nullptr);
    }

private:
    const std::atomic<bool>* m_cancel;
    unsigned long m_thread = 0;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_done = false;  // under m_mutex
    std::thread m_watch;
};

// While it lives, what the model prints goes to standard error: standard output carries
// Sprout's results (`sprout expand` writes the string there). Held with the GIL.
class PrintsToStderr {
public:
    PrintsToStderr() : m_sys(py::module_::import("sys")), m_saved(m_sys.attr("stdout")) { m_sys.attr("stdout") = m_sys.attr("stderr"); }
    ~PrintsToStderr() { m_sys.attr("stdout") = m_saved; }
    PrintsToStderr(const PrintsToStderr&) = delete;
    PrintsToStderr& operator=(const PrintsToStderr&) = delete;

private:
    py::module_ m_sys;
    py::object m_saved;
};

// A kept module as the record reads it: its class, its numbers (NaN for another Python value),
// and where it came from. For a step of Python modules, and of the native path's numbers.
struct ModuleOf {
    const LString& s;
    size_t size() const { return s.size(); }
    int cls(size_t i) const { return s[i].cls; }
    int count(size_t i) const { return s[i].args ? int(PyTuple_GET_SIZE(s[i].args.ptr())) : 0; }
    double number(size_t i, int a) const {
        PyObject* v = PyTuple_GET_ITEM(s[i].args.ptr(), a);
        double x = std::numeric_limits<double>::quiet_NaN();
        if (PyFloat_Check(v)) x = PyFloat_AS_DOUBLE(v);
        else if (PyLong_Check(v)) x = PyLong_AsDouble(v);
        if (PyErr_Occurred()) PyErr_Clear(), x = std::numeric_limits<double>::quiet_NaN();
        return x;
    }
    int rule(size_t i) const { return s[i].rule; }
    std::uint32_t parent(size_t i) const { return s[i].parent; }
};
struct NumberModuleOf {
    const NumString& s;
    std::vector<size_t> at;  // where each module's numbers start
    explicit NumberModuleOf(const NumString& n) : s(n) {
        at.reserve(s.size());
        size_t k = 0;
        for (size_t i = 0; i < s.size(); ++i) at.push_back(k), k += s.shape(i).n;
    }
    size_t size() const { return s.size(); }
    int cls(size_t i) const { return s.shape(i).cls; }
    int count(size_t i) const { return int(s.shape(i).n); }
    double number(size_t i, int a) const { return s.params[at[i] + size_t(a)]; }
    int rule(size_t i) const { return i < s.origins.size() ? s.origins[i].rule : -1; }
    std::uint32_t parent(size_t i) const { return i < s.origins.size() ? s.origins[i].parent : std::uint32_t(i); }
};

// The kept steps as Sprout's derivation record: module names with their numbers, and each
// module's rule and parent (lpy/engine/engine.hpp LModule), the rules' lines in a grammar of their own.
// `first`: the step every[0] is (0: the axiom, whose modules come from nowhere).
template <class Reader, class Step>
DerivationRecord recordOf(std::span<const Step> every, const Translation& tr, size_t first = 0) {
    auto g = std::make_shared<Grammar>();
    for (const Rule& r : tr.rules) {
        Production p;
        p.line = r.line;
        g->rules.productions.push_back(std::move(p));
    }
    DerivationRecord record;
    // Each class and arity's symbol, looked up once (the alphabet finds a name by a walk):
    // at cls * (kMaxArity + 1) + arity, -1 until looked up, -2 for none.
    constexpr size_t kArities = Alphabet::kMaxArity + 1;
    std::vector<std::int32_t> symbols;
    for (size_t k = 0; k < every.size(); ++k) {
        const Reader m(every[k]);
        auto string = std::make_shared<ModuleString>();
        auto origins = std::make_shared<Origins>();
        string->symbols.reserve(m.size());
        origins->parent.reserve(m.size());
        origins->rule.reserve(m.size());
        for (size_t i = 0; i < m.size(); ++i) {
            const int arity = std::min(m.count(i), Alphabet::kMaxArity);
            const size_t at = size_t(std::max(0, m.cls(i))) * kArities + size_t(arity);
            if (at >= symbols.size()) symbols.resize(at + kArities, -1);
            if (symbols[at] == -1) {
                std::optional<SymbolId> id = g->alphabet.intern(tr.classes.name(m.cls(i)), arity);
                if (!id) id = g->alphabet.intern("?", 0);
                symbols[at] = id ? std::int32_t(*id) : -2;
            }
            if (symbols[at] < 0) break;
            const std::optional<SymbolId> id = SymbolId(symbols[at]);
            string->symbols.push_back(*id);
            for (int a = 0; a < int(g->alphabet[*id].arity); ++a) string->params.push_back(m.number(i, a));
            const int rule = m.rule(i);
            const bool axiom = first + k == 0;
            origins->parent.push_back(axiom ? std::uint32_t(i) : m.parent(i));
            origins->rule.push_back(axiom || rule < 0 || size_t(rule) >= tr.rules.size() ? -1 : rule);
        }
        record.steps.push_back(std::move(string));
        record.origins.push_back(std::move(origins));
    }
    record.grammar = std::move(g);
    return record;
}

// A run that draws later (RunOptions::drawLater): its engine, namespace and kept steps, which
// hold Python objects, so that they are let go with the GIL held.
class KeptRun final : public StepDrawer {
public:
    struct State {
        RunOptions options;  // the engine keeps a reference
        py::dict ns;
        std::unique_ptr<Engine> engine;
        std::vector<LString> every;
        std::vector<NumString> numbers;  // or, on the native path, the steps as numbers
        TurtleDefaults defaults;
        std::string file, text;
    };
    std::unique_ptr<State> state = std::make_unique<State>();

    ~KeptRun() override {
        if (!Py_IsInitialized()) {
            (void)state.release();  // the interpreter is gone, and its objects with it
            return;
        }
        py::gil_scoped_acquire gil;
        state.reset();
    }

    int steps() const override { return int(state->numbers.empty() ? state->every.size() : state->numbers.size()); }

    std::string text(int step) override {
        if (step < 0 || step >= steps()) throw std::out_of_range("no step " + std::to_string(step) + " in this run");
        std::lock_guard<std::mutex> lock(runMutex());
        py::gil_scoped_acquire gil;
        State& st = *state;
        EngineScope scope(st.engine.get());
        return st.numbers.empty() ? st.engine->text(st.every[size_t(step)]) : st.engine->text(st.numbers[size_t(step)]);
    }

    DerivationRecord derived(int step) override {
        if (step < 0 || step >= steps()) throw std::out_of_range("no step " + std::to_string(step) + " in this run");
        py::gil_scoped_acquire gil;  // the modules' numbers are Python's
        State& st = *state;
        if (!st.numbers.empty()) return recordOf<NumberModuleOf>(std::span<const NumString>(st.numbers).subspan(size_t(step), 1), st.engine->translation(), size_t(step));
        return recordOf<ModuleOf>(std::span<const LString>(st.every).subspan(size_t(step), 1), st.engine->translation(), size_t(step));
    }

    std::shared_ptr<const Grammar> draw(int step, std::vector<std::uint32_t>* from, const std::atomic<bool>* cancel) override {
        if (step < 0 || step >= steps()) throw std::out_of_range("no step " + std::to_string(step) + " in this run");
        std::lock_guard<std::mutex> lock(runMutex());
        py::gil_scoped_acquire gil;
        State& st = *state;
        st.options.cancel = cancel;  // the engine reads it (a reference to these options)
        struct Forget {
            RunOptions& o;
            ~Forget() { o.cancel = nullptr; }
        } forget{st.options};
        CancelWatch watch(cancel);
        const PrintsToStderr prints;  // as in the run
        EngineScope scope(st.engine.get());
        try {
            const ModuleClasses& classes = st.engine->translation().classes;
            if (!st.numbers.empty() && !from && !st.engine->interprets()) return drawable(st.numbers[size_t(step)], classes, st.defaults);
            const LString shown = st.engine->interpret(st.numbers.empty() ? st.every[size_t(step)] : Engine::toL(st.numbers[size_t(step)]));
            auto g = drawable(shown, classes, st.defaults, nullptr, false, from);
            if (from)
                for (auto& v : *from) v = v < shown.size() ? shown[v].parent : 0;
            return g;
        } catch (py::error_already_set& e) {
            if (cancel && cancel->load() && e.matches(PyExc_KeyboardInterrupt)) return nullptr;
            throw DrawError(describe(e, st.file, st.text), st.file);
        } catch (Cancelled&) {
            return nullptr;
        }
    }
};

}  // namespace

Model runModel(std::string_view written, const RunOptions& options) {
    Model out;
    // %pastefile / %pastemodule lines first, as L-Py reads a file; then the bytes decoded as
    // its Python decodes them (a Latin-1 file opens).
    const std::string pasted = modelTextAsUtf8(pasteFiles(written, pasteReader(options.path), out.diagnostics));
    if (hasErrors(out.diagnostics)) return out;
    const std::string_view text = pasted;
    try {
        start(&defineSproutLpy);
    } catch (std::exception& e) {
        const Translation tr = translate(text);  // its own errors first, then why it cannot run
        out.diagnostics.insert(out.diagnostics.end(), tr.diagnostics.begin(), tr.diagnostics.end());
        out.diagnostics.push_back({0, 0, std::string("Python could not start: ") + e.what(), Severity::Error});
        return out;
    }
    std::lock_guard<std::mutex> lock(runMutex());
    py::gil_scoped_acquire gil;
    // Read with the process's names (the registry is held with the GIL): the same modules as
    // the L-systems made from Python, with ids that agree with theirs.
    Translation tr = translate(text, &registry());
    out.diagnostics.insert(out.diagnostics.end(), tr.diagnostics.begin(), tr.diagnostics.end());
    if (!tr.ok()) return out;
    registry().adopt(tr.classes, false);
    const std::string file = options.path.empty() ? "<model>" : options.path;
    std::string initCode = tr.initCode, mainCode = tr.mainCode;
    py::dict ns;
    ns["__builtins__"] = py::module_::import("builtins");
    ns["__name__"] = "__lpy__";
    ns["__file__"] = file;
    py::module_ lpyModule;
    try {
        lpyModule = py::module_::import("openalea.lpy");
        lpyModule.attr("_begin")(ns, file);
        prepareNamespace(ns, options.path);
    } catch (py::error_already_set& e) {
        out.diagnostics.push_back(describe(e, file, text));
        return out;
    }
    const PrintsToStderr prints;
    // The engine and what it needs live on the heap: a run that draws later (drawLater) keeps
    // them with the Model, the others drop them at the end of this function, the GIL held.
    auto kept = std::make_shared<KeptRun>();
    KeptRun::State& st = *kept->state;
    st.options = options;
    st.ns = ns;
    st.file = file;
    st.text = std::string(text);
    st.engine = std::make_unique<Engine>(std::move(tr), ns, st.options);
    Engine& engine = *st.engine;
    EngineScope scope(&engine);
    engine.sceneOf = [&engine](const LString& s) { return sceneOf(engine, s); };
    CancelWatch watch(options.cancel);
    auto builtins = py::module_::import("builtins");
    try {
        // The INITIALISATION part runs first, then __initialiseContext__, then the model.
        builtins.attr("exec")(builtins.attr("compile")(initCode, file, "exec"), ns);
        if (ns.contains("__initialiseContext__")) ns["__initialiseContext__"](lpyModule.attr("context")());
        builtins.attr("exec")(builtins.attr("compile")(mainCode, file, "exec"), ns);
        engine.bind();
        out.derivationLength = engine.derivationLength;
        const int steps = options.steps >= 0 ? options.steps : engine.derivationLength;
        std::vector<LString> every;
        std::vector<std::shared_ptr<const ContextMatches>> contexts;
        engine.fillQueries = [&engine, lpyModule](LString& s) { fillQueries(engine, s, turtleDefaults(lpyModule)); };
        LString axiom = engine.axiom();
        const auto deriveStart = std::chrono::steady_clock::now();
        LString s;
        // A model of the native path whose string no Python reads afterwards (no
        // interpretation rules, no growth stepping) keeps its string as numbers to the end.
        NumString numbers;
        const bool numeric = engine.native() && !engine.interprets() && !options.keepSteps &&
                             engine.deriveNumbers(axiom, steps, nullptr, numbers, false);
        // Steps kept to be drawn later (the `sprout` Python module), on the native path: kept as numbers,
        // made into Python modules only for a step that is drawn.
        std::vector<NumString> everyNumbers;
        const bool numericSteps = !numeric && options.keepSteps && options.drawLater && engine.native() &&
                                  engine.deriveNumbers(axiom, steps, &everyNumbers, numbers, true);
        if (!numeric && !numericSteps) {
            // Python's cycle collector walks every live object each time enough new ones were
            // made: with a string of a million parameter tuples alive it runs again and again
            // over all of them. The derivation makes no cycles of its own; it runs once after.
            struct Collector {
                int was = PyGC_Disable();
                ~Collector() {
                    if (was) PyGC_Enable();
                }
            } paused;
            // Where contexts matched: for the derivation inspector.
            s = engine.derive(std::move(axiom), steps, options.keepSteps ? &every : nullptr,
                              options.keepSteps && options.keepRecord ? &contexts : nullptr);
        }
        out.deriveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - deriveStart).count();
        out.stepsDone = engine.iteration + (steps > 0 ? 1 : 0);
        out.ranNative = engine.ranNative;
        // (Written when asked for, for a run drawn later: a big string takes a while.)
        if (!(options.drawLater && options.keepSteps)) out.derived = numeric || numericSteps ? engine.text(numbers) : engine.text(s);
        // What the turtle draws, with the file's turtle settings and materials.
        TurtleDefaults d = turtleDefaults(lpyModule);
        placeTextures(d, options.path, out.diagnostics);
        py::dict state = lpyModule.attr("_state");
        std::vector<std::string> leftOut;
        // Drawn later: only the turtle's settings now (a drawing of nothing), each step when asked.
        auto g = options.drawLater ? drawable(LString(), engine.translation().classes, d, nullptr)
                 : numeric         ? drawable(numbers, engine.translation().classes, d, &leftOut)
                                   : drawable(engine.interpret(s), engine.translation().classes, d, &leftOut);
        for (const auto& name : leftOut)
            out.diagnostics.push_back({0, 0, "'" + name + "' is not drawn by Sprout yet", Severity::Warning});
        if (!options.drawLater)
            for (const LString& step : every) {
                const LString shown = engine.interpret(step);
                auto from = std::make_shared<std::vector<std::uint32_t>>();
                out.steps.push_back(drawable(shown, engine.translation().classes, d, nullptr, false, from.get()));
                for (auto& v : *from) v = v < shown.size() ? shown[v].parent : 0;
                out.drawnFrom.push_back(std::move(from));
            }
        if (options.keepSteps && options.keepRecord)  // else each step's record when asked (StepDrawer::derived)
            out.record = numericSteps ? recordOf<NumberModuleOf>(std::span<const NumString>(everyNumbers), engine.translation())
                                      : recordOf<ModuleOf>(std::span<const LString>(every), engine.translation());
        out.record.contexts = std::move(contexts);
        for (auto w : py::list(state["warnings"]))
            out.diagnostics.push_back({w[py::int_(0)].cast<int>(), 0, std::string(py::str(w[py::int_(1)])), Severity::Warning});
        out.drawable = std::move(g);
        if (options.drawLater && options.keepSteps) {
            st.every = std::move(every);
            st.numbers = std::move(everyNumbers);
            st.defaults = d;
            st.options.cancel = nullptr;  // the caller's flag is not kept alive with the run
            out.later = kept;
        }
    } catch (py::error_already_set& e) {
        if (e.matches(PyExc_KeyboardInterrupt) && options.cancel && options.cancel->load()) {
            out.cancelled = true;
            out.diagnostics.push_back({0, 0, "cancelled", Severity::Error});
        } else {
            out.diagnostics.push_back(describe(e, file, text));
        }
    } catch (Cancelled&) {
        out.cancelled = true;
        out.diagnostics.push_back({0, 0, "cancelled", Severity::Error});
    } catch (TooBig& e) {  // at the line that asked for the steps
        const auto [line, col] = engine.translation().derivationLengthAt;
        out.diagnostics.push_back({line, col, e.what(), Severity::Error});
    } catch (std::exception& e) {  // a value Python gave that C++ cannot take (pybind11's cast errors)
        out.diagnostics.push_back({0, 0, e.what(), Severity::Error});
    }
    return out;
}

bool pythonAvailable() { return true; }

void installOpenalea() { start(&defineSproutLpy); }

void setScenePlantMaker(void* maker) { setScenePlant(py::reinterpret_borrow<py::object>(static_cast<PyObject*>(maker))); }

}  // namespace sprout::lpy
