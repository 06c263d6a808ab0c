#pragma once
// L-Py's derivation (L-Py's src/cpp/lsystem.cpp, described in ../shared/lpy-notes.md and the
// L-Py documentation): a string of modules whose parameters are Python values, rewritten by
// rules whose bodies are Python functions. Runs with the GIL held.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <set>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/base/pod_buffer.hpp"
#include "core/base/recycled.hpp"
#include "core/derive/provenance.hpp"
#include "core/language/expr.hpp"
#include "lpy/engine/run_options.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout::lpy {

namespace py = pybind11;

struct LModule {
    int cls = 0;
    py::tuple args;  // empty when the module has none
    // Where it came from ("why this branch?"): the rule that made it at this step (an index
    // of Translation::rules; -1 copied unchanged or made by Python), and its module in the
    // step before (in the string an interpretation read, for an interpreted module).
    std::int32_t rule = -1;
    std::uint32_t parent = 0;
};
// Its buffers come back to the next derivation (core/base/recycled.hpp): every step is kept,
// and a plant dropped and opened again took its pages from the kernel anew.
using LString = std::vector<LModule, recycled::Allocator<LModule>>;

// A string of the native path (lpy/engine/native_derive.cpp): each module is its shape (class, count of
// numbers, which of them Python holds as ints), 4 bytes, and the numbers of all modules are in
// one array, in order: module k's follow module k - 1's. No Python objects. Drawn and written
// as it is; made into an LString only where Python reads it (the interpretation rules, growth
// stepping). A step reads and writes half the bytes it did with 16-byte modules that held
// their class, numbers' offset and count.
struct NumString {
    struct Shape {
        int cls = 0;
        std::uint32_t n = 0;     // its numbers
        std::uint32_t ints = 0;  // bit a: Python holds number a as an int
    };
    struct Origin {  // as LModule::rule and LModule::parent
        std::int32_t rule = -1;
        std::uint32_t parent = 0;
    };
    // No zeroing, and huge pages from 1 MB: a step writes its string once, into fresh
    // memory, and with 4 KB pages the kernel's page faults took more than half of it. From
    // 1 MB (not 2) the buffers come from the mappings kept between derivations, not from
    // malloc, whose choice between its heap and a fresh mapping for a buffer of 1-2 MB moves
    // with what the process freed before (lpy_bench's 18 steps ran at 150 or at 300 M
    // matches/s depending on how big a module the interpreter had compiled first).
    PodBuffer<std::uint32_t, (1u << 20)> modules;  // an index of `shapes` per module
    PodBuffer<double, (1u << 20)> params;
    PodBuffer<Origin, (1u << 20)> origins;  // one per module when kept, else none
    std::shared_ptr<const std::vector<Shape>> shapes;  // the derivation's, shared by its steps
    size_t size() const { return modules.size(); }
    const Shape& shape(size_t k) const { return (*shapes)[modules[k]]; }
    void swap(NumString& o) noexcept {
        modules.swap(o.modules);
        params.swap(o.params);
        origins.swap(o.origins);
        shapes.swap(o.shapes);
    }
};

// The string as Python sees it (hooks' `lstring`, Lstring(...)), and one module of it: a
// view into a string (writes go to it) or a module of its own.
struct PyLstring {
    PyLstring() = default;
    explicit PyLstring(std::shared_ptr<LString> modules, std::shared_ptr<const NumString> numbers = nullptr)
        : s(std::move(modules)), pending(std::move(numbers)) {}
    std::shared_ptr<LString> s;
    // A native derivation's result (Lsystem.derive on the native path): its modules made only
    // when Python reads them (get()), so a derivation from a script costs what it costs from
    // the command line.
    mutable std::shared_ptr<const NumString> pending;
    LString& get() const;
    size_t size() const;
};
struct PyModule {
    std::shared_ptr<LString> owner;  // set: a view of (*owner)[index]
    size_t index = 0;
    LModule own;
    LModule& get() { return owner ? (*owner)[index] : own; }
};

struct PyModuleClass {
    int cls = 0;
};

// Thrown when the caller cancels between rule calls.
struct Cancelled {};
// A step refused by the growth limits (RunOptions' maxModules, maxBytes): a ValueError in
// Python, an error at the `derivation length:` line in a file's diagnostics.
struct TooBig : py::value_error {
    using py::value_error::value_error;
};

