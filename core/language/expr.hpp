#pragma once
// Arithmetic expressions in parameters, conditions and directive values, compiled once to a
// small stack-machine program (never re-parsed per application). Constant subtrees are
// folded; a bare parameter or constant skips the interpreter altogether.
//
// Trigonometric functions work in degrees, like the grammar's `angle` and like cpfg.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/base/rng.hpp"
#include "core/language/source.hpp"

namespace sprout {

struct CurveTables;  // core/language/vlab/curve_files.hpp
namespace expr_detail {
struct Node;  // expr_builtins.hpp
}

enum class Op : std::uint8_t {
    Const, Slot, Add, Sub, Mul, Div, Mod, Pow, Neg, Not,
    Lt, Le, Gt, Ge, Eq, Ne, And, Or, Select, Call1, Call2, Rand, Normal,
    Beta, Binomial, Srand,  // cpfg's bran(a, b), biran(n, p) and srand(seed)
    Index,                  // cpfg's arrays: slots[slot + index], value = the array's size
    Func,  // cpfg's func(id, x): a function of the grammar's CurveTables
    // cpfg's own: `/` dividing by 1 where the divisor is 0, `%` of the operands made ints (a
    // divisor 0 gives NaN: cpfg stops), an array's index held in [0, value - 1] (generate.c)
    DivC, ModC, Clamp,
};

struct Instr {
    Op op;
    std::uint8_t fn = 0;     // Call1 / Call2: index into the function table
    std::uint16_t slot = 0;  // Slot
    double value = 0;        // Const
};

class Expr {
public:
    // SlotOpConst / ConstOpSlot: `x*0.7`, `t+1`, `2/x`... the shapes most successor
    // parameters take, evaluated without the interpreter loop (same operation, same rounding).
    // CpfgTree: an expression of cpfg's with ||, && or ?:, run as cpfg's Eval runs it (its
    // short-circuits, and the values its skips leave on the stack), from the tree.
    enum class Kind : std::uint8_t { Const, Slot, SlotOpConst, ConstOpSlot, Program, CpfgTree };

    static Expr constant(double v) {
        Expr e;
        e.m_kind = Kind::Const;
        e.m_value = v;
        return e;
    }

    // `slots` holds the values bound to the formal parameters; `rng` feeds rand()/normal().
    double eval(const double* slots, Rng& rng) const {
        switch (m_kind) {
            case Kind::Const: return m_value;
            case Kind::Slot: return slots[m_slot];
            case Kind::SlotOpConst: return binary(m_op, slots[m_slot], m_value);
            case Kind::ConstOpSlot: return binary(m_op, m_value, slots[m_slot]);
            case Kind::Program: return run(slots, rng);
            default: return runCpfgTree(slots, rng);
        }
    }
    Kind kind() const { return m_kind; }
    // Where the expression is a parameter, or a parameter and a constant added, subtracted
    // or multiplied: x * mul + add with x = slots[slot] gives the same double as eval() for
    // every finite x (mul is +-1 or add is -0, so the product or the sum is exact, fused or not).
    bool affine(std::uint16_t& slot, double& mul, double& add) const {
        slot = m_slot;
        mul = 1;
        add = -0.0;
        if (m_kind == Kind::Slot) return true;
        if (m_kind != Kind::SlotOpConst && m_kind != Kind::ConstOpSlot) return false;
        switch (m_op) {
            case Op::Add: add = m_value; return true;
            case Op::Mul: mul = m_value; return true;
            case Op::Sub:
                if (m_kind == Kind::SlotOpConst) add = -m_value;  // x - c is x + -c
                else mul = -1, add = m_value;                     // c - x is -x + c
                return true;
            default: return false;
        }
    }
    bool isConstant() const { return m_kind == Kind::Const; }
    double constantValue() const { return m_value; }
    bool usesRandom() const { return m_usesRandom; }

private:
    friend class ExprCompiler;
    double run(const double* slots, Rng& rng) const;
    double runCpfgTree(const double* slots, Rng& rng) const;
    static double binary(Op op, double a, double b) {
        switch (op) {
            case Op::Add: return a + b;
            case Op::Sub: return a - b;
            case Op::Mul: return a * b;
            default: return a / b;
        }
    }

    Kind m_kind = Kind::Const;
    Op m_op = Op::Add;
    std::uint16_t m_slot = 0;
    bool m_usesRandom = false;
    double m_value = 0;
    std::vector<Instr> m_code;
    std::shared_ptr<const expr_detail::Node> m_tree;  // CpfgTree
    const CurveTables* m_curves = nullptr;  // func()'s functions (the Grammar keeps them)
};

// A function-like cpfg `#define in(x, y) (x > 0 && y > 0)`: its body is compiled at each
// use with the arguments in place of its parameters (as the C preprocessor would).
struct ExprMacro {
    std::vector<std::string> params;
    std::string body;
};

// cpfg's global variables (assigned in the Start:, StartEach:, EndEach: and End: blocks) live
// in the slots from here on, after a production's parameters and locals (at most 255).
constexpr std::uint16_t kGlobalSlot = 256;

// cpfg's array of global variables (`define: { array a[3][4] = {...}; }`): its elements are the
// global slots kGlobalSlot + first ... in row-major order.
struct GlobalArray {
    std::string name;
    std::uint16_t first = 0;
    std::vector<int> dims;
    int size() const {
        int n = 1;
        for (int d : dims) n *= d;
        return n;
    }
};

struct ExprScope {
    const std::vector<std::string>* params = nullptr;  // slot i is named params[i]
    const std::unordered_map<std::string, double>* defines = nullptr;
    const std::unordered_map<std::string, ExprMacro>* macros = nullptr;
    const std::vector<std::string>* globals = nullptr;  // slot kGlobalSlot + i is named globals[i]
    const std::vector<GlobalArray>* arrays = nullptr;
    // cpfg's functions for func(id, x), and their names (a function set's); null: func() is unknown.
    const CurveTables* curves = nullptr;
    // cpfg's own expressions (a .l file; lsys_input.y, generate.c): `^` left-associative and
    // below unary minus and `!` (-x^2 is (-x)^2), `<>` for `!=`, trunc(x) rounding (floor(x +
    // 0.5)), x/0 is x, `%` of ints, ||, && and ?: evaluated as cpfg's Eval does, an array's
    // indices each held in its range, and an unknown name 0 (a warning), not an error.
    bool cpfg = false;
};

// Where an array's flat index `at` falls in an array of `size` elements: out of range it is
// the nearest end (cpfg does not check; Sprout never reads outside).
inline std::uint16_t arrayOffset(double at, double size) {
    if (!(at > 0)) return 0;
    return std::uint16_t(at >= size - 1 ? size - 1 : at);
}

// Compiles `text`, a view into `line.text`; on failure reports to `sink` and returns nullopt.
std::optional<Expr> compileExpr(std::string_view text, const SourceLine& line, const ExprScope& scope,
                                DiagnosticSink& sink);
// The flat index of the element `text` (`a[i][j]`) of `array`, as reading it computes it (for
// an assignment to it); nullopt when `text` is not such an element. `cpfgMisread`: where cpfg
// assigns instead, for ExprScope::cpfg (`a[floor(x)] = v` assigns v to x: the slot of x), or -1.
std::optional<Expr> compileArrayIndex(std::string_view text, const GlobalArray& array, const SourceLine& line,
                                      const ExprScope& scope, DiagnosticSink& sink, int* cpfgMisread = nullptr);

// Names of the built-in functions (for suggestions and documentation).
std::vector<std::string> builtinFunctionNames();

}  // namespace sprout
