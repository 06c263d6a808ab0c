// L-Py's rules matched along a string (lpy/engine/match.hpp): a module's pattern matched (its
// parameters bound as Python values, header constants and predicates checked), the contexts
// left and right of it (skipping branches and the modules a filter ignores), a rule's header
// at a position, and a body's own context tests. One file: a match and everything it calls,
// so that it stays inlined; the passes that try the rules are the Engine's (passes.cpp).

// Index of this file:
//   [SECTION] binding: inheritance, header constants and predicates
//   [SECTION] a module matched
//   [SECTION] the bracket index
//   [SECTION] left contexts
//   [SECTION] a body's context tests
//   [SECTION] right contexts
//   [SECTION] a rule's header

#include <algorithm>

#include "lpy/engine/match.hpp"

namespace sprout::lpy {

//-----------------------------------------------------------------------------
// [SECTION] binding: inheritance, header constants and predicates
//-----------------------------------------------------------------------------
void Matcher::setInheritance(bool on) {
    m_ancestors.clear();
    if (on)
        for (size_t c = 0; c < m_tr.classes.size(); ++c) m_ancestors.push_back(m_tr.classes.ancestors(int(c)));
}

void Matcher::compile(const PatternModule& p, py::dict& ns) {
    for (const auto& inner : p.repeat) compile(inner, ns);
    for (const auto& alt : p.alternatives)
        for (const auto& inner : alt) compile(inner, ns);
    for (const auto& a : p.args) {
        if (a.kind == PatternArg::Kind::Equal)
            m_constants[&a] = py::reinterpret_steal<py::object>(
                PyRun_String(a.expr.c_str(), Py_eval_input, ns.ptr(), ns.ptr()));
        else if (a.kind == PatternArg::Kind::Predicate)
            m_predicates[&a] = py::reinterpret_steal<py::object>(
                PyRun_String(("lambda " + a.name + ": " + a.expr).c_str(), Py_eval_input, ns.ptr(), ns.ptr()));
        if (PyErr_Occurred()) throw py::error_already_set();
    }
}

//-----------------------------------------------------------------------------
// [SECTION] a module matched
//-----------------------------------------------------------------------------
bool Matcher::skipped(int cls, int filter) const {
    if (filter < 0 || cls == ModuleClasses::kPush || cls == ModuleClasses::kPop) return false;
    const ContextFilter& f = m_tr.filters[size_t(filter)];
    const bool listed = std::find(f.classes.begin(), f.classes.end(), cls) != f.classes.end();
    return f.consider ? !listed : listed;
}

py::object Matcher::nodeOf(const LModule& m) {
    PyNodeModule node;
    if (m_reading && &m >= m_reading->data() && &m < m_reading->data() + m_reading->size()) {
        // A view of the string read (a copy made once a pass, when a pattern asks for one):
        // its place, its parent and sons.
        if (!m_readingShared) m_readingShared = std::make_shared<LString>(*m_reading);
        node.owner = m_readingShared;
        node.index = size_t(&m - m_reading->data());
        node.detached = true;
        node.own = m;
    } else {
        node.own = m;
    }
    return py::cast(std::move(node));
}

bool Matcher::matchModule(const PatternModule& p, const LModule& m, std::vector<py::object>& bound) {
    const size_t n = m.args ? size_t(PyTuple_GET_SIZE(m.args.ptr())) : 0;
    // `*(*args)`, `*(**kwds)`: a star module's values are its name, then its parameters.
    bool nameFirst = false;
    if (p.cls == ModuleClasses::kStar) {
        if (!p.anyName.empty()) bound.push_back(py::str(m_tr.classes.name(m.cls)));
        if (!p.hasParens || (p.anyName.empty() && p.args.empty())) return true;
        nameFirst = p.anyName.empty();
    } else {
        if (p.cls != m.cls && !derived(m.cls, p.cls)) return false;
        if (!p.moduleVariable.empty()) {
            bound.push_back(nodeOf(m));
            return true;
        }
        if (!p.hasParens) return n == 0;
    }
    const size_t total = n + (nameFirst ? 1 : 0);
    auto value = [&](size_t k) {
        if (nameFirst) {
            if (k == 0) return py::object(py::str(m_tr.classes.name(m.cls)));
            --k;
        }
        return py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(m.args.ptr(), k));
    };
    size_t k = 0;
    for (size_t ai = 0; ai < p.args.size(); ++ai) {
        const PatternArg& a = p.args[ai];
        if (a.kind == PatternArg::Kind::Rest || a.kind == PatternArg::Kind::Keywords) {
            // The values left: those the module's declaration names (its last parameters, by
            // name; 'name' for a star's name) go to **kwds, the others to *args (L-Py's
            // test_kwd). Without **kwds, *args takes them all; without *args, a value with
            // no name means no match.
            const bool hasKeywords = p.args.back().kind == PatternArg::Kind::Keywords;
            const auto& names = m_tr.classes.parameterNames[size_t(m.cls)];
            const size_t named = std::min(names.size(), n);
            auto nameOf = [&](size_t j) -> const std::string* {  // j: index in the values
                static const std::string star = "name";
                if (nameFirst && j == 0) return &star;
                const size_t param = j - (nameFirst ? 1 : 0);
                if (param + named < n) return nullptr;
                return &names[param - (n - named)];
            };
            py::list rest;
            py::dict kw;
            for (size_t j = k; j < total; ++j) {
                const std::string* name = hasKeywords ? nameOf(j) : nullptr;
                if (name) kw[py::str(*name)] = value(j);
                else rest.append(value(j));
            }
            k = total;
            const bool hasRest = a.kind == PatternArg::Kind::Rest;
            if (!hasRest && py::len(rest) > 0) return false;
            if (hasRest) bound.push_back(rest);
            if (hasKeywords) bound.push_back(kw);
            break;
        }
        if (k >= total) return false;
        py::object v = value(k++);
        switch (a.kind) {
            case PatternArg::Kind::Skip: break;
            case PatternArg::Kind::Bind: bound.push_back(std::move(v)); break;
            case PatternArg::Kind::Equal: {
                const int eq = PyObject_RichCompareBool(v.ptr(), m_constants[&a].ptr(), Py_EQ);
                if (eq < 0) throw py::error_already_set();
                if (!eq) return false;
                break;
            }
            case PatternArg::Kind::Predicate: {
                py::object ok = m_predicates[&a](v);
                bound.push_back(std::move(v));
                if (!ok.cast<bool>()) return false;
                break;
            }
            default: break;
        }
    }
    return k == total;
}

