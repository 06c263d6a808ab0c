#include "lpy/engine.hpp"

#include <algorithm>
#include <cstring>
#include <functional>

#include "core/language/module_string.hpp"

namespace sprout::lpy {
namespace {

thread_local Engine* g_engine = nullptr;

constexpr int kindIndex(RuleKind k) { return int(k); }

}  // namespace

Engine* currentEngine() { return g_engine; }

Engine::Engine(Translation translation, py::dict ns, const RunOptions& options)
    : m_tr(std::move(translation)), m_ns(std::move(ns)), m_options(options) {
    g_engine = this;
}

Engine::~Engine() {
    if (g_engine == this) g_engine = nullptr;
}

void Engine::bind() {
    g_engine = this;
    const size_t classes = m_tr.classes.size();
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
        };
        add(first, 0);
        if (rule.kind == RuleKind::Production) add(key, 1 << 30);
        if (rule.kind == RuleKind::Production) {
            std::function<bool(const PatternModule&)> query = [&](const PatternModule& p) {
                if (p.cls >= 0 && size_t(p.cls) < classes && isQuery(m_tr.classes.name(p.cls))) return true;
                return std::any_of(p.repeat.begin(), p.repeat.end(), query);
            };
            for (const auto* part : {&rule.left, &rule.newLeft, &rule.pred, &rule.newRight, &rule.right})
                m_queryRules = m_queryRules || std::any_of(part->begin(), part->end(), query);
        }
        // Header constants and predicates, evaluated once (in repetitions too).
        std::function<void(const PatternModule&)> compile = [&](const PatternModule& p) {
            for (const auto& inner : p.repeat) compile(inner);
            for (const auto& a : p.args) {
                if (a.kind == PatternArg::Kind::Equal)
                    m_constants[&a] = py::reinterpret_steal<py::object>(
                        PyRun_String(a.expr.c_str(), Py_eval_input, m_ns.ptr(), m_ns.ptr()));
                else if (a.kind == PatternArg::Kind::Predicate)
                    m_predicates[&a] = py::reinterpret_steal<py::object>(
                        PyRun_String(("lambda " + a.name + ": " + a.expr).c_str(), Py_eval_input, m_ns.ptr(), m_ns.ptr()));
                if (PyErr_Occurred()) throw py::error_already_set();
            }
        };
        for (const auto* part : {&rule.left, &rule.newLeft, &rule.pred, &rule.newRight, &rule.right})
            for (const auto& p : *part) compile(p);
    }
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
    prepareNative();
}

LString Engine::parse(std::string_view text) {
    std::vector<Diagnostic> diags;
    LString out;
    for (const auto& w : readLstring(text, m_tr.classes, 0, 1, diags)) {
        LModule m;
        m.cls = w.cls;
        if (!w.args.empty()) {
            py::list args;
            for (const auto& a : w.args)
                args.append(py::reinterpret_steal<py::object>(PyRun_String(a.c_str(), Py_eval_input, m_ns.ptr(), m_ns.ptr())));
            if (PyErr_Occurred()) throw py::error_already_set();
            m.args = py::tuple(args);
        }
        if (w.cls >= 0) out.push_back(std::move(m));
    }
    if (!diags.empty()) throw py::value_error(diags[0].message);
    return out;
}

LString Engine::axiom() {
    LString out;
    if (m_tr.axiomIsBlock) {
        m_buffer.clear();
        py::object ret = m_ns["__axiom_block__"]();
        out = std::move(m_buffer);
        if (!ret.is_none()) append(out, ret);
        return out;
    }
    if (m_ns.contains("__axiom__")) append(out, m_ns["__axiom__"]);
    return out;
}

