// The growth budget on L-Py's Python path (issue 39): the string's bytes measured (its
// Python parameters included) and checked as a pass makes it, and the growth of the rules
// that always make the same successor followed before the first step, so that a derivation
// whose step k would be over the limits is refused before it starts, not after the steps
// before k have taken their time.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>

#include "core/derive/derive.hpp"
#include "lpy/engine/growth.hpp"

namespace sprout::lpy {

namespace {
// sys.getsizeof(o), read off the object for the numbers and tuples modules are made of (a
// call of sys.getsizeof each was most of measuring a small string, every step): their type's
// __sizeof__, and for a tuple the collector's header, as sys.getsizeof adds it.
struct SizeOf {
    py::object getsizeof = py::module_::import("sys").attr("getsizeof");
    std::size_t tupleHeader = getsizeof(py::tuple()).cast<std::size_t>() - std::size_t(PyTuple_Type.tp_basicsize);
    std::size_t operator()(py::handle o) const {
        PyObject* p = o.ptr();
        PyTypeObject* t = Py_TYPE(p);
        if (PyFloat_CheckExact(p)) return std::size_t(t->tp_basicsize);
        if (PyTuple_CheckExact(p)) return std::size_t(t->tp_basicsize) + std::size_t(PyTuple_GET_SIZE(p)) * std::size_t(t->tp_itemsize) + tupleHeader;
#if PY_VERSION_HEX < 0x030C0000  // an int's digits are its size until 3.12
        if (PyLong_CheckExact(p))  // at least one digit, as int.__sizeof__ counts it
            return std::size_t(t->tp_basicsize) + std::size_t(std::max<Py_ssize_t>(std::abs(Py_SIZE(p)), 1)) * std::size_t(t->tp_itemsize);
#endif
        return getsizeof(o).cast<std::size_t>();
    }
};
}  // namespace

std::size_t GrowthBudget::moduleBytes(const LString& s) {
    if (s.empty()) return sizeof(LModule);
    static const SizeOf* sizeOf = new SizeOf();  // never freed: at exit Python is gone
    const size_t stride = std::max<size_t>(1, s.size() / 64);
    std::size_t total = 0, n = 0;
    for (size_t i = 0; i < s.size(); i += stride, ++n) {
        const LModule& m = s[i];
        if (m.args.empty()) continue;
        total += (*sizeOf)(m.args);
        for (py::handle a : m.args) total += (*sizeOf)(a);
    }
    return sizeof(LModule) + total / std::max<std::size_t>(n, 1);
}

void GrowthBudget::check(const LString& in, const LString& out, std::size_t perModule, int iteration) const {
    const std::uint64_t bytes = std::uint64_t(in.size() + out.size()) * perModule;
    if (out.size() <= m_options.maxModules && bytes <= m_options.maxBytes) return;
    const std::string lower = "lower the derivation length (to " + std::to_string(iteration) + " at most)";
    if (out.size() > m_options.maxModules)
        throw TooBig("step " + std::to_string(iteration + 1) + ": the string grew past " + withThousands(m_options.maxModules) +
                     " modules; " + lower + " or raise the limit (--max-modules)");
    throw TooBig("step " + std::to_string(iteration + 1) + ": the string grew past " + withThousands(out.size()) + " modules of about " +
                 std::to_string(perModule) + " bytes each (their Python parameters measured), over the memory budget of " +
                 humanBytes(m_options.maxBytes) + " with the string before it; " + lower + " or raise the budget (--max-memory)");
}

void GrowthBudget::predictNextStep(const LString& in, std::size_t perModule, int iteration) const {
    // The step grows the string as the step before did: refused before it starts when that is
    // over the limits.
    if (m_lastGrowth <= 1) return;
    const double predicted = double(in.size()) * m_lastGrowth, bytes = (double(in.size()) + predicted) * double(perModule);
    const bool modules = predicted > double(m_options.maxModules);
    if (!modules && bytes <= double(m_options.maxBytes)) return;
    char grew[32];
    std::snprintf(grew, sizeof grew, "%.2f", m_lastGrowth);
    throw TooBig("step " + std::to_string(iteration + 1) + " would make about " + withThousands(std::uint64_t(predicted)) +
                 " modules (the step before grew " + grew + " times), " + humanBytes(std::uint64_t(bytes)) +
                 " with the string before it (" + std::to_string(perModule) + " bytes a module, its Python parameters measured), over the " +
                 (modules ? "limit of " + withThousands(m_options.maxModules) + " modules" : "memory budget of " + humanBytes(m_options.maxBytes)) +
                 "; lower the derivation length or raise the " + (modules ? "limit (--max-modules)" : "budget (--max-memory)"));
}

namespace {
enum class Match { Never, Maybe, Always };

// Whether a rule's single predecessor module `p` matches a module of class `cls` with `arity`
// values (-1: unknown), as Matcher::matchModule decides.
Match matchOf(const PatternModule& p, int cls, int arity, const std::function<bool(int, int)>& derived) {
    if (cls < 0) return Match::Maybe;
    if (p.cls == ModuleClasses::kStar) {
        if (!p.hasParens || (p.anyName.empty() && p.args.empty())) return Match::Always;
        return Match::Maybe;
    }
    if (p.cls != cls && !derived(cls, p.cls)) return Match::Never;
    if (!p.moduleVariable.empty()) return Match::Always;
    if (arity < 0) return Match::Maybe;
    if (!p.hasParens) return arity == 0 ? Match::Always : Match::Never;
    size_t fixed = 0;
    bool rest = false;
    for (const PatternArg& a : p.args) {
        switch (a.kind) {
            case PatternArg::Kind::Bind:
            case PatternArg::Kind::Skip: ++fixed; break;
            case PatternArg::Kind::Rest: rest = true; break;
            default: return Match::Maybe;  // a value compared, a predicate, **kwds
        }
    }
    if (rest) return size_t(arity) >= fixed ? Match::Always : Match::Never;
    return size_t(arity) == fixed ? Match::Always : Match::Never;
}
}  // namespace

bool GrowthBudget::growthPredictable() const {
    // A derivation Python could steer (stop it, change the rules' group, insert or replace
    // modules between steps) or cut, or whose rules read several modules: not predicted.
    for (const char* word : {"Stop", "useGroup", "requestSelection", "setSelectionAlwaysRequired"})
        for (const std::string* code : {&m_tr.mainCode, &m_tr.initCode})
            for (size_t at = code->find(word); at != std::string::npos; at = code->find(word, at + 1)) {
                const size_t end = at + std::string_view(word).size();
                auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
                if ((at == 0 || !ident((*code)[at - 1])) && (end >= code->size() || !ident((*code)[end]))) return false;
            }
    if (m_tr.writesCut) return false;
    for (const Rule& r : m_tr.rules)
        if (r.kind == RuleKind::Production && (r.pred.size() != 1 || r.pred[0].isRepeat() || r.pred[0].isOr())) return false;
    return true;
}

void GrowthBudget::predict(const LString& s, int steps, int iteration, const std::function<bool(int, int)>& derived) const {
    if (steps <= 0 || !m_predictable) return;
    for (const LModule& m : s)
        if (m.cls == ModuleClasses::kCut) return;
    // The symbols: a class with its count of values (-1: unknown, or the class unknown: a
    // `$v` or `*args`), from the string's modules and the successors of the rules they meet.
    std::map<std::pair<int, int>, int> ids;
    std::vector<std::pair<int, int>> symbols;
    auto idOf = [&](int cls, int arity) {
        auto [it, fresh] = ids.emplace(std::pair{cls, arity}, int(symbols.size()));
        if (fresh) symbols.push_back({cls, arity});
        return it->second;
    };
    std::vector<double> count;
    for (const LModule& m : s) {
        const int id = idOf(m.cls, m.args ? int(PyTuple_GET_SIZE(m.args.ptr())) : 0);
        if (size_t(id) >= count.size()) count.resize(size_t(id) + 1, 0);
        ++count[size_t(id)];
    }
    // Per symbol: whether it may stay as it is, may become nothing we can count (a body that
    // may not produce: at least nothing), or the successors it may become (symbol ids).
    struct Fate {
        bool stays = true, unknown = false;
        std::vector<std::vector<int>> options;
    };
    std::vector<Fate> fates;
    bool exact = true;
    for (size_t id = 0; id < symbols.size(); ++id) {  // symbols grows as successors are met
        const auto [cls, arity] = symbols[id];
        Fate f;
        if (cls < 0) f.unknown = true;
        for (size_t ri = 0; ri < m_tr.rules.size() && !f.unknown; ++ri) {
            const Rule& r = m_tr.rules[ri];
            if (r.kind != RuleKind::Production || r.group != 0) continue;
            Match m = matchOf(r.pred[0], cls, arity, derived);
            if (m == Match::Never) continue;
            const bool contexts = !r.left.empty() || !r.right.empty() || !r.newLeft.empty() || !r.newRight.empty();
            if (!r.alwaysProduces) {
                f.unknown = true;  // its body decides
                break;
            }
            std::vector<int> succ;
            for (const WrittenModule& w : r.successor) {
                int a = int(w.args.size());
                for (const std::string& arg : w.args)
                    if (!arg.empty() && arg[0] == '*') a = -1;
                succ.push_back(w.cls < 0 || !w.variable.empty() ? idOf(-1, -1) : idOf(w.cls, a));
            }
            f.options.push_back(std::move(succ));
            if (m == Match::Always && !contexts) {
                f.stays = false;
                break;
            }
        }
        if (f.unknown || f.stays != f.options.empty() || f.options.size() > 1) exact = false;
        fates.push_back(std::move(f));
    }
    count.resize(symbols.size(), 0);
    const size_t S = symbols.size();
    // What one symbol becomes after j steps, at least: modules, and bytes. A module's bytes
    // are those its class's modules in the string take (their Python parameters measured, on
    // up to 64 modules a class), or for a class the rules bring in, the module and the tuple
    // of its values (sys.getsizeof's 40 + 8 a value), its values not counted.
    std::vector<double> mods(S, 1.0), bytes(S), nextMods(S), nextBytes(S);
    std::vector<double> measured(S, 0), sampled(S, 0);
    if (!s.empty()) {
        py::object getsizeof = py::module_::import("sys").attr("getsizeof");
        const size_t stride = std::max<size_t>(1, s.size() / 256);
        for (size_t i = 0; i < s.size(); i += stride) {
            const LModule& m = s[i];
            const size_t id = size_t(ids.at({m.cls, m.args ? int(PyTuple_GET_SIZE(m.args.ptr())) : 0}));
            if (sampled[id] >= 64) continue;
            double b = double(sizeof(LModule));
            if (m.args && PyTuple_GET_SIZE(m.args.ptr()) > 0) {
                b += getsizeof(m.args).cast<double>();
                for (py::handle a : m.args) b += getsizeof(a).cast<double>();
            }
            measured[id] += b, ++sampled[id];
        }
    }
    bool estimated = false;  // a measured size is in the bytes (a module's parameters may change)
    for (size_t id = 0; id < S; ++id) {
        const int a = std::max(0, symbols[id].second);
        bytes[id] = double(sizeof(LModule)) + (a > 0 ? 40.0 + 8.0 * a : 0.0);
        if (sampled[id] > 0 && measured[id] / sampled[id] > bytes[id]) bytes[id] = measured[id] / sampled[id], estimated = true;
    }
    double before = 0;  // the string before step k, at least
    for (size_t id = 0; id < S; ++id) before += count[id] * bytes[id];
    constexpr double kHuge = 1e30;
    for (int k = 1; k <= steps; ++k) {
        double total = 0, totalBytes = 0;
        for (size_t id = 0; id < S; ++id) {
            const Fate& f = fates[id];
            double m = f.stays ? mods[id] : kHuge, b = f.stays ? bytes[id] : kHuge;
            if (f.unknown) m = b = 0;
            for (const auto& succ : f.options) {
                double pm = 0, pb = 0;
                for (int t : succ) pm += mods[size_t(t)], pb += bytes[size_t(t)];
                m = std::min(m, pm), b = std::min(b, pb);
            }
            nextMods[id] = std::min(m, kHuge), nextBytes[id] = std::min(b, kHuge);
            total += count[id] * nextMods[id], totalBytes += count[id] * nextBytes[id];
        }
        const bool settled = nextMods == mods && nextBytes == bytes;  // every step after is this one
        mods.swap(nextMods), bytes.swap(nextBytes);
        const bool overModules = total > double(m_options.maxModules);
        if (overModules || totalBytes + before > double(m_options.maxBytes)) {
            auto clamp = [](double v) { return v >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max() : std::uint64_t(v); };
            const std::string modules = total >= 1e19 ? std::string("more than 10^19") : withThousands(clamp(total));
            const std::string size = totalBytes + before >= 1e19 ? std::string("more than 10^19 bytes") : humanBytes(clamp(totalBytes + before));
            const int step = iteration + k;
            const std::string lower = exact && (overModules || !estimated)
                                          ? "lower the derivation length (to " + std::to_string(step - 1) + " at most)"
                                          : "lower the derivation length below " + std::to_string(step);
            throw TooBig("step " + std::to_string(step) + " would make " + (exact ? "" : "at least ") + modules + " modules (" +
                         (estimated ? "about " : "") + size + " with the string before it" +
                         (estimated ? ", their Python parameters measured" : "") + "), over the " +
                                  (overModules ? "limit of " + withThousands(m_options.maxModules) + " modules; " + lower + " or raise the limit (--max-modules)"
                                               : "memory budget of " + humanBytes(m_options.maxBytes) + "; " + lower + " or raise the budget (--max-memory)"));
        }
        before = totalBytes;
        if (settled) return;
    }
}

}  // namespace sprout::lpy