// A Python error raised while running the model: where in the file, and the message.
struct ModelError {
    int line = 0, col = 0;
    std::string message;
};

class NativeHelper;  // lpy/engine/native_derive.cpp

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

    // The native path: a model whose rules are all `-->` productions with arithmetic on
    // their numbers (no contexts, hooks, groups, queries, cuts or Python values) derives
    // without a Python call per match (lpy/engine/native_derive.cpp). Decided by bind().
    bool native() const { return m_nativeOk; }
    bool ranNative = false;  // the last derive() took the native path
    // Derives `steps` steps natively; false when a value is not a finite number (Python would
    // have raised, or the axiom holds other values): then nothing is derived, and the native
    // path is off for this model. `origins`: keep where each module came from (for toL).
    bool deriveNumbers(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result,
                       bool origins);
    // The same string as Python holds it (integral numbers as ints where Python has ints).
    static LString toL(const NumString& s);
    // `InLeftContext(pattern, d)` / `InRightContext` in a rule's body (translation's
    // contextPatterns[index]): matched from where the rule's own context ended, or from the
    // previous such test's end, which then moves past it (so a loop counts a run of modules);
    // the pattern's variables are written into d. Outside a rule's body: an error.
    bool inContext(size_t index, bool left, py::handle dict);
private:
    // Where a running body's context tests start (set by applies() around the call).
    struct BodyContext {
        const LString* s = nullptr;
        long left = -1;      // the next module to the left to read
        size_t right = 0;    // the next module to the right to read
        int filter = -1;
    } m_body;
    // With L-Py's option 'Module inheritance' (rules match derived modules): each class's
    // ancestors, worked out once by bind(); empty without the option.
    std::vector<std::vector<int>> m_ancestors;
    bool derived(int cls, int base) const {
        if (m_ancestors.empty() || size_t(cls) >= m_ancestors.size()) return false;
        const auto& a = m_ancestors[size_t(cls)];
        return std::find(a.begin(), a.end(), base) != a.end();
    }
    // The `turtle` of interpretation rules (openalea.lpy._InterpretationTurtle), while an
    // interpretation runs and only when a rule or hook uses it: its parameters are saved at
    // each '[' and restored at each ']' of the walk.
    bool m_usesTurtle = false;
    py::object m_turtle;
    // Multiscale strings (scales.cpp): the option 'String matching' (0 as a string, 1
    // as an axial tree, 2 multi-level, 3 multiscale; read at each derive) and each class's
    // scale (INT_MAX: none, L-Py's DEFAULT_SCALE).
    int m_stringMatching = 1;
    std::vector<int> m_scale;
    py::object m_lpyModule;  // openalea.lpy, imported once (an import a step was a tenth of a small step)
    // The context state the options were last read from, and its count of changes then
    // ('changes': bumped by the option and scale setters): read again only when either moved.
    py::object m_optionsOf;
    long m_optionsChanges = -1;
    void readMatchingOptions();
    int scaleOf(int cls) const;
    // The module a left context reads after `pos` at scale `target` (-1: none); the one a
    // right context reads from `pos` (the position after the last module matched; npos: none).
    long predecessorAt(const LString& s, long pos, int target, int filter);
    size_t nextAt(const LString& s, size_t pos, int target, int filter);
    bool multiscale() const { return m_stringMatching >= 2; }
public:
    int classScale(int cls) const { return scaleOf(cls); }
private:
    LString interpretationHook(const char* name);
    void endEach(LString& s);
    void insertSelection(LString& s);
    // Tells the debugger of a match (total_match, partial_match) or of a module copied (identity).
    void debugMatch(const char* what, const Rule* r, size_t begin, size_t end, bool forward, const LString& built,
                    const LString* result, const py::tuple* args);  // the EndEach hook, with a scene when it takes two arguments
    struct Index {
        std::vector<std::vector<int>> byClass;  // class -> rules whose first (or last) module is it
        std::vector<int> any;                   // rules starting with '*'
    };
    void pass(const LString& in, LString& out, RuleKind kind, bool forward);
    // The bytes a module of `s` takes, its Python parameters measured on up to 64 of its
    // modules; and the check of a growing string against RunOptions' limits.
    std::size_t moduleBytes(const LString& s) const;
    void checkGrowth(const LString& in, const LString& out, std::size_t perModule) const;
    void predictNextStep(const LString& in, std::size_t perModule) const;  // from m_lastGrowth
    double m_lastGrowth = 1;  // the production pass before: modules made per module read
    // Before the first step (lpy/engine/growth.cpp): the least size of each of the next `steps`
    // steps, followed through the rules that always make the same successor; the first over
    // RunOptions' limits is refused (a ValueError naming it). Nothing is predicted where
    // Python may steer the derivation (growthPredictable, worked out by bind()) or a hook runs
    // between steps.
    bool growthPredictable() const;
    void predictGrowth(const LString& s, int steps) const;
    bool m_predictable = false;
    bool tryRules(RuleKind kind, const LString& s, size_t i, bool forward, LString& out, size_t& consumed);
    bool applies(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, size_t& consumed, LString& result);
    // Whether rule r's header matches at `at` (its predecessor's first module, or last when
    // backward), its variables' values in `args`, where its contexts ended.
    bool matchAt(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, py::tuple& args, long& leftEnd,
                 size_t& rightEnd);