//-----------------------------------------------------------------------------
// [SECTION] the bracket index
//-----------------------------------------------------------------------------
namespace {
// The bracket that closes/opens the one at j, by counting (strings not indexed).
long partner(const LString& s, long j) {
    const bool open = s[size_t(j)].cls == ModuleClasses::kPush;
    int depth = 0;
    for (long k = j; k >= 0 && size_t(k) < s.size(); k += open ? 1 : -1) {
        const int c = s[size_t(k)].cls;
        if (c == ModuleClasses::kPush) depth += open ? 1 : -1;
        else if (c == ModuleClasses::kPop) depth += open ? -1 : 1;
        if (depth == 0) return k;
    }
    return -1;
}
}  // namespace

void Matcher::matchBrackets(const LString& s) {
    m_match.assign(s.size(), -1);
    std::vector<long> stack;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i].cls == ModuleClasses::kPush) stack.push_back(long(i));
        else if (s[i].cls == ModuleClasses::kPop && !stack.empty()) {
            m_match[i] = stack.back();
            m_match[size_t(stack.back())] = long(i);
            stack.pop_back();
        }
    }
    m_matchOf = &s;
}

//-----------------------------------------------------------------------------
// [SECTION] left contexts
//-----------------------------------------------------------------------------
// or(...)'s variables: None for each alternative's before and after the one that matched.
void Matcher::bindAlternative(const PatternModule& p, size_t matched, std::vector<py::object>& got, std::vector<py::object>& bound) {
    auto nones = [&](size_t a) {
        const int n = a < p.alternativeVariables.size() ? p.alternativeVariables[a] : 0;
        for (int v = 0; v < n; ++v) bound.push_back(py::none());
    };
    for (size_t a = 0; a < matched; ++a) nones(a);
    for (auto& o : got) bound.push_back(std::move(o));
    for (size_t a = matched + 1; a < p.alternatives.size(); ++a) nones(a);
}

