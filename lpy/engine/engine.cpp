// L-Py's derivation (lpy/engine/engine.hpp): the engine's set-up (bind: the rules' functions, header
// constants and predicates, the rule index) and its steps (derive: the hooks around each
// production and decomposition pass; interpret). The passes themselves, matching rules module
// by module, are in passes.cpp (a rule's header matched by the Matcher, match.cpp); Python's
// values in and out of the strings in values.cpp.
#include "lpy/engine/engine.hpp"

#include <algorithm>
#include <cstring>
#include <functional>

namespace sprout::lpy {
namespace {

thread_local Engine* g_engine = nullptr;

}  // namespace

Engine* currentEngine() { return g_engine; }

Engine* setCurrentEngine(Engine* e) {
    Engine* was = g_engine;
    g_engine = e;
    return was;
}

Engine::Engine(Translation translation, py::dict ns, const RunOptions& options)
    : m_tr(std::move(translation)), m_ns(std::move(ns)), m_options(options), m_matcher(m_tr), m_growth(m_tr, options),
      m_native(options) {}

Engine::~Engine() {
    if (g_engine == this) g_engine = nullptr;
}

namespace {
// How many arguments a model's function takes (L-Py calls hooks by it), and whether its code
// reads a global `name`; 0 and false for what is not a Python function.
int arityOf(const py::object& fn) {
    return py::hasattr(fn, "__code__") ? fn.attr("__code__").attr("co_argcount").cast<int>() : 0;
}
bool reads(const py::object& fn, const char* name) {
    return py::hasattr(fn, "__code__") && py::list(fn.attr("__code__").attr("co_names")).contains(py::str(name));
}
}  // namespace

void Engine::bind() {
    const size_t classes = m_tr.classes.size();
    // Set by the INITIALISATION block (context.options.setSelection('Module inheritance', 1)).
    py::object options = py::module_::import("openalea.lpy").attr("_state")["options"];
    {
        // 'Module declaration' mandatory: a module the file uses without a `module` line is
        // an error (L-Py's option; on the fly, its default, declares them).
        py::object mandatory = options.attr("get")("Module declaration");
        if (!mandatory.is_none() && (py::str(mandatory).cast<std::string>() == "Mandatory" ||
                                     (!py::isinstance<py::str>(mandatory) && py::bool_(mandatory)))) {
            std::vector<bool> declared(classes, false);
            for (int c : m_tr.declared)
                if (size_t(c) < classes) declared[size_t(c)] = true;
            for (size_t c = 0; c < classes; ++c)
                if (!m_tr.classes.isPredefined(int(c)) && m_tr.classes.used(int(c)) && !declared[c])
                {
                    const std::string name = m_tr.classes.name(int(c));
                    PyErr_SetString(PyExc_NameError, ("module " + name + " is not declared: with the option 'Module declaration' set to "
                                                      "Mandatory, declare it with `module " + name + "`").c_str());
                    throw py::error_already_set();
                }
        }
    }
    {
        py::object chosen = options.attr("get")("Module inheritance");
        m_matcher.setInheritance(!chosen.is_none() && py::bool_(chosen));
    }
    // Header constants and predicates, evaluated once (in repetitions and alternatives too, and
    // in the patterns a body tests with InLeftContext).
    auto compile = [&](const PatternModule& p) { m_matcher.compile(p, m_ns); };
    m_functions.clear();
    for (size_t r = 0; r < m_tr.rules.size(); ++r) {
        const Rule& rule = m_tr.rules[r];
        m_functions.push_back(m_ns[rule.function.c_str()]);
        const int k = kindIndex(rule.kind);
        m_hasKind[k] = true;
        Index& index = m_index[k][rule.group];
        index.byClass.resize(classes);
        const PatternModule& key = rule.kind == RuleKind::Production ? rule.pred.back() : rule.pred.front();
        const PatternModule& first = rule.pred.front();
        // Forward steps look rules up by their first module, backward ones by their last:
        // a production is in both lists (by its first and its last module).
        auto add = [&](const PatternModule& p, int tag) {
            if (p.cls == ModuleClasses::kStar) index.any.push_back(int(r) | tag);
            else if (size_t(p.cls) < classes) index.byClass[size_t(p.cls)].push_back(int(r) | tag);
            // With inheritance, a rule for A is also tried on the modules derived from A.
            if (p.cls != ModuleClasses::kStar)
                for (size_t c = 0; m_matcher.inherits() && c < classes; ++c)
                    if (m_matcher.derived(int(c), p.cls)) index.byClass[c].push_back(int(r) | tag);
        };
        add(first, 0);
        if (rule.kind == RuleKind::Production) add(key, 1 << 30);
        if (rule.kind != RuleKind::Decomposition) {
            std::function<bool(const PatternModule&)> query = [&](const PatternModule& p) {
                if (p.cls >= 0 && size_t(p.cls) < classes && isQuery(m_tr.classes.name(p.cls))) return true;
                for (const auto& alt : p.alternatives)
                    if (std::any_of(alt.begin(), alt.end(), query)) return true;
                return std::any_of(p.repeat.begin(), p.repeat.end(), query);
            };
            for (const auto* part : {&rule.left, &rule.newLeft, &rule.pred, &rule.newRight, &rule.right})
                if (!std::any_of(part->begin(), part->end(), query)) continue;
                else if (rule.kind == RuleKind::Interpretation) interpretationReadsQueries = true;
                else m_queryRules = true, m_queryGroups.insert(rule.group);
        }
        for (const auto* part : {&rule.left, &rule.newLeft, &rule.pred, &rule.newRight, &rule.right})
            for (const auto& p : *part) compile(p);
    }
    for (const ContextPattern& cp : m_tr.contextPatterns)
        for (const auto& p : cp.modules) compile(p);
    // Depths and the derivation length are whole numbers in range (a float is rounded, as
    // L-Py does; NaN or a huge value is an error, never a cast out of range).
    auto whole = [&](const char* name, double lo, double hi) {
        const double v = py::cast<double>(m_ns[name]);
        if (!(v >= lo && v <= hi))
            throw py::value_error(std::string(name) + " is " + std::to_string(v) + ": Sprout reads " + std::to_string(long(lo)) + " to " +
                                  std::to_string(long(hi)));
        return int(std::lround(v));
    };
    auto depth = [&](const char* name, int fallback) { return m_ns.contains(name) ? whole(name, 0, 100000) : fallback; };
    m_depth[kindIndex(RuleKind::Decomposition)] = depth("__decomposition_max_depth__", 1);
    m_depth[kindIndex(RuleKind::Interpretation)] = depth("__homomorphism_max_depth__", 1);
    if (m_ns.contains("__derivation_length__")) derivationLength = whole("__derivation_length__", 0, 100000);
    // The native path: no hooks, query modules or decomposition.
    bool eligible = m_options.native && !m_queryRules && !m_hasKind[kindIndex(RuleKind::Decomposition)];
    for (const char* hook : {"Start", "End", "StartEach", "EndEach"})
        if (eligible && m_ns.contains(hook)) eligible = false;
    m_native.prepare(m_tr, eligible);
    if (m_matcher.inherits()) m_native.disable();  // the native path matches classes exactly
    m_growth.bind();
    // A `turtle` in an interpretation rule's body, or a hook that takes it.
    m_usesTurtle = false;
    for (size_t r = 0; r < m_tr.rules.size(); ++r)
        if (m_tr.rules[r].kind == RuleKind::Interpretation && reads(m_functions[r], "turtle")) m_usesTurtle = true;
    for (const char* hook : {"StartInterpretation", "EndInterpretation"})
        if (m_ns.contains(hook) && (arityOf(m_ns[hook]) > 0 || reads(m_ns[hook], "turtle"))) m_usesTurtle = true;
}

py::object Engine::callHook(const char* name, const LString* s, bool* replaced, LString* out) {
    if (!m_ns.contains(name)) return py::none();
    py::object fn = m_ns[name];
    if (!PyCallable_Check(fn.ptr())) return py::none();
    const int arity = arityOf(fn);
    py::object ret;
    if (arity == 0 || !s) {
        ret = fn();
    } else {
        auto shared = std::make_shared<LString>(*s);
        py::object lstring = py::cast(PyLstring{shared});
        ret = arity == 1 ? fn(lstring) : fn(lstring, py::none());
        // Changes made through it (lstring[i][k] = v) are kept.
        if (out) *out = *shared;
    }
    if (ret.is_none() || !out) return ret;
    if (py::isinstance<py::tuple>(ret) && py::len(ret) == 2 && !PyLong_Check(PyTuple_GET_ITEM(ret.ptr(), 0))) ret = ret[py::int_(0)];
    if (ret.is_none()) return ret;
    if (py::isinstance<PyLstring>(ret) || py::isinstance<py::list>(ret)) {
        LString next;
        append(next, ret);
        *out = std::move(next);
        if (replaced) *replaced = true;
    }
    return ret;
}

LString Engine::derive(LString s, int steps, std::vector<LString>* everyStep,
                       std::vector<std::shared_ptr<const ContextMatches>>* contexts, int start, int total) {
    iteration = start;
    stopRequested = false;
    m_matcher.readOptions();
    if (total < 0) total = start + steps;
    // The native path has no hooks: where it starts matters only to getIterationNb.
    if (m_native.ok() && start == 0 && total == steps && !debugger) {
        NumString result;
        std::vector<NumString> every;
        if (deriveNumbers(s, steps, everyStep ? &every : nullptr, result, true)) {
            if (everyStep)
                for (const NumString& step : every) everyStep->push_back(toL(step));
            return toL(result);
        }
        iteration = start;  // a value Python would not take: Python from the start
    }
    if (start == 0) callHook("Start", &s, nullptr, &s);
    predictGrowth(s, steps);
    if (contexts) contexts->push_back(nullptr);  // the axiom's: none
    const int prod = kindIndex(RuleKind::Production), dec = kindIndex(RuleKind::Decomposition);
    // Each step is kept (everyStep) as it ends. It is moved there once the next step's
    // production has read it, unless something may change it in place before (StartEach,
    // a selection, query modules filled, a debugger): then it is copied at once.
    bool pending = everyStep != nullptr;
    const bool changedBeforePass = m_ns.contains("StartEach") || (fillQueries && !m_queryGroups.empty()) || debugger;
    int done = 0;
    for (int i = 0; i < steps; ++i) {
        checkCancel();
        if (pending && (changedBeforePass || selectionAlways || selectionRequested || !m_hasKind[prod])) {
            everyStep->push_back(s);
            pending = false;
        }
        if (selectionAlways || selectionRequested) insertSelection(s);
        iteration = start + i;
        callHook("StartEach", &s, nullptr, &s);
        // Direction, group and the string matching options are read after StartEach (so
        // StartEach may set them).
        m_matcher.readOptions();
        LString next;
        // As L-Py: the turtle fills the query modules when the rules of the group in use (with
        // group 0's) read one.
        if (m_hasKind[prod] && fillQueries && (m_queryGroups.count(0) || m_queryGroups.count(group))) fillQueries(s);
        auto matched = contexts ? std::make_shared<ContextMatches>() : nullptr;
        if (m_hasKind[prod]) {
            struct Keep {  // where the pass's contexts matched, until it ends (or throws)
                ContextMatches*& to;
                ~Keep() { to = nullptr; }
            } keep{m_matcher.contexts() = matched.get()};
            if (debugger) debugger.attr("begin")(PyLstring{std::make_shared<LString>(s)}, forwardDirection ? 0 : 1);
            pass(s, next, RuleKind::Production, forwardDirection);
            if (pending) everyStep->push_back(std::move(s)), pending = false;
            s = std::move(next);
            if (debugger) debugger.attr("end")(PyLstring{std::make_shared<LString>(s)});
        }
        if (m_hasKind[dec]) s = decompose(std::move(s), m_depth[dec], RuleKind::Decomposition);
        frameDisplayed = animating || i == steps - 1;
        endEach(s);
        ++done;
        pending = everyStep != nullptr;
        if (contexts) matched->sort(), contexts->push_back(std::move(matched));
        if (stopRequested) break;
    }
    if (pending) everyStep->push_back(s);
    iteration = start + std::max(0, done - 1);
    if (start + done == total) {
        // End(lstring, scene): the scene of the last step (EndEach's, or made now).
        py::object fn = m_ns.contains("End") ? py::object(m_ns["End"]) : py::object();
        if (fn && arityOf(fn) >= 2 && sceneOf) {
            py::object scene = lastScene && !lastScene.is_none() ? lastScene : sceneOfFilled(s);
            auto shared = std::make_shared<LString>(s);
            py::object ret = fn(py::cast(PyLstring{shared}), scene);
            s = *shared;
            if (py::isinstance<PyLstring>(ret) || py::isinstance<py::list>(ret)) {
                LString next;
                append(next, ret);
                s = std::move(next);
            }
        } else {
            callHook("End", &s, nullptr, &s);
        }
    }
    return s;
}

bool Engine::deriveNumbers(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result,
                           bool origins) {
    if (!m_native.derive(axiom, steps, everyStep, result, origins, iteration)) return false;
    ranNative = true;
    return true;
}

void Engine::predictGrowth(const LString& s, int steps) const {
    const int prod = kindIndex(RuleKind::Production), dec = kindIndex(RuleKind::Decomposition);
    if (!m_hasKind[prod] || m_hasKind[dec] || debugger || selectionAlways || selectionRequested || group != 0 ||
        m_ns.contains("StartEach") || m_ns.contains("EndEach"))
        return;
    m_growth.predict(s, steps, iteration, [this](int cls, int base) { return m_matcher.derived(cls, base); });
}

py::object Engine::debugMatch(const char* what, const Rule* r, size_t begin, size_t end, bool forward, const LString& built,
                              const LString* result, const py::tuple* args) {
    // The new string so far, as L-Py's debugger sees it: what was built, with what the rule made.
    auto dest = std::make_shared<LString>();
    if (forward) {
        *dest = built;
        if (result) dest->insert(dest->end(), result->begin(), result->end());
    } else {
        if (result) *dest = *result;
        dest->insert(dest->end(), built.rbegin(), built.rend());
    }
    py::object d = py::cast(PyLstring{dest});
    if (!r) return debugger.attr(what)(begin, d);
    py::object rule = ruleObject ? ruleObject(int(r - m_tr.rules.data()))
                                 : py::module_::import("types").attr("SimpleNamespace")(py::arg("lineno") = r->line, py::arg("name") = r->header,
                                                                                        py::arg("ruleid") = int(r - m_tr.rules.data()));
    py::list values = args ? py::list(*args) : py::list();
    if (result) return debugger.attr(what)(begin, end, d, result->size(), rule, values);
    return debugger.attr(what)(begin, end, d, rule, values);
}

void Engine::insertSelection(LString& s) {
    selectionRequested = false;
    py::object chosen = py::module_::import("openalea.lpy").attr("_selection")();
    if (chosen.is_none()) return;
    std::vector<size_t> at;
    for (py::handle h : chosen) at.push_back(h.cast<size_t>());
    std::sort(at.begin(), at.end());
    const int x = m_tr.classes.intern("X");
    size_t added = 0;
    const size_t size = s.size();
    for (size_t p : at)
        if (p < size) s.insert(s.begin() + std::ptrdiff_t(p + added++), LModule{x, py::tuple()});
}

py::object Engine::sceneOfFilled(LString& s) {
    // L-Py draws the scene a hook receives from the string itself: its turtle writes the
    // query modules (?P, ?H...) it passes, in the string the hook then reads.
    if (fillQueries)
        for (const LModule& m : s)
            if (isQuery(m_tr.classes.name(m.cls))) {
                fillQueries(s);
                break;
            }
    return sceneOf(s);
}

void Engine::endEach(LString& s) {
    lastScene = py::none();
    py::object fn = m_ns.contains("EndEach") ? py::object(m_ns["EndEach"]) : py::object();
    if (!fn || arityOf(fn) < 2) {
        callHook("EndEach", &s, nullptr, &s);
        return;
    }
    py::object scene = frameDisplayed && sceneOf ? sceneOfFilled(s) : py::object(py::none());
    auto shared = std::make_shared<LString>(s);
    py::object ret = fn(py::cast(PyLstring{shared}), scene);
    s = *shared;
    lastScene = scene;
    if (ret.is_none()) return;
    py::object string = ret;
    if (py::isinstance<py::tuple>(ret) && py::len(ret) == 2 && !PyLong_Check(PyTuple_GET_ITEM(ret.ptr(), 0))) {
        string = ret[py::int_(0)];
        lastScene = ret[py::int_(1)];
    } else if (!py::isinstance<PyLstring>(ret) && !py::isinstance<py::list>(ret)) {
        lastScene = ret;  // a scene alone
        return;
    } else {
        lastScene = py::none();  // a new string: its scene is made again
    }
    if (!string.is_none()) {
        LString next;
        append(next, string);
        s = std::move(next);
    }
}

bool Engine::isQuery(const std::string& name) {
    return name.size() == 2 && name[0] == '?' && name[1] != '\0' && std::strchr("PHULRF", name[1]) != nullptr;
}

bool Engine::interprets() const {
    return m_hasKind[kindIndex(RuleKind::Interpretation)] || m_ns.contains("StartInterpretation") || m_ns.contains("EndInterpretation");
}

// StartInterpretation / EndInterpretation: called with the turtle when they take an argument;
// what they produce is drawn first / last.
LString Engine::interpretationHook(const char* name) {
    if (!m_ns.contains(name)) return {};
    py::object fn = m_ns[name];
    if (!PyCallable_Check(fn.ptr())) return {};
    const int arity = arityOf(fn);
    m_buffer.clear();
    m_produced = false;
    py::object ret = arity > 0 ? fn(m_turtle ? m_turtle : py::object(py::none())) : fn();
    LString made = std::move(m_buffer);
    m_buffer.clear();
    if (made.empty() && !ret.is_none()) append(made, ret);
    return made;
}

LString Engine::interpret(const LString& s) {
    // Each module of the result knows its module in `s` (parent), and the rule that drew it.
    LString in = s;
    for (size_t i = 0; i < in.size(); ++i) in[i].parent = std::uint32_t(i), in[i].rule = -1;
    const int k = kindIndex(RuleKind::Interpretation);
    const bool hooks = m_ns.contains("StartInterpretation") || m_ns.contains("EndInterpretation");
    if (!m_hasKind[k] && !hooks) return in;
    struct Turtle {
        Engine& e;
        ~Turtle() { e.m_turtle = py::object(); }
    } turtle{*this};
    if (m_usesTurtle) {
        m_turtle = py::module_::import("openalea.lpy").attr("_InterpretationTurtle")();
        m_ns["turtle"] = m_turtle;
    }
    LString first = interpretationHook("StartInterpretation");
    LString out = m_hasKind[k] ? decompose(std::move(in), m_depth[k], RuleKind::Interpretation) : std::move(in);
    LString last = interpretationHook("EndInterpretation");
    if (first.empty() && last.empty()) return out;
    for (auto* part : {&first, &last})
        for (LModule& m : *part) m.parent = 0, m.rule = -1;
    first.insert(first.end(), std::make_move_iterator(out.begin()), std::make_move_iterator(out.end()));
    first.insert(first.end(), std::make_move_iterator(last.begin()), std::make_move_iterator(last.end()));
    return first;
}

}  // namespace sprout::lpy
