// Expressions: the compiler's names (parameters, variables, arrays, constants) and calls
// (built-in functions, #define macros, cpfg's func()).
#include <cmath>
#include <cstdio>

#include "core/language/expr_compiler.hpp"
#include "core/language/vlab/curve_files.hpp"

namespace sprout {

using namespace expr_detail;

NodePtr ExprCompiler::parseName(int depth) {
    size_t start = m_pos;
    while (m_pos < m_text.size()) {
        if (const size_t g = greekLetter(m_pos)) m_pos += g;  // α, β, θ ...
        else if (std::isalnum(static_cast<unsigned char>(m_text[m_pos])) || m_text[m_pos] == '_') ++m_pos;
        else break;
    }
    std::string name(m_text.substr(start, m_pos - start));
    if (peek("(")) return parseCall(name, start, depth);
    if (m_scope.arrays) {
        for (const GlobalArray& a : *m_scope.arrays)
            if (a.name == name) return parseArrayElement(a, start, depth);
    }
    if (auto arg = m_args.find(name); arg != m_args.end()) return clone(arg->second);
    if (m_scope.params) {
        for (size_t i = 0; i < m_scope.params->size(); ++i) {
            if ((*m_scope.params)[i] == name) {
                auto n = std::make_unique<Node>();
                n->op = Op::Slot;
                n->slot = std::uint16_t(i);
                return n;
            }
        }
    }
    if (m_scope.globals) {
        for (size_t i = 0; i < m_scope.globals->size(); ++i) {
            if ((*m_scope.globals)[i] == name) {
                auto n = std::make_unique<Node>();
                n->op = Op::Slot;
                n->slot = std::uint16_t(kGlobalSlot + i);
                return n;
            }
        }
    }
    if (m_scope.defines) {
        auto it = m_scope.defines->find(name);
        if (it != m_scope.defines->end()) return makeConst(it->second);
    }
    // A function set's function by its name (cpfg defines it: -DNAME=id).
    if (m_scope.curves)
        if (const int id = m_scope.curves->functionId(name)) return makeConst(id);
    auto k = builtinConstants().find(name);
    if (k != builtinConstants().end() && !m_scope.cpfg) return makeConst(k->second);  // cpfg has no pi, e
    if (m_funcArg) {  // func(NAME, x): NAME should be a function of the set
        std::vector<std::string> names = m_scope.curves ? m_scope.curves->functionNames() : std::vector<std::string>{};
        std::string msg = "unknown function '" + name + "' in func()";
        std::string guess = closestMatch(name, names);
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        else if (names.empty()) msg += ": no function set names its functions (func's first argument is then a function's number, 1 for the first)";
        else msg += ": the function set does not name one so";
        fail(start, msg);
        return makeConst(0);
    }
    std::vector<std::string> known;
    if (m_scope.params) known = *m_scope.params;
    if (m_scope.globals) known.insert(known.end(), m_scope.globals->begin(), m_scope.globals->end());
    if (m_scope.defines)
        for (auto& [d, _] : *m_scope.defines) known.push_back(d);
    if (!m_scope.cpfg)
        for (auto& [d, _] : builtinConstants()) known.push_back(d);
    std::string msg = "unknown name '" + name + "'";
    std::string guess = closestMatch(name, known);
    if (m_scope.cpfg) {  // cpfg: an identifier not defined before is a new variable, 0 (lsys_input.y)
        if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
        warn(start, msg + (guess.empty() ? ": " : " ") + "cpfg reads it as a variable never given a value, 0");
        return makeConst(0);
    }
    if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
    else if (!m_scope.params || m_scope.params->empty())
        msg += ": only defined constants can be used here";
    else msg += ": not a parameter of this rule or a defined constant";
    fail(start, msg);
    return makeConst(0);
}

// `a[i][j]`: the element's slot, from the indices in row-major order.
NodePtr ExprCompiler::parseArrayElement(const GlobalArray& a, size_t start, int depth) {
    NodePtr index = arrayIndex(a, start, depth);
    auto n = std::make_unique<Node>();
    n->op = Op::Index;
    n->slot = std::uint16_t(kGlobalSlot + a.first);
    n->value = a.size();
    n->a = std::move(index);
    return n;
}

// The flat index of `[i][j]`: each index truncated to an integer; cpfg's (generate.c) each held
// in its dimension's range and not truncated, the flat index truncated (by Op::Index).
NodePtr ExprCompiler::arrayIndex(const GlobalArray& a, size_t start, int depth) {
    NodePtr index;
    for (size_t k = 0; k < a.dims.size(); ++k) {
        if (!accept("[")) {
            fail(m_pos < m_text.size() ? m_pos : start, "'" + a.name + "' is an array of " +
                 std::to_string(a.dims.size()) + " dimension" + (a.dims.size() == 1 ? "" : "s") +
                 ": give each index in brackets, as in " + a.name + "[0]");
            return makeConst(0);
        }
        NodePtr i = parseTernary(depth + 1);
        if (m_failed) return makeConst(0);
        if (k == 0) m_misreadSlot = cpfgMisreadSlot(*i);
        if (!accept("]")) {
            fail(m_pos < m_text.size() ? m_pos : start, "expected ']' after the index of '" + a.name + "'");
            return makeConst(0);
        }
        auto floorOf = std::make_unique<Node>();
        floorOf->op = m_scope.cpfg ? Op::Clamp : Op::Call1;
        floorOf->fn = m_scope.cpfg ? 0 : truncIndex();
        floorOf->value = a.dims[k];
        floorOf->a = std::move(i);
        if (!index) {
            index = std::move(floorOf);
        } else {
            auto mul = std::make_unique<Node>();
            mul->op = Op::Mul;
            mul->a = std::move(index);
            mul->b = makeConst(a.dims[k]);
            auto add = std::make_unique<Node>();
            add->op = Op::Add;
            add->a = std::move(mul);
            add->b = std::move(floorOf);
            index = std::move(add);
        }
    }
    return index;
}

// The built-in function `name` of one argument applied to `a` (folded when `a` is a constant).
NodePtr ExprCompiler::call1(std::string_view name, NodePtr a) {
    std::uint8_t fn = 0;
    while (fn + 1u < std::size(kFunctions1) && kFunctions1[fn].name != name) ++fn;
    if (a->op == Op::Const) return folded(kFunctions1[fn].fn(a->value));
    auto n = std::make_unique<Node>();
    n->op = Op::Call1;
    n->fn = fn;
    n->a = std::move(a);
    return n;
}

// cpfg's assignment `a[i] = v` is an array's only when the first name or number of its first
// index is followed by another operand (lsys_input.y tests its nextParam): `a[floor(x)] = v`
// and `a[-x] = v` assign v to x. That variable's slot, or -1.
int ExprCompiler::cpfgMisreadSlot(const Node& index) {
    const Node* n = &index;
    const Node* parent = nullptr;
    while (n->a) parent = n, n = n->a.get();
    if (n->op != Op::Slot || !parent || parent->b) return -1;
    return n->slot;
}

std::uint8_t ExprCompiler::truncIndex() {
    for (size_t i = 0; i < std::size(kFunctions1); ++i)
        if (std::string_view(kFunctions1[i].name) == "trunc") return std::uint8_t(i);
    return 0;
}

NodePtr ExprCompiler::parseCall(const std::string& name, size_t start, int depth) {
    size_t open = m_pos;
    accept("(");
    std::vector<NodePtr> args;
    if (!accept(")")) {
        do {
            m_funcArg = name == "func" && args.empty();
            args.push_back(parseTernary(depth + 1));
            m_funcArg = false;
            if (m_failed) return makeConst(0);
        } while (accept(","));
        if (!accept(")")) {
            fail(m_pos < m_text.size() ? m_pos : open,
                 m_pos < m_text.size() ? "expected ',' or ')' in the arguments of '" + name + "'"
                                       : "the '(' of '" + name + "(' is never closed");
            return makeConst(0);
        }
    }
    auto arity = [&](size_t want) {
        if (args.size() == want) return true;
        fail(start, "'" + name + "' takes " + std::to_string(want) + " argument" +
                        (want == 1 ? "" : "s") + ", not " + std::to_string(args.size()));
        return false;
    };
    if (m_scope.macros) {
        if (auto it = m_scope.macros->find(name); it != m_scope.macros->end()) {
            if (!arity(it->second.params.size())) return makeConst(0);
            if (m_macroDepth >= 16) {
                fail(start, "'#define " + name + "' expands into itself too deeply (more than 16 levels)");
                return makeConst(0);
            }
            m_callStart = start;
            return expandMacro(name, it->second, args, depth);
        }
    }
    if (name == "bran" || name == "biran") {  // cpfg: beta and binomial samples
        if (!arity(2)) return makeConst(0);
        auto n = std::make_unique<Node>();
        n->op = name == "bran" ? Op::Beta : Op::Binomial;
        n->a = std::move(args[0]);
        n->b = std::move(args[1]);
        return n;
    }
    if (name == "srand") {  // cpfg: starts the random numbers again from this seed
        if (!arity(1)) return makeConst(0);
        auto n = std::make_unique<Node>();
        n->op = Op::Srand;
        n->a = std::move(args[0]);
        return n;
    }
    if (const std::optional<CurveCall> c = curveCallNamed(name)) return funcCall(*c, name, start, std::move(args));
    // cpfg's names: ran(x) is uniform in [0, x), nran(mean, sigma) normal, random(a, b) uniform.
    if (name == "rand" || name == "uniform" || name == "normal" || name == "gauss" || name == "ran" ||
        name == "nran" || name == "random") {
        bool isNormal = name == "normal" || name == "gauss" || name == "nran";
        if (!isNormal && args.empty()) {
            args.push_back(makeConst(0));
            args.push_back(makeConst(1));
        } else if (!isNormal && args.size() == 1) {
            args.insert(args.begin(), makeConst(0));
        }
        if (!arity(2)) return makeConst(0);
        auto n = std::make_unique<Node>();
        n->op = isNormal ? Op::Normal : Op::Rand;
        n->a = std::move(args[0]);
        n->b = std::move(args[1]);
        return n;
    }
    if (m_scope.cpfg && name == "trunc") {  // cpfg's trunc rounds: floor(x + 0.5) (generate.c)
        if (!arity(1)) return makeConst(0);
        args[0] = binary(Op::Add, std::move(args[0]), makeConst(0.5));
        return call1("floor", std::move(args[0]));
    }
    for (size_t i = 0; i < std::size(kFunctions1); ++i) {
        if (name != kFunctions1[i].name) continue;
        if (!arity(1)) return makeConst(0);
        if (args[0]->op == Op::Const) return folded(kFunctions1[i].fn(args[0]->value));
        auto n = std::make_unique<Node>();
        n->op = Op::Call1;
        n->fn = std::uint8_t(i);
        n->a = std::move(args[0]);
        return n;
    }
    for (size_t i = 0; i < std::size(kFunctions2); ++i) {
        if (name != kFunctions2[i].name) continue;
        if (!arity(2)) return makeConst(0);
        if (args[0]->op == Op::Const && args[1]->op == Op::Const)
            return folded(kFunctions2[i].fn(args[0]->value, args[1]->value));
        auto n = std::make_unique<Node>();
        n->op = Op::Call2;
        n->fn = std::uint8_t(i);
        n->a = std::move(args[0]);
        n->b = std::move(args[1]);
        return n;
    }
    std::string msg = "unknown function '" + name + "'";
    std::string guess = closestMatch(name, builtinFunctionNames());
    if (!guess.empty()) msg += " — did you mean '" + guess + "'?";
    fail(start, msg);
    return makeConst(0);
}

// cpfg's func(id, x), curveX/Y/Z(id, t) and curveGAL(id): the id-th function (a number, or
// a function set's name) or curve of the view file; an id with none gives 0 there, as in
// cpfg, and a warning here.
NodePtr ExprCompiler::funcCall(CurveCall c, const std::string& name, size_t start, std::vector<NodePtr> args) {
    const bool func = c == CurveCall::Func;
    if (!m_scope.curves) {
        fail(start, name + "() needs cpfg's " + (func ? "functions: the view file's 'function:' or 'function set:' lines" :
                                                        "curves: the view file's 'curve:' lines") + " (open the VLab object's folder)");
        return makeConst(0);
    }
    const size_t want = c == CurveCall::CurveLength ? 1 : 2;
    if (args.size() != want) {
        fail(start, "'" + name + "' takes " + (want == 1 ? "1 argument (a curve)" : func ? "2 arguments (a function and x)" :
                                               "2 arguments (a curve and t in [0, 1])") + ", not " + std::to_string(args.size()));
        return makeConst(0);
    }
    if (want == 1) args.push_back(makeConst(0));  // curveGAL(id): the second is not used
    const CurveTables& t = *m_scope.curves;
    if (args[0]->op == Op::Const)
        if (std::string problem = t.idProblem(c, args[0]->value); !problem.empty()) warn(start, std::move(problem));
    if (args[0]->op == Op::Const && args[1]->op == Op::Const) return folded(t.call(c, args[0]->value, args[1]->value));
    auto n = std::make_unique<Node>();
    n->op = Op::Func;
    n->fn = std::uint8_t(c);
    n->a = std::move(args[0]);
    n->b = std::move(args[1]);
    return n;
}

std::string ExprCompiler::formatId(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

// A warning at `at` (inside a #define's body: at its use).
void ExprCompiler::warn(size_t at, std::string msg) {
    ExprCompiler* root = this;
    while (root->m_parent) {
        at = root->m_reportAt;
        msg = "in '#define " + root->m_macroName + "': " + msg;
        root = root->m_parent;
    }
    root->m_sink.warning(root->m_line, root->m_text.substr(std::min(at, root->m_text.size())), std::move(msg));
}

}  // namespace sprout