bool Matcher::matchLeft(const std::vector<PatternModule>& ps, const LString& s, long j, int filter, std::vector<py::object>& bound,
                       std::vector<std::uint32_t>* at, long* stop) {
    const size_t kept = at ? at->size() : 0;
    std::vector<std::vector<py::object>> per(ps.size());
    const bool indexed = m_matchOf == &s && m_match.size() == s.size();
    for (long k = long(ps.size()) - 1; k >= 0; --k) {
        if (ps[size_t(k)].isOr()) {
            // The first alternative that matches leftwards from j (their modules are not kept in `at`).
            const PatternModule& p = ps[size_t(k)];
            size_t matched = p.alternatives.size();
            std::vector<py::object> got;
            for (size_t a = 0; a < p.alternatives.size() && matched == p.alternatives.size(); ++a) {
                std::vector<py::object> one;
                long stopAt = j;
                if (p.alternatives[a].empty() || matchLeft(p.alternatives[a], s, j, filter, one, nullptr, &stopAt)) {
                    matched = a;
                    got = std::move(one);
                    j = stopAt;
                }
            }
            if (matched == p.alternatives.size()) return false;
            bindAlternative(p, matched, got, per[size_t(k)]);
            continue;
        }
        if (ps[size_t(k)].isRepeat()) {
            // Greedy, leftwards: as many repetitions as match (none at the string's start);
            // each variable a list of its values in the string's order.
            const PatternModule& p = ps[size_t(k)];
            std::vector<std::vector<py::object>> found;
            for (int count = 0; count < p.repeatMax; ++count) {
                std::vector<py::object> one;
                long stopAt = j;
                if (!matchLeft(p.repeat, s, j, filter, one, nullptr, &stopAt) || stopAt == j) break;
                found.push_back(std::move(one));
                j = stopAt;
            }
            if (int(found.size()) < p.repeatMin) return false;
            std::vector<py::list> lists(size_t(p.repeatVariables));
            for (auto it = found.rbegin(); it != found.rend(); ++it)
                for (size_t v = 0; v < it->size() && v < lists.size(); ++v) lists[v].append((*it)[v]);
            for (auto& l : lists) per[size_t(k)].push_back(std::move(l));
            continue;
        }
        const bool none = ps[size_t(k)].cls == ModuleClasses::kNone;  // `None < A`: nothing before
        if (multiscale() && !none && ps[size_t(k)].cls != ModuleClasses::kPush && ps[size_t(k)].cls != ModuleClasses::kPop) {
            const long m = predecessorAt(s, j + 1, scaleOf(ps[size_t(k)].cls), filter);
            if (m < 0 || !matchModule(ps[size_t(k)], s[size_t(m)], per[size_t(k)])) return false;
            if (at) at->push_back(std::uint32_t(m));
            j = m - 1;
            continue;
        }
        for (;;) {
            if (j < 0) {
                if (none) break;
                return false;
            }
            const int c = s[size_t(j)].cls;
            if (c == ModuleClasses::kPop) {  // a whole branch before this one: skipped
                const long o = indexed ? m_match[size_t(j)] : partner(s, j);
                if (o < 0) return false;
                j = o - 1;
                continue;
            }
            // A '[' the pattern asks for is matched (`[ I(x) [ < I(y)`: the branch's own
            // bracket); any other '[' is left behind on the way down the tree.
            if ((c == ModuleClasses::kPush && ps[size_t(k)].cls != ModuleClasses::kPush) || skipped(c, filter)) {
                --j;
                continue;
            }
            break;
        }
        if (none) {
            if (j >= 0) return false;
            continue;
        }
        if (!matchModule(ps[size_t(k)], s[size_t(j)], per[size_t(k)])) return false;
        if (at) at->push_back(std::uint32_t(j));
        --j;
    }
    for (auto& v : per)
        for (auto& o : v) bound.push_back(std::move(o));
    if (at) std::reverse(at->begin() + long(kept), at->end());  // found right to left
    if (stop) *stop = j;
    return true;
}

//-----------------------------------------------------------------------------
// [SECTION] a body's context tests
//-----------------------------------------------------------------------------
bool Matcher::inContextText(const std::string& text, bool left, py::handle dict, py::dict& ns) {
    if (!m_body.s) throw py::value_error(std::string(left ? "inLeftContext" : "inRightContext") + " is called outside a rule's body");
    auto found = m_textPatterns.find(text);
    if (found == m_textPatterns.end()) {
        std::vector<Diagnostic> diags;
        ContextPattern p = readContextPattern(text, m_tr.classes, diags);
        for (const Diagnostic& d : diags)
            if (d.severity == Severity::Error) throw py::value_error(std::string(left ? "inLeftContext" : "inRightContext") + "('" + text + "'): " + d.message);
        found = m_textPatterns.emplace(text, std::move(p)).first;  // its place kept: compile() keys by address
        for (const auto& m : found->second.modules) compile(m, ns);
    }
    return inContext(found->second, left, dict);
}

