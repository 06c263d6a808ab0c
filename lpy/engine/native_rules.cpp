// The native path's set-up (lpy/engine/native_derive.cpp says what the path is): which models take it and
// their rules compiled (NativeDeriver::prepare, when the model is bound), and before each derivation
// every module shape the axiom's can lead to, with what a step does with each (closeShapes);
// and the native string made into Python's values (toL). Its own file: none of it runs in a
// step's loop over the modules.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/language/source.hpp"
#include "lpy/engine/engine.hpp"  // Engine::isQuery
#include "lpy/engine/native_deriver.hpp"

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


}  // namespace

void NativeDeriver::prepare(const Translation& tr, bool eligible) {
    m_ok = false;
    m_native.clear();
    m_nativeByClass.assign(tr.classes.size(), {});
    if (!eligible) return;
    for (size_t r = 0; r < tr.rules.size(); ++r) {
        const Rule& rule = tr.rules[r];
        if (rule.kind == RuleKind::Interpretation) continue;  // run in Python on the result
        if (!rule.arrow || rule.group != 0 || rule.filter >= 0 || !rule.left.empty() || !rule.newLeft.empty() ||
            !rule.newRight.empty() || !rule.right.empty() || rule.pred.size() != 1)
            return;
        const PatternModule& p = rule.pred[0];
        if (p.cls == ModuleClasses::kStar || p.isRepeat() || p.isOr() || !p.anyName.empty() || !p.moduleVariable.empty() ||
            p.exactPop || p.cls < 0 ||
            size_t(p.cls) >= tr.classes.size())
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
                w.cls == ModuleClasses::kNone || Engine::isQuery(tr.classes.name(w.cls)) ||
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
            m_flatOuts.push_back({std::uint32_t(o.args.size())});
            for (const NativeArg& a : o.args) m_flatArgs.push_back({&a.expr, a.used | (std::uint64_t(a.isFloat) << 32)});
        }
    }
    m_fastArgs.clear();
    m_fastScale = m_fastShift = 0;
    for (NativeRule& r : m_native) {
        std::vector<FastArg> args;
        double scale = 0, shift = 0;  // the largest |mul| and |add| of its arguments
        bool fast = r.params <= 64;   // its ints are one 64-bit word
        for (const NativeOut& o : r.outs) {
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
        if (!fast) continue;
        r.fast = true;
        r.firstFastArg = std::uint32_t(m_fastArgs.size());
        m_fastArgs.insert(m_fastArgs.end(), args.begin(), args.end());
        m_fastScale = std::max(m_fastScale, scale);
        m_fastShift = std::max(m_fastShift, shift);
    }
    m_ok = true;
}

LString NativeDeriver::toL(const NumString& s) {
    LString out;
    out.reserve(s.size());
    const double* v = s.params.data();
    for (size_t k = 0; k < s.size(); ++k) {
        const NumString::Shape& m = s.shape(k);
        py::tuple args(m.n);
        for (std::uint32_t a = 0; a < m.n; ++a) {
            PyObject* o = m.ints >> a & 1 ? PyLong_FromDouble(v[a]) : PyFloat_FromDouble(v[a]);
            if (!o) throw py::error_already_set();
            PyTuple_SET_ITEM(args.ptr(), a, o);
        }
        v += m.n;
        LModule lm{m.cls, m.n ? std::move(args) : py::tuple()};
        if (k < s.origins.size()) lm.rule = s.origins[k].rule, lm.parent = s.origins[k].parent;
        out.push_back(std::move(lm));
    }
    return out;
}

const NativeDeriver::NativeRule* NativeDeriver::nativeRule(int cls, std::uint32_t arity) const {
    if (cls < 0 || size_t(cls) >= m_nativeByClass.size()) return nullptr;
    for (int r : m_nativeByClass[size_t(cls)])
        if (std::uint32_t(m_native[size_t(r)].arity) == arity) return &m_native[size_t(r)];
    return nullptr;
}

// Past this many shapes (a model whose rules shuffle many ints and floats) the model runs in
// Python: finding them all would cost more than it saves.
constexpr size_t kMaxShapes = 1u << 16;

std::uint32_t NativeDeriver::shapeOf(const NumString::Shape& shape) {
    const std::uint64_t key = std::uint64_t(std::uint32_t(shape.cls)) << 38 | std::uint64_t(shape.n) << 32 | shape.ints;
    auto [it, made] = m_shapeIds.emplace(key, std::uint32_t(m_shapes.size()));
    if (made) m_shapes.push_back(shape);
    return it->second;
}

bool NativeDeriver::closeShapes() {
    m_shapeSteps.clear();
    m_outShapes.clear();
    // The shapes found so far are the work list: each one's step may find more.
    for (std::uint32_t id = 0; id < m_shapes.size(); ++id) {
        if (m_shapes.size() > kMaxShapes) return false;
        const NumString::Shape shape = m_shapes[id];  // a copy: shapeOf grows m_shapes
        ShapeStep k;
        k.n = shape.n;
        k.ints = shape.ints;
        k.firstOut = std::uint32_t(m_outShapes.size());
        const NativeRule* rule = nativeRule(shape.cls, shape.n);
        if (!rule) {
            k.kind = ShapeStep::Copy;
            k.nArgs = shape.n;
            m_outShapes.push_back(id);
        } else {
            // The numbers it makes that are ints: those of int parameters only, never after
            // a '/' or a float literal (FlatArg::need).
            k.kind = rule->fast ? ShapeStep::Fast : ShapeStep::General;
            k.rule = rule;
            k.nOuts = std::uint32_t(rule->outs.size());
            k.nArgs = rule->params;
            k.firstArg = rule->firstFastArg;
            const std::uint64_t notInt = ~std::uint64_t(shape.ints);
            std::uint32_t number = 0;
            for (const NativeOut& o : rule->outs) {
                std::uint32_t ints = 0;
                for (std::uint32_t a = 0; a < o.args.size(); ++a, ++number) {
                    const NativeArg& arg = o.args[a];
                    const bool isInt = ((arg.used | (std::uint64_t(arg.isFloat) << 32)) & notInt) == 0;
                    ints |= std::uint32_t(isInt) << a;
                    if (isInt && number < 64) k.outInts |= std::uint64_t(1) << number;
                }
                m_outShapes.push_back(shapeOf({o.cls, std::uint32_t(o.args.size()), ints}));
            }
        }
        m_shapeSteps.push_back(k);
    }
    return true;
}

}  // namespace sprout::lpy
