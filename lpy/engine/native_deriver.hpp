#pragma once
// The native path (lpy/engine/native_derive.cpp says what it is): a model whose rules are all
// `-->` productions with arithmetic on their numbers (no contexts, hooks, groups, queries, cuts
// or Python values) derives on plain numbers, without a Python call per match. The Engine owns
// one: it compiles the rules when the model is bound (native_rules.cpp) and derives
// (native_derive.cpp, the hot loop).
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/language/expr.hpp"
#include "lpy/engine/lstring.hpp"
#include "lpy/engine/run_options.hpp"
#include "lpy/translate/translate.hpp"

namespace sprout::lpy {

class NativeHelper;  // lpy/engine/native_derive.cpp

class NativeDeriver {
public:
    explicit NativeDeriver(const RunOptions& options) : m_options(options) {}

    // When the model is bound: its rules compiled, or the path off (`eligible` false: the
    // engine found a hook, a query, a decomposition, or the option off).
    void prepare(const Translation& tr, bool eligible);
    void disable() { m_ok = false; }
    bool ok() const { return m_ok; }
    // Derives `steps` steps natively; false when a value is not a finite number (Python would
    // have raised, or the axiom holds other values): then nothing is derived, and the native
    // path is off for this model. `origins`: keep where each module came from (for toL).
    // `iteration`: the engine's, set to each step as it runs.
    bool derive(const LString& axiom, int steps, std::vector<NumString>* everyStep, NumString& result, bool origins,
                int& iteration);
    // The same string as Python holds it (integral numbers as ints where Python has ints).
    static LString toL(const NumString& s);

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
    const RunOptions& m_options;
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
    bool m_ok = false;
    static constexpr int kMaxNativeArity = 32;  // NumString::Shape::ints holds a bit per parameter
};

}  // namespace sprout::lpy
