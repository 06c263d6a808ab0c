#pragma once
// The expression compiler (internal to core/language): text to tree (expr.cpp: operators,
// numbers, the code; expr_names.cpp: names, calls, arrays), the tree to a stack program, or,
// for cpfg's ||, && and ?: (which cpfg evaluates its own way), kept as cpfg's tree
// (expr_run.cpp runs both).
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/language/expr.hpp"
#include "core/language/expr_builtins.hpp"
#include "core/language/vlab/curve_files.hpp"

namespace sprout {

class ExprCompiler {
    using Node = expr_detail::Node;
    using NodePtr = expr_detail::NodePtr;

public:
    ExprCompiler(std::string_view text, const SourceLine& line, const ExprScope& scope,
                 DiagnosticSink& sink)
        : m_text(text), m_line(line), m_scope(scope), m_sink(sink) {}

    // The body of a function-like #define, compiled where it is used: its errors are
    // reported at the use, naming the macro.
    NodePtr expandMacro(const std::string& name, const ExprMacro& macro, std::vector<NodePtr>& args, int depth);

    std::optional<Expr> compile();
    std::optional<Expr> compileIndex(const GlobalArray& array);  // compileArrayIndex
    int misreadSlot() const { return m_misreadSlot; }

private:
    void fail(size_t at, std::string msg);
    // The whole UTF-8 character at `at`, for messages.
    std::string codePointAt(size_t at) const;
    // A Greek letter (U+0391..U+03C9) at `i`: its two bytes, else 0 (names such as α).
    size_t greekLetter(size_t i) const;
    void skipSpace();
    bool peek(std::string_view tok);
    bool accept(std::string_view tok);
    NodePtr binary(Op op, NodePtr a, NodePtr b);
    NodePtr guard(int depth);
    NodePtr parseTernary(int depth);
    // `and`, `or`, `not` as words (Python's and ABOP's notes), not the start of a longer name.
    bool acceptWord(std::string_view word);
    NodePtr parseOr(int depth);
    NodePtr parseAnd(int depth);
    // Python's `not` binds looser than comparisons: `not x > 1` is `!(x > 1)`.
    NodePtr parseNot(int depth);
    NodePtr parseEquality(int depth);
    NodePtr parseRelational(int depth);
    NodePtr parseAdditive(int depth);
    NodePtr parseMultiplicative(int depth);
    NodePtr parseUnary(int depth);
    NodePtr unary(Op op, NodePtr a);
    // ^ binds tighter than unary minus (-x^2 is -(x^2)) and is right-associative.
    NodePtr parsePower(int depth);
    NodePtr parseCpfgPower(int depth);  // ExprScope::cpfg's `^`, unary minus and `!`
    NodePtr parseCpfgUnary(int depth);
    NodePtr parsePrimary(int depth);
    NodePtr parseNumber();
    NodePtr parseName(int depth);
    // `a[i][j]`: the element's slot, from the indices in row-major order.
    NodePtr parseArrayElement(const GlobalArray& a, size_t start, int depth);
    NodePtr arrayIndex(const GlobalArray& a, size_t start, int depth);  // the flat index of its [i][j]
    static std::uint8_t truncIndex();
    static int cpfgMisreadSlot(const Node& index);
    NodePtr call1(std::string_view name, NodePtr a);
    NodePtr parseCall(const std::string& name, size_t start, int depth);
    // cpfg's func(id, x): the id-th function of the view file (a number, or a function set's
    // name); an id with no function gives 0 there, as in cpfg, and a warning here.
    NodePtr funcCall(CurveCall c, const std::string& name, size_t start, std::vector<NodePtr> args);
    static std::string formatId(double v);
    // A warning at `at` (inside a #define's body: at its use).
    void warn(size_t at, std::string msg);

    // The code for `n`; counts its stack's depth and its ||, && and ?: (cpfg's short-circuits).
    void emit(const Node& n, Expr& e, int& depth, int& maxDepth, int& shortCircuits);

    std::string_view m_text;
    const SourceLine& m_line;
    const ExprScope& m_scope;
    DiagnosticSink& m_sink;
    ExprCompiler* m_parent = nullptr;  // set while compiling a macro body
    std::string m_macroName;
    size_t m_reportAt = 0, m_callStart = 0;
    int m_macroDepth = 0;
    std::unordered_map<std::string, const Node*> m_args;  // macro parameters -> argument trees
    size_t m_pos = 0;
    bool m_failed = false;
    bool m_funcArg = false;     // compiling func()'s first argument
    int m_nodes = 0;
    int m_misreadSlot = -1;     // arrayIndex: cpfgMisreadSlot of its first index
};

}  // namespace sprout