public:
    // L-Py's LsysRule.match / reverse_match: (the position past the match, its values) or False.
    py::object matchRule(size_t rule, const LString& s, long at, bool forward);
private:
    bool matchModule(const PatternModule& p, const LModule& m, std::vector<py::object>& bound);
    // `$A(a)`: the module bound whole, a view of the string a pass reads (m_reading).
    py::object nodeOf(const LModule& m);
    const LString* m_reading = nullptr;
    std::shared_ptr<LString> m_readingShared;
    // `at`: where the modules matched are added (their indices in s), when kept.
    void bindAlternative(const PatternModule& p, size_t matched, std::vector<py::object>& got, std::vector<py::object>& bound);
    // `stop`: set to the position left of the match, when given.
    bool matchLeft(const std::vector<PatternModule>& ps, const LString& s, long from, int filter, std::vector<py::object>& bound,
                   std::vector<std::uint32_t>* at = nullptr, long* stop = nullptr);
    // A string read left to right, or (the new string of a backward step, built from its
    // end) right to left.
    struct View {
        const LString* s;
        bool reversed = false;
        size_t size() const { return s->size(); }
        const LModule& operator[](size_t j) const { return reversed ? (*s)[s->size() - 1 - j] : (*s)[j]; }
    };
    // Matches `ps` from position j; the position after the match, or npos.
    size_t matchRight(const std::vector<PatternModule>& ps, const View& s, size_t j, int filter, std::vector<py::object>& bound,
                      std::vector<std::uint32_t>* at = nullptr);
    long partnerIn(const View& s, size_t j);
    bool skipped(int cls, int filter) const;
    LString decompose(LString piece, int depth, RuleKind kind);
    py::object callHook(const char* name, const LString* s, bool* replaced, LString* out);
    void checkCancel();
    void matchBrackets(const LString& s);

    // While a production pass keeps where contexts matched (derive's `contexts`): the rules'
    // matches go here, the last rule tried's context in m_left / m_right.
    ContextMatches* m_contexts = nullptr;
    std::vector<std::uint32_t> m_left, m_right;
    Translation m_tr;
    py::dict m_ns;
    const RunOptions& m_options;
    std::vector<py::object> m_functions;  // per rule
    std::unordered_map<const PatternArg*, py::object> m_constants, m_predicates;
    static constexpr int kindIndex(RuleKind k) { return int(k); }
    std::unordered_map<int, Index> m_index[3];  // per kind (kindIndex): group -> index
    bool m_hasKind[3] = {false, false, false};
    bool m_queryRules = false;  // a production's header has a query module
    std::set<int> m_queryGroups;  // the groups of those productions
