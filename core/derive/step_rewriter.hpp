#pragma once
// One parallel rewriting step for any grammar: stochastic, context-sensitive (ABOP bracket
// semantics), parametric with conditions, cut. Used for derivation steps and, with the
// interpretation rules, for the cpfg homomorphism.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/language/grammar.hpp"

namespace sprout {

class StepRewriter {
public:
    StepRewriter(const Grammar& g, const RuleSet& rules);

    // An upper bound on the size of the rewritten string, computed without rewriting:
    // `tight` counts per symbol (one pass over the string), otherwise the longest
    // successor times the length (no pass).
    void bound(const ModuleString& in, std::uint64_t& modules, std::uint64_t& params, bool tight) const;
    // Rewrites `in` into `out` (sized by bound()). Returns false when cancelled.
    // With `ages`, also writes the step that created each output module: a module no rule
    // rewrote keeps its age, and so does the first module of a successor that repeats the
    // predecessor (F -> FF: the old F stays, the new one grows); all others are `step`.
    struct Ages {
        const std::uint16_t* in;  // with `out`: ages (either may be null when only origins are asked)
        PodBuffer<std::uint16_t>* out;
        std::uint16_t step;
        // Provenance, when set: for each output module, the index of the input module it came
        // from, and the production that made it (its index in the rule set; -1: copied as it was).
        PodBuffer<std::uint32_t>* parent = nullptr;
        PodBuffer<std::int32_t>* rule = nullptr;
    };
    bool rewrite(const ModuleString& in, ModuleString& out, Rng& rng, const std::atomic<bool>* cancel,
                 const std::function<void(double)>& progress, const Ages* ages = nullptr);

    // The modules of `in` that the context of production `p` matches around module i (the
    // derivation inspector: which context matched): left ones and right ones, each in text
    // order. False when the context does not match there.
    bool contextOf(const ModuleString& in, size_t i, const Production& p, std::vector<std::size_t>& left,
                   std::vector<std::size_t>& right);

    // The slots the rules' expressions read; cpfg's global variables are slots kGlobalSlot + i
    // (expr.hpp), kept here from step to step.
    double* slots() { return m_slots.data(); }
    void copyGlobals(const StepRewriter& from) {
        std::copy(from.m_slots.begin() + kGlobalSlot, from.m_slots.begin() + kGlobalSlot + std::ptrdiff_t(m_g.globals.size()),
                  m_slots.begin() + kGlobalSlot);
    }

private:
    const Production* select(size_t i, Rng& rng);
    const Production* selectCpfg(size_t i, Rng& rng);
    bool matches(const PatternModule& pm, SymbolId s) const;
    bool matchLeft(const Production& p, size_t i);
    bool matchRight(const Production& p, size_t i);
    void bind(const PatternModule& pm, size_t j);
    // Whether `p` applies at module i: its modules and contexts matched and bound, its
    // pre-condition block run, its condition true. Its post-condition block is finish()'s.
    bool applicable(const Production& p, size_t i, Rng& rng);
    void finish(const Production& p, Rng& rng);  // `p` chosen: its slots back, its post block run
    void saveState(const Production& p);
    void restoreState(const Production& p);
    void prepare(const ModuleString& in);

    const Grammar& m_g;
    const RuleSet& m_rules;
    std::vector<std::uint8_t> m_arity;
    std::vector<std::uint8_t> m_hasRules;
    // The rule that always applies to a symbol (first in file order, without context,
    // condition or probability), so the common case skips matching altogether.
    std::vector<const Production*> m_always;
    // Sub-L-systems: by symbol, 1 for `$(k)` (enter k), 2 for `$` (leave); the stack of those
    // entered while a step goes left to right.
    std::vector<std::uint8_t> m_subMark;
    std::vector<std::uint8_t> m_subStack;
    std::vector<int> m_inherit;  // per production: the successor index that keeps the age, or -1
    std::vector<std::uint32_t> m_maxLen;     // per symbol: most modules one rewrite can emit
    std::vector<std::uint32_t> m_maxParams;
    std::uint32_t m_maxLenAll = 1, m_maxParamsAll = 0;
    bool m_needBrackets = false;  // contexts: bracket matching and parameter offsets
    bool m_parametric = false;
    bool m_cut = false;
    // cpfg's stochastic L-system (a `seed:`): one draw for every module, the production chosen
    // among all those that apply (selectCpfg).
    bool m_cpfgDraw = false;
    // cpfg's `=` in a right context (generate.c, RconDiff): skip to the end of the branch.
    SymbolId m_skipToBranchEnd = SymbolId(-1);

    // Scratch for the current step.
    const ModuleString* m_in = nullptr;
    std::vector<std::uint32_t> m_match;    // index of the matching bracket
    std::vector<std::uint64_t> m_offset;   // parameter offset of each module (contexts only)
    size_t m_paramPos = 0;                 // parameter offset of the module being rewritten
    std::vector<double> m_slots;
    std::vector<std::uint32_t> m_candidates;
    std::vector<float> m_weights;  // selectCpfg: each candidate's probability
    // Per production, its slots (parameters and locals) as its last evaluation left them, when
    // m_keepState: the production chosen among several gets its own back, and in cpfg
    // (m_persistLocals) its locals keep their values from one application to the next, as
    // each production's symbol table keeps them (generate.c).
    std::vector<std::vector<double>> m_state;
    bool m_keepState = false;
    bool m_persistLocals = false;
    bool m_ignoreProbabilities = false;  // cpfg without `seed:`: the first production that applies
    const Production* m_lastEvaluated = nullptr;  // whose values m_slots holds
    std::vector<std::size_t>* m_bound = nullptr;  // contextOf: where matched modules are
};

// Runs a cpfg statement block over a production's slots (parameters and locals).
void runStatements(const std::vector<Statement>& block, double* slots, Rng& rng);

// Removes each cut symbol '%' together with the rest of its branch (ABOP section 1.10.3,
// used for shedding): everything up to, not including, the ']' that closes the branch.
// Per-module arrays (ages, provenance) are compacted along with the string.
void applyCut(ModuleString& s, const Alphabet& alphabet, PodBuffer<std::uint16_t>* ages = nullptr,
              PodBuffer<std::uint32_t>* parent = nullptr, PodBuffer<std::int32_t>* rule = nullptr);

}  // namespace sprout
