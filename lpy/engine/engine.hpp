#pragma once
// L-Py's derivation (L-Py's src/cpp/lsystem.cpp, described in ../shared/lpy-notes.md and the
// L-Py documentation): a string of modules whose parameters are Python values, rewritten by
// rules whose bodies are Python functions. Runs with the GIL held. The Engine binds a model,
// runs its steps and hooks (engine.cpp) and its passes over a string (passes.cpp), and owns
// its roles: the Matcher (match.hpp), the GrowthBudget (growth.hpp) and the NativeDeriver
// (native_deriver.hpp). L-Py's strings are in lstring.hpp.
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/derive/provenance.hpp"
#include "lpy/engine/growth.hpp"
#include "lpy/engine/lstring.hpp"
#include "lpy/engine/match.hpp"
#include "lpy/engine/native_deriver.hpp"
#include "lpy/engine/run_options.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout::lpy {

namespace py = pybind11;

// A Python error raised while running the model: where in the file, and the message.
struct ModelError {
    int line = 0, col = 0;
    std::string message;
};

class Engine {
public:
    Engine(Translation translation, py::dict ns, const RunOptions& options);
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // After the file's code ran: finds the rule functions, evaluates header constants and
    // predicates, and indexes the rules. Throws py::error_already_set.
    void bind();
    LString axiom();
    // Runs the derivation as L-Py's derive(): Start, then for each step StartEach,
    // production, decomposition, EndEach, Stop; End after the last step.
    // `contexts` (with everyStep): per step, where the contexts of the rules that made it
    // matched in the step before (the derivation inspector's "context matched").
    // `start`: the iteration the first step is (L-Py's derive(lstring, start, nb): Start is
    // called when it is 0, End when the last step is iteration `total` - 1; total < 0: start
    // + steps).
    LString derive(LString s, int steps, std::vector<LString>* everyStep,
                   std::vector<std::shared_ptr<const ContextMatches>>* contexts = nullptr, int start = 0, int total = -1);
    // The string with the interpretation rules applied (depth from `maximum depth:`).
    LString interpret(const LString& s);
    bool interprets() const;  // the model has interpretation rules or Start/EndInterpretation
    std::string text(const LString& s) const;
    std::string text(const NumString& s) const;

    // Called by Python (produce, nproduce and the control functions).
    void produce(py::handle items, bool last);
    void append(LString& out, py::handle item);
    const Translation& translation() const { return m_tr; }
    ModuleClasses& classes() { return m_tr.classes; }  // grows as Python names new modules
    py::dict& ns() { return m_ns; }
    int iteration = 0;
    bool forwardDirection = true;
    int group = 0;
    bool stopRequested = false;
    int derivationLength = 1;
    // L-Py's query modules (?P ?H ?U ?L ?R ?F): when a production's header has one, each step
    // first interprets the string with a turtle that makes no picture and writes the turtle's
    // state into them (set by the host, which knows the turtle's settings).
    std::function<void(LString&)> fillQueries;
    // The scene the turtle draws from a string (a PlantGL Scene in Python), for
    // EndEach(lstring, scene); set by the host. Without it EndEach receives None.
    std::function<py::object(const LString&)> sceneOf;
    py::object sceneOfFilled(LString& s);
    // An interpretation rule's header has a query module (L-Py's turtle fills a query module
    // as it passes it, before the rules after it are tried: interpreter.cpp's fillQueries then walks
    // twice where a query module had no value yet).
    bool interpretationReadsQueries = false;  // sceneOf, the string's query modules filled first (as L-Py's turtle fills them)
    // L-Py's frame display: EndEach gets a scene at the steps whose frame is shown (every
    // step while animating, else the last of a derive call); what it left as the scene to
    // show (lastScene: the one computed, the one it returned, None when it changed the string).
    bool animating = false;
    // L-Py's selection (setSelectionAlwaysRequired, requestSelection): before a step, the
    // positions the plotter's selection() gives get an X module inserted.
    bool selectionAlways = false, selectionRequested = false;
    // L-Py's Lsystem.setDebugger: an object told of every production step's matches (begin,
    // total_match, partial_match, identity, end); derivations with one take the Python path.
    py::object debugger;
    bool frameDisplayed = false;
    py::object lastScene;
    static bool isQuery(const std::string& name);
    LString parse(std::string_view lstring);