void Engine::append(LString& out, py::handle item) {
    if (PyLong_Check(item.ptr())) {
        const long cls = PyLong_AsLong(item.ptr());
        if (cls < 0 || size_t(cls) >= m_tr.classes.size()) throw py::value_error("produce: not a module");
        out.push_back({int(cls), py::tuple()});
        return;
    }
    if (PyTuple_Check(item.ptr()) && PyTuple_GET_SIZE(item.ptr()) == 2 && PyLong_Check(PyTuple_GET_ITEM(item.ptr(), 0))) {
        const long cls = PyLong_AsLong(PyTuple_GET_ITEM(item.ptr(), 0));
        py::handle args = PyTuple_GET_ITEM(item.ptr(), 1);
        if (cls < 0 || size_t(cls) >= m_tr.classes.size() || !PyTuple_Check(args.ptr())) throw py::value_error("produce: not a module");
        // `A(*xs)`: a sequence given last is unpacked (the translation cannot tell).
        out.push_back({int(cls), py::reinterpret_borrow<py::tuple>(args)});
        return;
    }
    if (PyList_Check(item.ptr())) {
        for (py::handle h : py::reinterpret_borrow<py::list>(item)) append(out, h);
        return;
    }
    if (item.is_none()) return;
    // Modules, module classes and Lstrings made in Python.
    if (py::isinstance<PyModule>(item)) {
        out.push_back(py::cast<PyModule&>(item).get());
        return;
    }
    if (py::isinstance<PyLstring>(item)) {
        const LString& s = *py::cast<PyLstring&>(item).s;
        out.insert(out.end(), s.begin(), s.end());
        return;
    }
    if (py::isinstance<PyModuleClass>(item)) {
        out.push_back({py::cast<PyModuleClass&>(item).cls, py::tuple()});
        return;
    }
    throw py::type_error(std::string("produce: a ") + Py_TYPE(item.ptr())->tp_name + " is not a module (write a module name, $variable for a module held in a variable)");
}

void Engine::produce(py::handle items, bool last) {
    append(m_buffer, items);
    if (last) m_produced = true;
}

bool Engine::skipped(int cls, int filter) const {
    if (filter < 0 || cls == ModuleClasses::kPush || cls == ModuleClasses::kPop) return false;
    const ContextFilter& f = m_tr.filters[size_t(filter)];
    const bool listed = std::find(f.classes.begin(), f.classes.end(), cls) != f.classes.end();
    return f.consider ? !listed : listed;
}

bool Engine::matchModule(const PatternModule& p, const LModule& m, std::vector<py::object>& bound) {
    const size_t n = m.args ? size_t(PyTuple_GET_SIZE(m.args.ptr())) : 0;
    if (p.cls == ModuleClasses::kStar) {
        if (!p.anyName.empty()) bound.push_back(py::str(m_tr.classes.name(m.cls)));
        if (!p.hasParens || (p.anyName.empty() && p.args.empty())) return true;
    } else {
        if (p.cls != m.cls) return false;
        if (!p.hasParens) return n == 0;
    }
    size_t k = 0;
    for (const PatternArg& a : p.args) {
        switch (a.kind) {
            case PatternArg::Kind::Rest: {
                py::list rest;
                for (; k < n; ++k) rest.append(py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(m.args.ptr(), k)));
                bound.push_back(rest);
                continue;
            }
            case PatternArg::Kind::Keywords: bound.push_back(py::dict()); continue;
            default: break;
        }
        if (k >= n) return false;
        py::object v = py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(m.args.ptr(), k++));
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
    return k == n;
}

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

