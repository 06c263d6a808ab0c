// L-Py's passes over a string (lpy/engine/engine.hpp): for each module the rules tried in
// order (by the index bind() made) and the first that applies called (the Matcher says whether
// its header matches), in a production pass over the whole string, and in a decomposition or
// an interpretation to a depth; the growth budget checked as a pass makes the string.
#include <algorithm>

#include "lpy/engine/engine.hpp"

namespace sprout::lpy {

bool Engine::applies(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, size_t& consumed, LString& result) {
    py::tuple args;
    long leftEnd = 0;
    size_t rightEnd = 0;
    if (!m_matcher.matchAt(r, s, at, forward, built, args, leftEnd, rightEnd)) return false;
    const size_t len = r.pred.size();
    m_buffer.clear();
    m_produced = false;
    // The body's own context tests (InLeftContext ...) start where the header's ended.
    Matcher::BodyScope body(m_matcher, Matcher::BodyContext{&s, leftEnd, rightEnd, r.filter});
    py::object ret = py::reinterpret_steal<py::object>(PyObject_Call(m_functions[size_t(&r - m_tr.rules.data())].ptr(), args.ptr(), nullptr));
    const size_t start = forward ? at : at + 1 - len;
    // (L-Py's debugger is never asked error_match: its binding looks the method up with the
    // body's error pending, finds none, and the error goes on.)
    if (!ret) throw py::error_already_set();
    if (!m_produced && m_buffer.empty()) {
        if (ret.is_none()) {  // a body that produced nothing: the next rule is tried
            if (debugger && r.kind == RuleKind::Production) debugMatch("partial_match", &r, start, start + len, forward, built, nullptr, &args);
            return false;
        }
        append(m_buffer, ret);
    }
    result = std::move(m_buffer);
    m_buffer.clear();
    // A result that starts with None or '*' inserts nothing: the module is deleted.
    if (!result.empty() && (result[0].cls == ModuleClasses::kStar || result[0].cls == ModuleClasses::kNone)) result.clear();
    if (debugger && r.kind == RuleKind::Production) debugMatch("total_match", &r, start, start + len, forward, built, &result, &args);
    consumed = len;
    return true;
}

py::object Engine::applyRule(size_t rule, const py::tuple& args) {
    if (rule >= m_functions.size()) throw py::index_error("rule index out of range");
    m_buffer.clear();
    m_produced = false;
    Matcher::BodyScope body(m_matcher, Matcher::BodyContext{nullptr, -1, 0, m_tr.rules[rule].filter});
    py::object ret = py::reinterpret_steal<py::object>(PyObject_Call(m_functions[rule].ptr(), args.ptr(), nullptr));
    if (!ret) throw py::error_already_set();
    if (!m_produced && m_buffer.empty()) {
        if (ret.is_none()) return py::none();
        append(m_buffer, ret);
    }
    LString result = std::move(m_buffer);
    m_buffer.clear();
    return py::cast(PyLstring{std::make_shared<LString>(std::move(result))});
}

bool Engine::tryRules(RuleKind kind, const LString& s, size_t i, bool forward, LString& out, size_t& consumed) {
    auto& byGroup = m_index[kindIndex(kind)];
    const int cls = s[i].cls;
    const int tag = forward || kind != RuleKind::Production ? 0 : 1 << 30;
    const int groups[2] = {group, 0};
    for (int gi = 0; gi < (group == 0 ? 1 : 2); ++gi) {
        auto it = byGroup.find(groups[gi]);
        if (it == byGroup.end()) continue;
        const Index& index = it->second;
        static const std::vector<int> none;
        const std::vector<int>& a = size_t(cls) < index.byClass.size() ? index.byClass[size_t(cls)] : none;
        const std::vector<int>& b = index.any;
        // Both lists are in declaration order: merged, each rule tried once.
        size_t ia = 0, ib = 0;
        while (ia < a.size() || ib < b.size()) {
            int pick;
            if (ib >= b.size() || (ia < a.size() && (a[ia] & ~(1 << 30)) < (b[ib] & ~(1 << 30)))) pick = a[ia++];
            else pick = b[ib++];
            if ((pick & (1 << 30)) != tag) continue;
            const Rule& r = m_tr.rules[size_t(pick & ~(1 << 30))];
            LString result;
            if (applies(r, s, i, forward, out, consumed, result)) {
                // A production's modules come from the module it rewrote; a decomposition's or
                // an interpretation's from where that module came from (the same step's string).
                const std::uint32_t parent = kind == RuleKind::Production ? std::uint32_t(i) : s[i].parent;
                for (LModule& m : result) m.rule = pick & ~(1 << 30), m.parent = parent;
                if (m_matcher.contexts() && kind == RuleKind::Production && (!r.left.empty() || !r.right.empty()))
                    m_matcher.keepContexts(parent);
                if (forward) out.insert(out.end(), std::make_move_iterator(result.begin()), std::make_move_iterator(result.end()));
                else out.insert(out.end(), std::make_move_iterator(result.rbegin()), std::make_move_iterator(result.rend()));
                return true;
            }
        }
    }
    return false;
}

namespace {
// `%` at i: the rest of its branch goes, its ']' stays (the index of that ']', or the end).
size_t afterCut(const LString& in, size_t i) {
    int depth = 0;
    size_t j = i + 1;
    for (; j < in.size(); ++j) {
        if (in[j].cls == ModuleClasses::kPush) ++depth;
        else if (in[j].cls == ModuleClasses::kPop && depth-- == 0) break;
    }
    return j;
}
}  // namespace

void Engine::pass(const LString& in, LString& out, RuleKind kind, bool forward) {
    Matcher::Reading reading{m_matcher, in};  // the string `$A(a)` patterns bind modules of, while this pass runs
    out.clear();
    out.reserve(in.size());
    m_matcher.matchBrackets(in);
    // The string made is checked as it grows (every 1024 modules read, and at the end), with
    // the bytes of a module measured on the string read.
    const std::size_t perModule = GrowthBudget::moduleBytes(in);
    if (kind == RuleKind::Production) m_growth.predictNextStep(in, perModule, iteration);
    struct Growth {  // the next production pass's prediction
        GrowthBudget& budget;
        const LString& in;
        LString& out;
        bool production;
        ~Growth() {
            if (production) budget.grew(in, out);
        }
    } growth{m_growth, in, out, kind == RuleKind::Production};
    if (forward) {
        for (size_t i = 0; i < in.size();) {
            if ((i & 1023) == 0) checkCancel(), m_growth.check(in, out, perModule, iteration);
            if (in[i].cls == ModuleClasses::kCut) {
                i = afterCut(in, i);
                continue;
            }
            size_t consumed = 1;
            if (tryRules(kind, in, i, true, out, consumed)) {
                i += std::max<size_t>(consumed, 1);
                continue;
            }
            out.push_back(in[i]);
            out.back().rule = -1, out.back().parent = std::uint32_t(i);
            if (debugger && kind == RuleKind::Production) debugMatch("identity", nullptr, i, i, true, out, nullptr, nullptr);
            ++i;
        }
        m_growth.check(in, out, perModule, iteration);
    } else {
        for (size_t i = in.size(); i-- > 0;) {
            if ((i & 1023) == 0) checkCancel(), m_growth.check(in, out, perModule, iteration);
            size_t consumed = 1;
            if (tryRules(kind, in, i, false, out, consumed)) {
                i -= std::min(i, std::max<size_t>(consumed, 1) - 1);
                continue;
            }
            out.push_back(in[i]);
            out.back().rule = -1, out.back().parent = std::uint32_t(i);
            if (debugger && kind == RuleKind::Production) debugMatch("identity", nullptr, i, i, false, out, nullptr, nullptr);
        }
        m_growth.check(in, out, perModule, iteration);
        std::reverse(out.begin(), out.end());
    }
}

LString Engine::partialDerivation(const LString& in, size_t beg, size_t size) {
    // L-Py's Lsystem.partial_derivation (partialForwardStep, partialBackwardStep): the
    // productions applied to the modules from `beg` on, their contexts read in the whole
    // string, then the decompositions; no hook, no debugger.
    if (beg > in.size()) throw py::index_error("partial_derivation: a starting position past the string's end");
    m_matcher.readOptions();
    const size_t end = std::min(in.size(), beg + size);
    py::object told = std::move(debugger);
    struct Restore {
        py::object& to;
        py::object was;
        ~Restore() { to = std::move(was); }
    } restore{debugger, std::move(told)};
    LString out;
    if (m_hasKind[kindIndex(RuleKind::Production)]) {
        Matcher::Reading reading{m_matcher, in};
        m_matcher.matchBrackets(in);
        if (forwardDirection) {
            for (size_t i = beg; i < end;) {
                size_t consumed = 1;
                if (tryRules(RuleKind::Production, in, i, true, out, consumed)) i += std::max<size_t>(consumed, 1);
                else out.push_back(in[i++]);
            }
        } else {
            for (size_t i = end; i-- > beg;) {
                size_t consumed = 1;
                if (tryRules(RuleKind::Production, in, i, false, out, consumed)) i -= std::min(i - beg, std::max<size_t>(consumed, 1) - 1);
                else out.push_back(in[i]);
            }
            std::reverse(out.begin(), out.end());
        }
    } else {
        out.assign(in.begin() + std::ptrdiff_t(beg), in.begin() + std::ptrdiff_t(end));
    }
    const int dec = kindIndex(RuleKind::Decomposition);
    if (m_hasKind[dec]) out = decompose(std::move(out), m_depth[dec], RuleKind::Decomposition);
    return out;
}

LString Engine::decompose(LString in, int depth, RuleKind kind) {
    if (depth <= 0) return in;
    LString out;
    out.reserve(in.size());
    m_matcher.matchBrackets(in);
    for (size_t i = 0; i < in.size();) {
        if ((i & 1023) == 0) checkCancel();
        if (in[i].cls == ModuleClasses::kCut) {
            i = afterCut(in, i);
            continue;
        }
        if (m_turtle && kind == RuleKind::Interpretation) {
            // The turtle's parameters follow its branches, as the walk reaches them.
            if (in[i].cls == ModuleClasses::kPush) m_turtle.attr("_push")();
            else if (in[i].cls == ModuleClasses::kPop) m_turtle.attr("_pop")();
        }
        LString piece;
        size_t consumed = 1;
        if (tryRules(kind, in, i, true, piece, consumed)) {
            // The piece is decomposed again on its own (its contexts see only it).
            if (depth > 1) piece = decompose(std::move(piece), depth - 1, kind);
            out.insert(out.end(), std::make_move_iterator(piece.begin()), std::make_move_iterator(piece.end()));
            i += std::max<size_t>(consumed, 1);
            if (!m_matcher.indexed(in)) m_matcher.matchBrackets(in);
            if (out.size() > m_options.maxModules) throw TooBig("the string grew past " + std::to_string(m_options.maxModules) + " modules");
            continue;
        }
        out.push_back(in[i]);
        ++i;
    }
    return out;
}

}  // namespace sprout::lpy