bool Matcher::inContext(size_t index, bool left, py::handle dict) {
    if (!m_body.s) throw py::value_error(std::string(left ? "InLeftContext" : "InRightContext") + " is called outside a rule's body");
    if (index >= m_tr.contextPatterns.size()) throw py::index_error("no such context pattern");
    return inContext(m_tr.contextPatterns[index], left, dict);
}

bool Matcher::inContext(const ContextPattern& p, bool left, py::handle dict) {
    std::vector<py::object> bound;
    if (left) {
        long stop = m_body.left;
        if (!p.modules.empty() && !matchLeft(p.modules, *m_body.s, m_body.left, m_body.filter, bound, nullptr, &stop)) return false;
        m_body.left = stop;
    } else {
        const size_t end = p.modules.empty() ? m_body.right : matchRight(p.modules, View{m_body.s}, m_body.right, m_body.filter, bound);
        if (end == size_t(-1)) return false;
        m_body.right = end;
    }
    if (!dict.is_none())
        for (size_t k = 0; k < bound.size() && k < p.names.size(); ++k) dict[py::str(p.names[k])] = bound[k];
    return true;
}

//-----------------------------------------------------------------------------
// [SECTION] right contexts
//-----------------------------------------------------------------------------
long Matcher::partnerIn(const View& s, size_t j) {
    if (!s.reversed && m_matchOf == s.s && m_match.size() == s.size()) return m_match[j];
    int depth = 0;
    for (size_t k = j; k < s.size(); ++k) {
        const int c = s[k].cls;
        if (c == ModuleClasses::kPush) ++depth;
        else if (c == ModuleClasses::kPop && --depth == 0) return long(k);
    }
    return -1;
}

size_t Matcher::matchRight(const std::vector<PatternModule>& ps, const View& s, size_t j, int filter, std::vector<py::object>& bound,
                          std::vector<std::uint32_t>* at) {
    constexpr size_t npos = size_t(-1);
    for (const PatternModule& p : ps) {
        if (p.isOr()) {
            size_t matched = p.alternatives.size(), end = npos;
            std::vector<py::object> got;
            for (size_t a = 0; a < p.alternatives.size() && matched == p.alternatives.size(); ++a) {
                std::vector<py::object> one;
                const size_t kept = at ? at->size() : 0;
                const size_t e = p.alternatives[a].empty() ? j : matchRight(p.alternatives[a], s, j, filter, one, at);
                if (e == npos) {
                    if (at) at->resize(kept);
                    continue;
                }
                matched = a, end = e, got = std::move(one);
            }
            if (matched == p.alternatives.size()) return npos;
            bindAlternative(p, matched, got, bound);
            j = end;
            continue;
        }
        if (p.isRepeat()) {
            // Greedy: as many repetitions as match, each variable a list of its values.
            std::vector<py::list> lists(size_t(p.repeatVariables));
            int count = 0;
            for (; count < p.repeatMax; ++count) {
                std::vector<py::object> one;
                const size_t kept = at ? at->size() : 0;
                const size_t end = matchRight(p.repeat, s, j, filter, one, at);
                if (end == npos || end == j) {
                    if (at) at->resize(kept);  // not a repetition
                    break;
                }
                for (size_t k = 0; k < one.size() && k < lists.size(); ++k) lists[k].append(one[k]);
                j = end;
            }
            if (count < p.repeatMin) return npos;
            for (auto& l : lists) bound.push_back(std::move(l));
            continue;
        }
        if (p.cls == ModuleClasses::kPop && !p.exactPop) {
            // `]` in the pattern: to the end of the branch the match is in.
            int depth = 0;
            for (; j < s.size(); ++j) {
                if (s[j].cls == ModuleClasses::kPush) ++depth;
                else if (s[j].cls == ModuleClasses::kPop && depth-- == 0) break;
            }
            if (j >= s.size()) return npos;
            ++j;
            continue;
        }
        const bool none = p.cls == ModuleClasses::kNone;  // `A > None`: nothing after, on this axis
        if (multiscale() && !none && p.cls != ModuleClasses::kPush && p.cls != ModuleClasses::kPop && !s.reversed) {
            size_t m = nextAt(*s.s, j, scaleOf(p.cls), filter);
            while (m != npos && s[m].cls == ModuleClasses::kPush) {  // a side branch: skipped
                const long o = partnerIn(s, m);
                if (o < 0) return npos;
                m = nextAt(*s.s, size_t(o) + 1, scaleOf(p.cls), filter);
            }
            if (m == npos || s[m].cls == ModuleClasses::kPop || !matchModule(p, s[m], bound)) return npos;
            if (at) at->push_back(std::uint32_t(m));
            j = m + 1;
            continue;
        }
        for (;;) {
            if (j >= s.size()) {
                if (none) break;
                return npos;
            }
            const int c = s[j].cls;
            if (none && c == ModuleClasses::kPop) break;
            if (c == ModuleClasses::kPush && p.cls != ModuleClasses::kPush) {  // a side branch: skipped
                const long o = partnerIn(s, j);
                if (o < 0) return npos;
                j = size_t(o) + 1;
                continue;
            }
            if (c == ModuleClasses::kPop && p.cls != ModuleClasses::kPop) return npos;
            if (skipped(c, filter)) {
                ++j;
                continue;
            }
            break;
        }
        if (none) {
            if (j < s.size() && s[j].cls != ModuleClasses::kPop) return npos;
            continue;
        }
        if (!matchModule(p, s[j], bound)) return npos;
        if (at) at->push_back(std::uint32_t(j));
        ++j;
    }
    return j;
}