    // The native path (native_deriver.hpp): a model whose rules are all `-->` productions
    // with arithmetic on their numbers derives without a Python call per match. Decided by
    // bind().
    bool native() const { return m_native.ok(); }
    bool ranNative = false;  // the last derive() took the native path
    // Derives `steps` steps natively; false when a value is not a finite number (Python would
    // have raised, or the axiom holds other values): then nothing is derived, and the native
    // path is off for this model. `origins`: keep where each module came from (for toL).
    bool deriveNumbers(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result,
                       bool origins);
    // The same string as Python holds it (integral numbers as ints where Python has ints).
    static LString toL(const NumString& s) { return NativeDeriver::toL(s); }
    // `InLeftContext(pattern, d)` / `InRightContext` in a rule's body (Matcher::inContext).
    bool inContext(size_t index, bool left, py::handle dict) { return m_matcher.inContext(index, left, dict); }
    // `inLeftContext(p, d)` with a pattern made at run time.
    bool inContextText(const std::string& text, bool left, py::handle dict) { return m_matcher.inContextText(text, left, dict, m_ns); }
    int classScale(int cls) const { return m_matcher.scaleOf(cls); }
    // L-Py's LsysRule.match / reverse_match: (the position past the match, its values) or False.
    py::object matchRule(size_t rule, const LString& s, long at, bool forward) { return m_matcher.matchRule(rule, s, at, forward); }
    // L-Py's LsysRule.__call__: the rule's body called on `args` outside a pass (what it
    // produced, or None when it produced nothing). Throws py::error_already_set.
    py::object applyRule(size_t rule, const py::tuple& args);
    // L-Py's Lsystem.partial_derivation: one step of the productions on `size` modules from
    // `beg` (contexts read in all of `s`), then the decompositions.
    LString partialDerivation(const LString& s, size_t beg, size_t size);
    // L-Py's Lsystem.decompositionMaxDepth / interpretationMaxDepth (`maximum depth:`).
    int& maxDepth(RuleKind kind) { return m_depth[kindIndex(kind)]; }
    // What the debugger is given as a rule: ruleObject(index in the translation's rules)
    // when set (openalea.lpy's LsysRule), else a namespace with its lineno, name and ruleid.
    py::object ruleObject;

private:
    // The `turtle` of interpretation rules (openalea.lpy._InterpretationTurtle), while an
    // interpretation runs and only when a rule or hook uses it: its parameters are saved at
    // each '[' and restored at each ']' of the walk.
    bool m_usesTurtle = false;
    py::object m_turtle;
    LString interpretationHook(const char* name);
    void endEach(LString& s);
    void insertSelection(LString& s);
    // Tells the debugger of a match (total_match, partial_match) or of a module copied (identity).
    py::object debugMatch(const char* what, const Rule* r, size_t begin, size_t end, bool forward, const LString& built,
                          const LString* result, const py::tuple* args);  // the EndEach hook, with a scene when it takes two arguments
    // Before the first step: the growth budget's prediction, where no hook or Python can
    // steer the steps between them.
    void predictGrowth(const LString& s, int steps) const;
    // The passes (passes.cpp): each module's rules tried in order, the first that applies
    // called; a production pass over a string, a decomposition or interpretation to a depth.
    struct Index {
        std::vector<std::vector<int>> byClass;  // class -> rules whose first (or last) module is it
        std::vector<int> any;                   // rules starting with '*'
    };
    void pass(const LString& in, LString& out, RuleKind kind, bool forward);
    bool tryRules(RuleKind kind, const LString& s, size_t i, bool forward, LString& out, size_t& consumed);
    bool applies(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, size_t& consumed, LString& result);
    LString decompose(LString piece, int depth, RuleKind kind);
    py::object callHook(const char* name, const LString* s, bool* replaced, LString* out);
    void checkCancel() { lpy::checkCancel(m_options); }

    Translation m_tr;
    py::dict m_ns;
    const RunOptions& m_options;
    std::vector<py::object> m_functions;  // per rule
    static constexpr int kindIndex(RuleKind k) { return int(k); }
    std::unordered_map<int, Index> m_index[3];  // per kind (kindIndex): group -> index
    bool m_hasKind[3] = {false, false, false};
    bool m_queryRules = false;  // a production's header has a query module
    std::set<int> m_queryGroups;  // the groups of those productions
    int m_depth[3] = {1, 1, 1};
    LString m_buffer;
    bool m_produced = false;
    // Its roles, which hold references to m_tr and m_options.
    Matcher m_matcher;
    GrowthBudget m_growth;
    NativeDeriver m_native;
};

// The engine running on this thread (Python's builtins reach it through this).
Engine* currentEngine();
// Makes `e` the engine of this thread; gives the one before.
Engine* setCurrentEngine(Engine* e);

// Strings and Python values as an engine reads and writes them, without one (the Python
// API's Lstrings made outside a derivation): `classes` names the modules (new names are
// interned into it), an lstring's arguments are evaluated in `ns`.
LString parseLstring(std::string_view text, ModuleClasses& classes, py::handle ns);
void appendValue(LString& out, py::handle item, size_t classCount);
// As L-Py writes a string (its AxialTree::str, or repr: each parameter's Python str(), or
// repr(); a float as Python writes it, `7.0`).
std::string writeLstring(const LString& s, const ModuleClasses& classes, bool repr = false);
// Python's repr of a float: the shortest digits that read back the same, with `.0` on a whole
// number, and an exponent below 1e-4 and from 1e16 on (`1e-05`, `1e+16`).
void appendPythonFloat(std::string& out, double v);

}  // namespace sprout::lpy