void Engine::matchBrackets(const LString& s) {
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

bool Engine::matchLeft(const std::vector<PatternModule>& ps, const LString& s, long j, int filter, std::vector<py::object>& bound,
                       std::vector<std::uint32_t>* at) {
    const size_t kept = at ? at->size() : 0;
    std::vector<std::vector<py::object>> per(ps.size());
    const bool indexed = m_matchOf == &s && m_match.size() == s.size();
    for (long k = long(ps.size()) - 1; k >= 0; --k) {
        for (;;) {
            if (j < 0) return false;
            const int c = s[size_t(j)].cls;
            if (c == ModuleClasses::kPop) {  // a whole branch before this one: skipped
                const long o = indexed ? m_match[size_t(j)] : partner(s, j);
                if (o < 0) return false;
                j = o - 1;
                continue;
            }
            if (c == ModuleClasses::kPush || skipped(c, filter)) {
                --j;
                continue;
            }
            break;
        }
        if (!matchModule(ps[size_t(k)], s[size_t(j)], per[size_t(k)])) return false;
        if (at) at->push_back(std::uint32_t(j));
        --j;
    }
    for (auto& v : per)
        for (auto& o : v) bound.push_back(std::move(o));
    if (at) std::reverse(at->begin() + long(kept), at->end());  // found right to left
    return true;
}

long Engine::partnerIn(const View& s, size_t j) {
    if (!s.reversed && m_matchOf == s.s && m_match.size() == s.size()) return m_match[j];
    int depth = 0;
    for (size_t k = j; k < s.size(); ++k) {
        const int c = s[k].cls;
        if (c == ModuleClasses::kPush) ++depth;
        else if (c == ModuleClasses::kPop && --depth == 0) return long(k);
    }
    return -1;
}

size_t Engine::matchRight(const std::vector<PatternModule>& ps, const View& s, size_t j, int filter, std::vector<py::object>& bound,
                          std::vector<std::uint32_t>* at) {
    constexpr size_t npos = size_t(-1);
    for (const PatternModule& p : ps) {
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
        for (;;) {
            if (j >= s.size()) return npos;
            const int c = s[j].cls;
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
        if (!matchModule(p, s[j], bound)) return npos;
        if (at) at->push_back(std::uint32_t(j));
        ++j;
    }
    return j;
}

bool Engine::applies(const Rule& r, const LString& s, size_t at, bool forward, const LString& built, size_t& consumed, LString& result) {
    const size_t len = r.pred.size();
    if (!forward && at + 1 < len) return false;
    const size_t start = forward ? at : at + 1 - len;
    if (start + len > s.size()) return false;
    std::vector<py::object> left, newLeft, pred, newRight, right;
    for (size_t k = 0; k < len; ++k)
        if (!matchModule(r.pred[k], s[start + k], pred)) return false;
    const bool keep = m_contexts && (!r.left.empty() || !r.right.empty());
    if (keep) m_left.clear(), m_right.clear();
    if (!r.left.empty() && !matchLeft(r.left, s, long(start) - 1, r.filter, left, keep ? &m_left : nullptr)) return false;
    if (!r.right.empty() && matchRight(r.right, View{&s}, start + len, r.filter, right, keep ? &m_right : nullptr) == size_t(-1))
        return false;
    if (!r.newLeft.empty() && (!forward || !matchLeft(r.newLeft, built, long(built.size()) - 1, r.filter, newLeft))) return false;
    // `>>`: a backward step reads the new string already made to its right (built from the end).
    if (!r.newRight.empty() && (forward || matchRight(r.newRight, View{&built, true}, 0, r.filter, newRight) == size_t(-1))) return false;
    py::tuple args(left.size() + newLeft.size() + pred.size() + newRight.size() + right.size());
    size_t k = 0;
    for (auto* part : {&left, &newLeft, &pred, &newRight, &right})
        for (auto& o : *part) PyTuple_SET_ITEM(args.ptr(), k++, o.release().ptr());
    m_buffer.clear();
    m_produced = false;
    py::object ret = py::reinterpret_steal<py::object>(PyObject_Call(m_functions[size_t(&r - m_tr.rules.data())].ptr(), args.ptr(), nullptr));
    if (!ret) throw py::error_already_set();
    if (!m_produced && m_buffer.empty()) {
        if (ret.is_none()) return false;  // a body that produced nothing: the next rule is tried
        append(m_buffer, ret);
    }
    result = std::move(m_buffer);
    m_buffer.clear();
    // A result that starts with None or '*' inserts nothing: the module is deleted.
    if (!result.empty() && (result[0].cls == ModuleClasses::kStar || result[0].cls == ModuleClasses::kNone)) result.clear();
    consumed = len;
    return true;
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
                if (m_contexts && kind == RuleKind::Production && (!r.left.empty() || !r.right.empty()))
                    m_contexts->add(parent, m_left, m_right);
                if (forward) out.insert(out.end(), std::make_move_iterator(result.begin()), std::make_move_iterator(result.end()));
                else out.insert(out.end(), std::make_move_iterator(result.rbegin()), std::make_move_iterator(result.rend()));
                return true;
            }
        }
    }
    return false;
}