public:
    // The native path's rules (lpy/engine/native_rules.cpp): the class and arity they match, the modules
    // they make with their arguments compiled (Sprout's expressions on the matched numbers).
    struct NativeArg {
        Expr expr;
        bool isFloat = false;    // a float whatever its inputs
        std::uint32_t used = 0;  // the parameters it reads, as bits: an int when all of them are
    };
    struct NativeOut {
        int cls = 0;
        std::vector<NativeArg> args;
    };
    struct NativeRule {
        int cls = 0, arity = 0, index = 0;
        std::uint32_t params = 0;  // the numbers its successor holds
        std::uint32_t firstOut = 0, firstArg = 0;  // in m_flatOuts, m_flatArgs
        bool fast = false;  // its arguments are all fast ones (FastArg), from firstFastArg in m_fastArgs
        std::uint32_t firstFastArg = 0;
        std::vector<NativeOut> outs;
    };
    // The rules laid out flat for the derivation's inner loop: per rule its modules, their
    // arguments.
    struct FlatArg {
        const Expr* expr;
        std::uint64_t need;  // an int when the module's ints hold all of these bits (bit 32: never)
    };
    struct FlatOut {  // a module a rule makes: its count of numbers (its shape: ShapeStep)
        std::uint32_t n;
    };
    // A rule whose arguments are all a parameter times a constant plus a constant
    // (Expr::affine) or a constant: its numbers are written without an Expr call.
    struct FastArg {
        double mul, add;
        std::uint64_t need;  // as FlatArg::need
        std::uint32_t slot;
    };
    // What a step does with a module of one shape (NumString::Shape), found before the
    // derivation for every shape the axiom's can lead to: the inner loop reads one entry per
    // module, and writes the shapes it makes from a list.
    struct ShapeStep {
        enum Kind : std::uint8_t { Copy, Fast, General } kind = Copy;
        std::uint32_t n = 0;          // its numbers (read)
        std::uint32_t nOuts = 1;      // modules made
        std::uint32_t nArgs = 0;      // numbers made
        std::uint32_t firstOut = 0;   // the shapes made: in m_outShapes from here
        std::uint32_t firstArg = 0;   // a fast rule's arguments in m_fastArgs
        std::uint32_t ints = 0;       // its own ints (NumString::Shape::ints)
        std::uint64_t outInts = 0;    // a fast rule's numbers that are ints, as bits
        const NativeRule* rule = nullptr;
    };
    struct Tables {
        const ShapeStep* steps;
        const std::uint32_t* outShapes;
        const FlatOut* flatOuts;
        const FlatArg* flatArgs;
        const FastArg* fastArgs;
    };
    // Where a step writes (modules, their numbers, origins), and the next number it reads.
    struct NativeCursor {
        std::uint32_t* out;
        double* values;
        NumString::Origin* origin;  // null when origins are not kept
        size_t in;
    };
    const NativeRule* nativeRule(int cls, std::uint32_t arity) const;

private:
    // Rewrites cur's modules [begin, end) from c on; false when a value is not one Python
    // would give. `checked`: whether the fast rules' values are checked too (not needed where
    // the step's numbers are too small for them to reach 2^53: nativeStep).
    bool nativeRange(const NumString& cur, size_t begin, size_t end, NativeCursor& c, bool checked) const;
    // What cur's modules [0, end) make (modules, numbers), and the numbers they hold.
    void nativeSize(const NumString& cur, size_t end, std::uint64_t& modules, std::uint64_t& params, std::uint64_t& read) const;
    // The shapes of the axiom's modules and of all they can lead to, with what a step does
    // with each (m_shapes, m_shapeSteps, m_outShapes); false past kMaxShapes.
    std::uint32_t shapeOf(const NumString::Shape& shape);
    bool closeShapes();
    // All of cur, from c on (shared with a second thread when big); throws Cancelled.
    bool nativeStep(const NumString& cur, NativeCursor& c, NativeHelper* helper);
    std::vector<NativeRule> m_native;
    std::vector<std::vector<int>> m_nativeByClass;
    std::vector<FastArg> m_fastArgs;
    std::vector<NumString::Shape> m_shapes;
    std::unordered_map<std::uint64_t, std::uint32_t> m_shapeIds;
    std::vector<ShapeStep> m_shapeSteps;
    std::vector<std::uint32_t> m_outShapes;
    double m_fastScale = 0, m_fastShift = 0;  // over all fast rules
    // The biggest |number| the string can hold at this step (-1: not known, measured), known
    // from step to step where every rule the string meets is a fast one (`m_allFast`).
    double m_bound = -1;
    bool m_allFast = false;
    std::vector<FlatOut> m_flatOuts;
    std::vector<FlatArg> m_flatArgs;
    std::uint32_t m_nativeMaxOuts = 1, m_nativeMaxParams = 0;
    bool m_nativeOk = false;
    static constexpr int kMaxNativeArity = 32;  // NumString::Shape::ints holds a bit per parameter
    void prepareNative();
    int m_depth[3] = {1, 1, 1};
    LString m_buffer;
    bool m_produced = false;
    std::vector<long> m_match;  // bracket partners of the string being rewritten
    const LString* m_matchOf = nullptr;
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