//-----------------------------------------------------------------------------
// [SECTION] a rule's header
//-----------------------------------------------------------------------------
bool Matcher::matchAt(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, py::tuple& args, long& leftEnd,
                     size_t& rightEnd) {
    const size_t len = r.pred.size();
    if (!forward && at + 1 < len) return false;
    const size_t start = forward ? at : at + 1 - len;
    if (start + len > s.size()) return false;
    std::vector<py::object> left, newLeft, pred, newRight, right;
    for (size_t k = 0; k < len; ++k)
        if (!matchModule(r.pred[k], s[start + k], pred)) return false;
    const bool keep = m_contexts && (!r.left.empty() || !r.right.empty());
    if (keep) m_left.clear(), m_right.clear();
    leftEnd = long(start) - 1;
    if (!r.left.empty() && !matchLeft(r.left, s, long(start) - 1, r.filter, left, keep ? &m_left : nullptr, &leftEnd)) return false;
    rightEnd = start + len;
    if (!r.right.empty() &&
        (rightEnd = matchRight(r.right, View{&s}, start + len, r.filter, right, keep ? &m_right : nullptr)) == size_t(-1))
        return false;
    if (!r.newLeft.empty() && (!forward || !matchLeft(r.newLeft, built, long(built.size()) - 1, r.filter, newLeft))) return false;
    // `>>`: a backward step reads the new string already made to its right (built from the end).
    if (!r.newRight.empty() && (forward || matchRight(r.newRight, View{&built, true}, 0, r.filter, newRight) == size_t(-1))) return false;
    args = py::tuple(left.size() + newLeft.size() + pred.size() + newRight.size() + right.size());
    size_t k = 0;
    for (auto* part : {&left, &newLeft, &pred, &newRight, &right})
        for (auto& o : *part) PyTuple_SET_ITEM(args.ptr(), k++, o.release().ptr());
    return true;
}

py::object Matcher::matchRule(size_t rule, const LString& s, long at, bool forward) {
    if (rule >= m_tr.rules.size() || at < 0 || size_t(at) >= s.size()) return py::bool_(false);
    const Rule& r = m_tr.rules[rule];
    matchBrackets(s);
    py::tuple args;
    long leftEnd = 0;
    size_t rightEnd = 0;
    const bool matched = matchAt(r, s, size_t(at), forward, LString(), args, leftEnd, rightEnd);
    m_matchOf = nullptr;  // s is the caller's: its brackets are not kept
    if (!matched) return py::bool_(false);
    const long len = long(r.pred.size());
    return py::make_tuple(forward ? at + len : at - len, py::list(args));
}

}  // namespace sprout::lpy