void Engine::checkCancel() {
    if (m_options.cancel && m_options.cancel->load(std::memory_order_relaxed)) throw Cancelled{};
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
    out.clear();
    out.reserve(in.size());
    matchBrackets(in);
    if (forward) {
        for (size_t i = 0; i < in.size();) {
            if ((i & 1023) == 0) checkCancel();
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
            ++i;
            if (out.size() > m_options.maxModules) throw py::value_error("the string grew past " + std::to_string(m_options.maxModules) + " modules");
        }
    } else {
        for (size_t i = in.size(); i-- > 0;) {
            if ((i & 1023) == 0) checkCancel();
            size_t consumed = 1;
            if (tryRules(kind, in, i, false, out, consumed)) {
                i -= std::min(i, std::max<size_t>(consumed, 1) - 1);
                continue;
            }
            out.push_back(in[i]);
            out.back().rule = -1, out.back().parent = std::uint32_t(i);
        }
        std::reverse(out.begin(), out.end());
    }
}

LString Engine::decompose(LString in, int depth, RuleKind kind) {
    if (depth <= 0) return in;
    LString out;
    out.reserve(in.size());
    matchBrackets(in);
    for (size_t i = 0; i < in.size();) {
        if ((i & 1023) == 0) checkCancel();
        if (in[i].cls == ModuleClasses::kCut) {
            i = afterCut(in, i);
            continue;
        }
        LString piece;
        size_t consumed = 1;
        if (tryRules(kind, in, i, true, piece, consumed)) {
            // The piece is decomposed again on its own (its contexts see only it).
            if (depth > 1) piece = decompose(std::move(piece), depth - 1, kind);
            out.insert(out.end(), std::make_move_iterator(piece.begin()), std::make_move_iterator(piece.end()));
            i += std::max<size_t>(consumed, 1);
            if (m_matchOf != &in) matchBrackets(in);
            if (out.size() > m_options.maxModules) throw py::value_error("the string grew past " + std::to_string(m_options.maxModules) + " modules");
            continue;
        }
        out.push_back(in[i]);
        ++i;
    }
    return out;
}

