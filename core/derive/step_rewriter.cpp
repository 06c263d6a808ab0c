// One parallel rewriting step (step_rewriter.hpp says what it covers): the rule tables built
// once, then for each module the production that applies, its successor written out.
//
// Index of this file:
//   [SECTION] The rule tables and the size bound
//   [SECTION] Matching a predecessor and its contexts
//   [SECTION] Choosing a production: conditions, blocks, probabilities
//   [SECTION] The step: the string rewritten
//   [SECTION] Cut: the rest of a branch removed

#include "core/derive/step_rewriter.hpp"

#include "core/language/cpfg/user_files.hpp"

#include <algorithm>
#include <cstring>

namespace sprout {
namespace {
constexpr std::uint32_t kUnmatched = UINT32_MAX;
}

// [SECTION] The rule tables and the size bound

StepRewriter::StepRewriter(const Grammar& g, const RuleSet& rules) : m_g(g), m_rules(rules) {
    const size_t A = g.alphabet.size();
    m_arity.resize(A);
    m_hasRules.resize(A);
    m_maxLen.assign(A, 1);
    m_maxParams.resize(A);
    size_t slots = 0;
    for (size_t s = 0; s < A; ++s) {
        m_arity[s] = g.alphabet[SymbolId(s)].arity;
        m_maxParams[s] = m_arity[s];
        m_hasRules[s] = s < rules.bySymbol.size() && !rules.bySymbol[s].empty();
        if (m_arity[s]) m_parametric = true;
        for (auto idx : m_hasRules[s] ? rules.bySymbol[s] : std::vector<std::uint32_t>{}) {
            const Production& p = rules.productions[idx];
            m_maxLen[s] = std::max<std::uint32_t>(m_maxLen[s], std::uint32_t(p.successor.symbols.size()));
            m_maxParams[s] = std::max<std::uint32_t>(m_maxParams[s], std::uint32_t(p.successor.paramCount()));
            slots = std::max(slots, size_t(p.slotCount));
            if (p.hasContext()) m_needBrackets = true;
            for (SymbolId t : p.successor.symbols) m_cut |= t == Alphabet::kCut;
        }
        m_maxLenAll = std::max(m_maxLenAll, m_maxLen[s]);
        m_maxParamsAll = std::max(m_maxParamsAll, m_maxParams[s]);
    }
    if (!g.globals.empty()) slots = kGlobalSlot + g.globals.size();  // cpfg's global variables after the locals
    m_slots.assign(std::max<size_t>(slots, 1), 0.0);
    m_cpfgDraw = &rules == &g.rules && g.cpfgRandom && g.settings.seedGiven;
    if (g.cpfgRandom)
        if (auto eq = g.alphabet.find("=", 0)) m_skipToBranchEnd = *eq;
    for (size_t i = 0; i < g.globals.size() && i < g.globalInit.size(); ++i) m_slots[kGlobalSlot + i] = g.globalInit[i];
    if (&rules != &g.rules && !g.startBlock.empty()) {
        // The homomorphism reads the globals as the Start: block sets them (the derivation's
        // own rewriter keeps them from step to step; the decomposition copies them).
        Rng rng = g.cpfgRandom ? Rng::cpfg(0) : Rng(0);
        runStatements(g.startBlock, m_slots.data(), rng);
    }
    m_persistLocals = g.cpfgRandom;
    m_ignoreProbabilities = g.cpfgRandom && !g.settings.seedGiven;
    m_keepState = m_persistLocals || std::any_of(rules.productions.begin(), rules.productions.end(),
                                                 [](const Production& p) { return p.stochastic(); });
    if (m_keepState) {
        m_state.resize(rules.productions.size());
        for (size_t k = 0; k < rules.productions.size(); ++k) m_state[k].assign(size_t(rules.productions[k].slotCount), 0.0);
    }
    if (&rules == &g.rules) m_cut |= g.usesCut();  // a '%' in the axiom is cut at the first step
    if (g.cutInNextStep) m_cut = false;  // cpfg: the derivation cuts the input instead
    for (const Production& p : rules.productions) {
        int keep = -1;
        for (size_t j = 0; j < p.successor.symbols.size() && keep < 0; ++j)
            if (p.successor.symbols[j] == p.pred.symbol) keep = int(j);
        m_inherit.push_back(keep);
    }
    m_always.assign(A, nullptr);
    if (&rules == &g.rules && !g.subLsystems.empty()) {
        m_subMark.assign(A, 0);
        for (size_t s = 0; s < A; ++s) {
            const std::string& name = g.alphabet[SymbolId(s)].name;
            // cpfg calls a sub-L-system with ?(k, scale) (generate.c: a '?' with parameters)
            // and L-system Explorer with $(k); both return with $.
            const bool call = (name == "$" || (name == "?" && g.cpfgRandom)) && m_arity[s] > 0;
            if (!call && name != "$") continue;
            m_subMark[s] = call ? 1 : 2;
            m_hasRules[s] = 1;  // the copy of runs without rules stops there
        }
    }
    for (size_t s = 0; s < A && m_subMark.empty(); ++s) {
        if (!m_hasRules[s]) continue;
        const Production& first = rules.productions[rules.bySymbol[s].front()];
        if (!first.hasContext() && !first.condition && !first.stochastic() && !first.hasBlocks()) m_always[s] = &first;
    }
}

void StepRewriter::bound(const ModuleString& in, std::uint64_t& modules, std::uint64_t& params,
                         bool tight) const {
    if (!tight) {
        modules = std::uint64_t(in.size()) * m_maxLenAll;
        params = std::uint64_t(in.size()) * m_maxParamsAll;
        return;
    }
    modules = 0;
    params = 0;
    for (SymbolId s : in.symbols) {
        modules += m_maxLen[s];
        params += m_maxParams[s];
    }
}

void StepRewriter::prepare(const ModuleString& in) {
    m_in = &in;
    if (!m_needBrackets) return;
    const size_t N = in.size();
    const SymbolId* sym = in.symbols.data();
    m_match.assign(N, kUnmatched);
    std::vector<std::uint32_t> open;
    for (size_t i = 0; i < N; ++i) {
        if (sym[i] == Alphabet::kPush) {
            open.push_back(std::uint32_t(i));
        } else if (sym[i] == Alphabet::kPop && !open.empty()) {
            m_match[i] = open.back();
            m_match[open.back()] = std::uint32_t(i);
            open.pop_back();
        }
    }
    if (m_parametric) {
        m_offset.resize(N);
        std::uint64_t off = 0;
        for (size_t i = 0; i < N; ++i) {
            m_offset[i] = off;
            off += m_arity[sym[i]];
        }
    }
}

// [SECTION] Matching a predecessor and its contexts

bool StepRewriter::matches(const PatternModule& pm, SymbolId s) const {
    if (pm.wildcard) return true;
    if (pm.arity < 0) return m_g.alphabet[s].nameId == pm.name;
    return s == pm.symbol;
}

void StepRewriter::bind(const PatternModule& pm, size_t j) {
    if (m_bound) m_bound->push_back(j);
    if (pm.arity > 0)
        std::memcpy(&m_slots[pm.firstSlot], m_in->params.data() + m_offset[j], size_t(pm.arity) * sizeof(double));
}

// ABOP 1.8 / cpfg: the left context is found walking back towards the root, skipping
// completed side branches `[...]` and stepping out of the current branch at its `[`.
bool StepRewriter::contextOf(const ModuleString& in, size_t i, const Production& p, std::vector<std::size_t>& left,
                             std::vector<std::size_t>& right) {
    left.clear();
    right.clear();
    if (i >= in.size()) return false;
    prepare(in);
    if (!m_needBrackets || m_offset.size() != in.size()) {
        // Parameter offsets for bind(): computed here when the step did not need them.
        m_offset.resize(in.size());
        std::uint64_t o = 0;
        for (size_t k = 0; k < in.size(); ++k) m_offset[k] = o, o += m_arity[in.symbols.data()[k]];
    }
    if (m_match.size() != in.size()) m_match.assign(in.size(), kUnmatched);
    m_slots.resize(std::max<size_t>(m_slots.size(), size_t(p.slotCount) + 1));  // never shrinks: globals stay
    m_bound = &left;
    bool ok = matchLeft(p, i);
    std::reverse(left.begin(), left.end());
    m_bound = &right;
    ok = ok && matchRight(p, i);
    m_bound = nullptr;
    return ok;
}

bool StepRewriter::matchLeft(const Production& p, size_t i) {
    const SymbolId* sym = m_in->symbols.data();
    std::ptrdiff_t j = std::ptrdiff_t(i) - 1;
    bool wrapped = false;
    for (std::ptrdiff_t k = std::ptrdiff_t(p.left.size()) - 1; k >= 0; --k) {
        for (;;) {
            if (j < 0 && m_g.ring && !wrapped && m_in->size() > 1) {  // cpfg's ring: on from the last module
                wrapped = true;
                j = std::ptrdiff_t(m_in->size()) - 1;
            }
            if (j < 0) return false;
            SymbolId s = sym[j];
            if (s == Alphabet::kPop) {
                j = m_match[j] == kUnmatched ? -1 : std::ptrdiff_t(m_match[j]) - 1;
            } else if (s == Alphabet::kPush || m_g.ignored[m_g.alphabet[s].nameId]) {
                --j;
            } else {
                break;
            }
        }
        const PatternModule& pm = p.left[size_t(k)];
        if (!matches(pm, sym[j])) return false;
        bind(pm, size_t(j));
        --j;
    }
    return true;
}

// The right context skips side branches and fails at the `]` that ends the current
// branch; `[` and `]` written in the context match a branch start and a branch end. In cpfg
// (generate.c, RconDiff) a bracket `ignore:` or `consider:` leaves out is passed like any
// module left out, into a branch or out of it, and a `]` in the context matches the next
// module only.
bool StepRewriter::matchRight(const Production& p, size_t i) {
    const SymbolId* sym = m_in->symbols.data();
    const size_t N = m_in->size();
    size_t j = i + 1 + p.predRest.size();  // after the whole strict predecessor
    bool wrapped = false;
    const bool cpfg = m_g.cpfgRandom;
    auto left = [&](SymbolId s) {  // a module the context passes over
        return m_g.ignored[m_g.alphabet[s].nameId] && (cpfg || (s != Alphabet::kPush && s != Alphabet::kPop));
    };
    auto skipIgnored = [&] {
        while (j < N && left(sym[j])) ++j;
    };
    for (const PatternModule& pm : p.right) {
        if (!pm.wildcard && pm.symbol == m_skipToBranchEnd) {  // cpfg's `=`: on to this branch's end
            while (j < N && sym[j] != Alphabet::kPop)
                j = sym[j] == Alphabet::kPush && m_match[j] != kUnmatched ? m_match[j] + 1 : j + 1;
            continue;
        }
        if (!pm.wildcard && pm.symbol == Alphabet::kPush) {
            skipIgnored();
            if (j >= N || sym[j] != Alphabet::kPush) return false;
            ++j;
            continue;
        }
        if (!pm.wildcard && pm.symbol == Alphabet::kPop && !cpfg) {
            while (j < N && sym[j] != Alphabet::kPop)
                j = sym[j] == Alphabet::kPush && m_match[j] != kUnmatched ? m_match[j] + 1 : j + 1;
            if (j >= N) return false;
            ++j;
            continue;
        }
        for (;;) {
            if (j >= N && m_g.ring && !wrapped && N > 1) {  // cpfg's ring: on from the first module
                wrapped = true;
                j = 0;
            }
            if (j >= N) return false;
            SymbolId s = sym[j];
            if (left(s)) {
                ++j;
            } else if (s == Alphabet::kPush) {
                if (m_match[j] == kUnmatched) return false;
                j = m_match[j] + 1;
            } else if (s == Alphabet::kPop && !(cpfg && pm.symbol == Alphabet::kPop && !pm.wildcard)) {
                return false;
            } else {
                break;
            }
        }
        if (!matches(pm, sym[j])) return false;
        bind(pm, j);
        ++j;
    }
    return true;
}

// [SECTION] Choosing a production: conditions, blocks, probabilities

bool StepRewriter::applicable(const Production& p, size_t i, Rng& rng) {
    if (p.pred.arity > 0)
        std::memcpy(&m_slots[p.pred.firstSlot], m_in->params.data() + m_paramPos,
                    size_t(p.pred.arity) * sizeof(double));
    for (size_t k = 0; k < p.predRest.size(); ++k) {  // cpfg: `AB --> C` rewrites A and the B after it
        const size_t j = i + 1 + k;
        if (j >= m_in->size() || !matches(p.predRest[k], m_in->symbols.data()[j])) return false;
        bind(p.predRest[k], j);
    }
    if (!p.left.empty() && !matchLeft(p, i)) return false;
    if (!p.right.empty() && !matchRight(p, i)) return false;
    // Blocks: the pre-condition block runs before the condition (finish() runs the other).
    // Locals start at 0 each time; in cpfg they keep the values the production last left.
    const double* kept = m_persistLocals ? m_state[size_t(&p - m_rules.productions.data())].data() : nullptr;
    for (int k = p.firstLocal; k < p.slotCount; ++k) m_slots[size_t(k)] = kept ? kept[k] : 0;
    if (!p.pre.empty()) runStatements(p.pre, m_slots.data(), rng);
    const bool holds = !p.condition || p.condition->eval(m_slots.data(), rng) != 0;
    m_lastEvaluated = &p;
    if (m_keepState) saveState(p);
    return holds;
}

void StepRewriter::saveState(const Production& p) {
    std::copy_n(m_slots.begin(), p.slotCount, m_state[size_t(&p - m_rules.productions.data())].begin());
}

void StepRewriter::restoreState(const Production& p) {
    const auto& kept = m_state[size_t(&p - m_rules.productions.data())];
    std::copy(kept.begin(), kept.end(), m_slots.begin());
}

void StepRewriter::finish(const Production& p, Rng& rng) {
    if (m_lastEvaluated != &p && m_keepState) restoreState(p);
    m_lastEvaluated = &p;
    if (p.post.empty()) return;
    runStatements(p.post, m_slots.data(), rng);
    if (m_keepState) saveState(p);
}

void runStatements(const std::vector<Statement>& block, double* slots, Rng& rng) {
    for (const Statement& s : block) {
        switch (s.kind) {
            case Statement::Kind::Assign:
                if (s.size) slots[s.slot + arrayOffset(s.index.eval(slots, rng), s.size)] = s.expr.eval(slots, rng);
                else slots[s.slot] = s.expr.eval(slots, rng);
                break;
            case Statement::Kind::Eval: s.expr.eval(slots, rng); break;
            case Statement::Kind::Open: runOpen(s, slots); break;
            case Statement::Kind::Scan: runScan(s, slots, rng); break;
            case Statement::Kind::If:
                if (s.expr.eval(slots, rng) != 0) runStatements(s.then, slots, rng);
                else runStatements(s.otherwise, slots, rng);
                break;
            case Statement::Kind::While:
                for (int n = 0; n < Statement::kMaxLoop && s.expr.eval(slots, rng) != 0; ++n) runStatements(s.then, slots, rng);
                break;
            case Statement::Kind::Do:
                for (int n = 0; n < Statement::kMaxLoop; ++n) {
                    runStatements(s.then, slots, rng);
                    if (s.expr.eval(slots, rng) == 0) break;
                }
                break;
        }
    }
}

// cpfg's SelectProc (generate.c): the applicable productions (each of probability 1 unless
// given), then one drand48 draw scaled by their total, in single precision as cpfg computes it.
const Production* StepRewriter::selectCpfg(size_t i, Rng& rng) {
    m_candidates.clear();
    m_weights.clear();
    float total = 0;
    const std::uint8_t in = m_subStack.empty() ? 0 : m_subStack.back();
    if (m_hasRules[m_in->symbols[i]]) {
        for (std::uint32_t k : m_rules.bySymbol[m_in->symbols[i]]) {
            const Production& p = m_rules.productions[k];
            if (p.lsystem != in || !applicable(p, i, rng)) continue;
            // Its probability (cpfg keeps it as a float), evaluated as it applies.
            const float w = float(p.probabilityExpr ? p.probabilityExpr->eval(m_slots.data(), rng)
                                                    : p.stochastic() ? p.probability : 1.0);
            m_candidates.push_back(k);
            m_weights.push_back(w);
            total += w;
        }
    }
    float scaled = float(double(total) * rng.uniform());
    for (size_t c = 0; c < m_candidates.size(); ++c)
        if ((scaled -= m_weights[c]) <= 0) return &m_rules.productions[m_candidates[c]];
    return nullptr;
}

const Production* StepRewriter::select(size_t i, Rng& rng) {
    if (m_cpfgDraw) return selectCpfg(i, rng);
    const auto& list = m_rules.bySymbol[m_in->symbols[i]];
    const auto& prods = m_rules.productions;
    const std::uint8_t in = m_subStack.empty() ? 0 : m_subStack.back();
    for (size_t k = 0; k < list.size(); ++k) {
        const Production& p = prods[list[k]];
        if (p.lsystem != in || !applicable(p, i, rng)) continue;
        if (!p.stochastic() || m_ignoreProbabilities) return &p;
        // Stochastic: choose among the applicable stochastic rules for this module by their
        // probabilities. If they add up to less than 1, the module stays unchanged for the
        // rest; more than 1, they are weights.
        m_candidates.assign(1, list[k]);
        double total = p.probability;
        for (size_t k2 = k + 1; k2 < list.size(); ++k2) {
            const Production& q = prods[list[k2]];
            if (!q.stochastic() || q.lsystem != in) continue;
            if (applicable(q, i, rng)) {
                m_candidates.push_back(list[k2]);
                total += q.probability;
            }
        }
        double r = rng.uniform() * std::max(total, 1.0);
        for (auto c : m_candidates) {
            if (r < prods[c].probability) return &prods[c];
            r -= prods[c].probability;
        }
        return nullptr;
    }
    return nullptr;
}

// [SECTION] The step: the string rewritten

bool StepRewriter::rewrite(const ModuleString& in, ModuleString& out, Rng& rng,
                           const std::atomic<bool>* cancel, const std::function<void(double)>& progress,
                           const Ages* ages) {
    prepare(in);
    const size_t N = in.size();
    std::uint64_t maxModules, maxParams;
    bound(in, maxModules, maxParams, false);
    if (maxModules > (64u << 20) || maxParams > (16u << 20)) bound(in, maxModules, maxParams, true);  // reserve less when big
    out.symbols.resizeUninitialized(maxModules);
    out.params.resizeUninitialized(maxParams);
    std::uint16_t* da = nullptr;
    std::uint32_t* dParent = nullptr;
    std::int32_t* dRule = nullptr;
    if (ages && ages->out) {
        ages->out->resizeUninitialized(maxModules);
        da = ages->out->data();
    }
    if (ages && ages->parent) {
        ages->parent->resizeUninitialized(maxModules);
        ages->rule->resizeUninitialized(maxModules);
        dParent = ages->parent->data();
        dRule = ages->rule->data();
    }
    SymbolId* ds = out.symbols.data();
    double* dp = out.params.data();
    const SymbolId* sym = in.symbols.data();
    const double* par = in.params.data();
    const std::uint8_t* hasRules = m_hasRules.data();
    const std::uint8_t* arity = m_arity.data();
    size_t pp = 0;
    size_t nextCheck = 1u << 18;
    m_subStack.clear();
    for (size_t i = 0; i < N;) {
        if (i >= nextCheck) {
            nextCheck = i + (1u << 18);
            if (cancel && cancel->load(std::memory_order_relaxed)) return false;
            if (progress) progress(double(i) / double(N));
        }
        if (!hasRules[sym[i]] && !m_cpfgDraw) {  // a run of modules no rule rewrites: copy it whole
            size_t j = i, pc = 0;
            if (m_parametric) {
                while (j < N && !hasRules[sym[j]]) pc += arity[sym[j++]];
            } else {
                while (j < N && !hasRules[sym[j]]) ++j;
            }
            std::memcpy(ds, sym + i, (j - i) * sizeof(SymbolId));
            ds += j - i;
            if (da) {
                std::memcpy(da, ages->in + i, (j - i) * sizeof(std::uint16_t));
                da += j - i;
            }
            if (dParent)
                for (size_t k = i; k < j; ++k) *dParent++ = std::uint32_t(k), *dRule++ = -1;
            if (pc) std::memcpy(dp, par + pp, pc * sizeof(double));
            dp += pc;
            pp += pc;
            i = j;
            continue;
        }
        m_paramPos = pp;
        const unsigned a = arity[sym[i]];
        const Production* p = m_cpfgDraw ? nullptr : m_always[sym[i]];
        if (p) {
            for (unsigned k = 0; k < a; ++k) m_slots[k] = par[pp + k];
        } else {
            p = select(i, rng);
        }
        if (p && p != m_always[sym[i]]) finish(*p, rng);
        if (p) {
            const auto& succ = p->successor;
            const size_t n = succ.symbols.size();
            if (n) std::memcpy(ds, succ.symbols.data(), n * sizeof(SymbolId));
            ds += n;
            if (da) {
                const int keep = m_inherit[size_t(p - m_rules.productions.data())];
                for (size_t j = 0; j < n; ++j) da[j] = int(j) == keep ? ages->in[i] : ages->step;
                da += n;
            }
            if (dParent)
                for (size_t j = 0; j < n; ++j)
                    *dParent++ = std::uint32_t(i), *dRule++ = std::int32_t(p - m_rules.productions.data());
            if (m_g.cpfgRandom) {  // cpfg keeps a module's parameters as floats in its string
                for (const Expr& e : succ.args) *dp++ = double(float(e.eval(m_slots.data(), rng)));
            } else {
                for (const Expr& e : succ.args) *dp++ = e.eval(m_slots.data(), rng);
            }
        } else {
            *ds++ = sym[i];
            for (unsigned k = 0; k < a; ++k) *dp++ = par[pp + k];
            if (da) *da++ = ages->in[i];
            if (dParent) *dParent++ = std::uint32_t(i), *dRule++ = -1;
        }
        if (!m_subMark.empty() && m_subMark[sym[i]]) {  // after its own rewriting, as L-system Explorer does
            if (m_subMark[sym[i]] == 2) {
                if (!m_subStack.empty()) m_subStack.pop_back();
            } else {
                const auto& labels = m_g.subLsystems;
                const auto at = std::find(labels.begin(), labels.end(), par[pp]);
                // An unknown label rewrites with the L-system it is in.
                m_subStack.push_back(at == labels.end() ? (m_subStack.empty() ? 0 : m_subStack.back())
                                                        : std::uint8_t(at - labels.begin() + 1));
            }
        }
        pp += a;
        ++i;
        if (p && !p->predRest.empty()) {  // the strict predecessor's other modules are rewritten with it
            for (size_t k = 0; k < p->predRest.size() && i < N; ++k) pp += arity[sym[i++]];
        }
    }
    out.symbols.resizeUninitialized(size_t(ds - out.symbols.data()));
    out.params.resizeUninitialized(size_t(dp - out.params.data()));
    if (da) ages->out->resizeUninitialized(size_t(da - ages->out->data()));
    if (dParent) {
        ages->parent->resizeUninitialized(size_t(dParent - ages->parent->data()));
        ages->rule->resizeUninitialized(size_t(dRule - ages->rule->data()));
    }
    if (m_cut) applyCut(out, m_g.alphabet, da ? ages->out : nullptr, dParent ? ages->parent : nullptr, dParent ? ages->rule : nullptr);
    if (out.symbols.capacity() > out.symbols.size() + out.symbols.size() / 4 + 1024) out.symbols.shrinkToFit();
    if (out.params.capacity() > out.params.size() + out.params.size() / 4 + 1024) out.params.shrinkToFit();
    return true;
}

// [SECTION] Cut: the rest of a branch removed

void applyCut(ModuleString& s, const Alphabet& alphabet, PodBuffer<std::uint16_t>* ages, PodBuffer<std::uint32_t>* parent,
              PodBuffer<std::int32_t>* rule) {
    SymbolId* sym = s.symbols.data();
    double* par = s.params.data();
    std::uint16_t* age = ages ? ages->data() : nullptr;
    std::uint32_t* from = parent ? parent->data() : nullptr;
    std::int32_t* by = rule ? rule->data() : nullptr;
    const size_t N = s.size();
    size_t w = 0, pr = 0, pw = 0;
    for (size_t i = 0; i < N;) {
        SymbolId id = sym[i];
        if (id == Alphabet::kCut) {
            int depth = 0;
            for (; i < N; ++i) {  // skip to the ']' closing this branch (kept) or the end
                SymbolId t = sym[i];
                if (t == Alphabet::kPush) ++depth;
                else if (t == Alphabet::kPop && depth-- == 0) break;
                pr += alphabet[t].arity;
            }
            continue;
        }
        unsigned a = alphabet[id].arity;
        if (age) age[w] = age[i];
        if (from) from[w] = from[i];
        if (by) by[w] = by[i];
        sym[w++] = id;
        for (unsigned k = 0; k < a; ++k) par[pw++] = par[pr++];
        ++i;
    }
    s.symbols.resizeUninitialized(w);
    s.params.resizeUninitialized(pw);
    if (ages) ages->resizeUninitialized(w);
    if (parent) parent->resizeUninitialized(w);
    if (rule) rule->resizeUninitialized(w);
}

}  // namespace sprout