py::object Engine::callHook(const char* name, const LString* s, bool* replaced, LString* out) {
    if (!m_ns.contains(name)) return py::none();
    py::object fn = m_ns[name];
    if (!PyCallable_Check(fn.ptr())) return py::none();
    int arity = 0;
    if (py::hasattr(fn, "__code__")) arity = fn.attr("__code__").attr("co_argcount").cast<int>();
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
                       std::vector<std::shared_ptr<const ContextMatches>>* contexts) {
    iteration = 0;
    stopRequested = false;
    if (m_nativeOk) {
        NumString result;
        std::vector<NumString> every;
        if (deriveNumbers(s, steps, everyStep ? &every : nullptr, result, true)) {
            if (everyStep)
                for (const NumString& step : every) everyStep->push_back(toL(step));
            return toL(result);
        }
        iteration = 0;  // a value Python would not take: Python from the start
    }
    callHook("Start", &s, nullptr, &s);
    if (everyStep) everyStep->push_back(s);
    if (contexts) contexts->push_back(nullptr);  // the axiom's: none
    const int prod = kindIndex(RuleKind::Production), dec = kindIndex(RuleKind::Decomposition);
    int done = 0;
    for (int i = 0; i < steps; ++i) {
        checkCancel();
        iteration = i;
        callHook("StartEach", &s, nullptr, &s);
        // Direction and group are read after StartEach (so StartEach may set them).
        LString next;
        if (m_hasKind[prod] && m_queryRules && fillQueries) fillQueries(s);
        auto matched = contexts ? std::make_shared<ContextMatches>() : nullptr;
        if (m_hasKind[prod]) {
            struct Keep {  // where the pass's contexts matched, until it ends (or throws)
                ContextMatches*& to;
                ~Keep() { to = nullptr; }
            } keep{m_contexts = matched.get()};
            pass(s, next, RuleKind::Production, forwardDirection);
            s = std::move(next);
        }
        if (m_hasKind[dec]) s = decompose(std::move(s), m_depth[dec], RuleKind::Decomposition);
        callHook("EndEach", &s, nullptr, &s);
        ++done;
        if (everyStep) everyStep->push_back(s);
        if (contexts) matched->sort(), contexts->push_back(std::move(matched));
        if (stopRequested) break;
    }
    iteration = std::max(0, done - 1);
    if (done == steps) callHook("End", &s, nullptr, &s);
    return s;
}

bool Engine::isQuery(const std::string& name) {
    return name.size() == 2 && name[0] == '?' && std::strchr("PHULRF", name[1]) != nullptr;
}

bool Engine::interprets() const { return m_hasKind[kindIndex(RuleKind::Interpretation)]; }

LString Engine::interpret(const LString& s) {
    // Each module of the result knows its module in `s` (parent), and the rule that drew it.
    LString in = s;
    for (size_t i = 0; i < in.size(); ++i) in[i].parent = std::uint32_t(i), in[i].rule = -1;
    const int k = kindIndex(RuleKind::Interpretation);
    if (!m_hasKind[k]) return in;
    return decompose(std::move(in), m_depth[k], RuleKind::Interpretation);
}

std::string Engine::text(const NumString& s) const {
    std::string out;
    const double* v = s.params.data();
    for (size_t j = 0; j < s.size(); ++j) {
        const NumString::Shape& m = s.shape(j);
        out += m_tr.classes.name(m.cls);
        if (m.n == 0) continue;
        out += '(';
        for (std::uint32_t k = 0; k < m.n; ++k) {
            if (k) out += ',';
            appendNumber(out, v[k]);
        }
        v += m.n;
        out += ')';
    }
    return out;
}

std::string Engine::text(const LString& s) const {
    std::string out;
    for (const LModule& m : s) {
        out += m_tr.classes.name(m.cls);
        const Py_ssize_t n = m.args ? PyTuple_GET_SIZE(m.args.ptr()) : 0;
        if (n == 0) continue;
        out += '(';
        for (Py_ssize_t k = 0; k < n; ++k) {
            if (k) out += ',';
            PyObject* v = PyTuple_GET_ITEM(m.args.ptr(), k);
            // Ints past 2^53 as Python writes them: a double would round them.
            bool smallInt = false;
            if (PyLong_Check(v) && !PyBool_Check(v)) {
                int overflow = 0;
                const long long i = PyLong_AsLongLongAndOverflow(v, &overflow);
                smallInt = !overflow && i > -(1ll << 53) && i < (1ll << 53);
            }
            if (PyFloat_Check(v) || smallInt) {
                appendNumber(out, PyFloat_Check(v) ? PyFloat_AS_DOUBLE(v) : PyLong_AsDouble(v));
            } else {
                out += py::repr(v).cast<std::string>();
            }
        }
        out += ')';
    }
    return out;
}

}  // namespace sprout::lpy
