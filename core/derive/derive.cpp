// Derivation (derive.hpp says what it promises): the axiom made step 0, each step's size
// checked before it is made, the D0L fast path or the general rewriter, decomposition and
// queries after each step.
//
// Index of this file:
//   [SECTION] Sizes in words and the memory budget
//   [SECTION] A derivation set up: the axiom as step 0
//   [SECTION] After each step: decomposition and queries
//   [SECTION] Size limits, checked before a step is made; the figures of each step
//   [SECTION] Deriving to step n: D0L counts, predicted growth, general steps
//   [SECTION] The steps kept, and derive()

#include "core/derive/derive.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/derive/d0l.hpp"
#include "core/derive/step_rewriter.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {
namespace {

// [SECTION] Sizes in words and the memory budget

double millisSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string humanBytes(std::uint64_t b) {
    char buf[32];
    if (b >= (1ull << 30)) std::snprintf(buf, sizeof buf, "%.1f GB", double(b) / double(1ull << 30));
    else std::snprintf(buf, sizeof buf, "%.1f MB", double(b) / double(1ull << 20));
    return buf;
}

std::uint64_t defaultMemoryBudget() {
    static const std::uint64_t budget = [] {
        std::ifstream in("/proc/meminfo");
        std::string line;
        while (std::getline(in, line)) {
            std::istringstream words(line);
            std::string key;
            std::uint64_t kb = 0;
            if (words >> key >> kb && key == "MemAvailable:" && kb > 0) return std::max<std::uint64_t>(kb * 1024 / 2, 64ull << 20);
        }
        return std::uint64_t(8ull << 30);
    }();
    return budget;
}

std::string withThousands(std::uint64_t v) {
    std::string digits = std::to_string(v), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

// [SECTION] A derivation set up: the axiom as step 0

Derivation::Derivation(std::shared_ptr<const Grammar> grammar, DeriveOptions options)
    : m_grammar(std::move(grammar)),
      m_options(std::move(options)),
      m_seed(m_options.seed.value_or(m_grammar->settings.seed)) {
    std::shared_ptr<PodBuffer<std::uint16_t>> axiomAges;
    if (m_options.trackAges) {
        axiomAges = std::make_shared<PodBuffer<std::uint16_t>>();
        axiomAges->resizeUninitialized(m_grammar->axiom.size());
        std::fill(axiomAges->data(), axiomAges->data() + axiomAges->size(), std::uint16_t(0));
    }
    if (D0LExpander::applicable(*m_grammar) && !m_options.trackAges && !m_options.holdQueries &&
        !m_options.trackOrigins && !m_grammar->hasGlobals())
        m_d0l = std::make_unique<D0LExpander>(*m_grammar);
    else m_rewriter = std::make_unique<StepRewriter>(*m_grammar, m_grammar->rules);
    if (!m_grammar->decomposition.productions.empty())
        m_decomposer = std::make_unique<StepRewriter>(*m_grammar, m_grammar->decomposition);
    if (m_grammar->cpfgRandom) {
        // cpfg's derivation as `cpfg -g` writes it leaves drand48 unseeded whatever the
        // `seed:` (only its window's first run calls seed48): a seed other than the grammar's
        // own (--seed, the viewer's reseed) gives other plants; the grammar's own gives cpfg's.
        const bool other = m_options.seed && *m_options.seed != m_grammar->settings.seed;
        m_cpfgRng = Rng::cpfg(other ? std::int64_t(*m_options.seed) : 0);
    }
    if (m_rewriter && !m_grammar->startBlock.empty()) {  // cpfg's Start: block, before the axiom is decomposed
        Rng rng = Rng::forStream(m_seed, 0);
        runStatements(m_grammar->startBlock, m_rewriter->slots(), m_cpfgRng ? *m_cpfgRng : rng);
    }
    if (m_grammar->environment.program) {
        m_environmentRun = m_grammar->environment.program->start();
        m_programBefore = !m_grammar->environment.program->afterStep;
    }
    auto axiom = std::make_shared<ModuleString>(m_grammar->axiom);
    if (m_grammar->cpfgRandom)  // cpfg's string keeps parameters as floats
        for (size_t k = 0; k < axiom->params.size(); ++k) axiom->params.data()[k] = double(float(axiom->params.data()[k]));
    std::shared_ptr<Origins> axiomOrigins;
    if (m_options.trackOrigins) {
        axiomOrigins = std::make_shared<Origins>();
        axiomOrigins->parent.resizeUninitialized(axiom->size());
        axiomOrigins->rule.resizeUninitialized(axiom->size());
        for (size_t i = 0; i < axiom->size(); ++i) axiomOrigins->parent.data()[i] = std::uint32_t(i), axiomOrigins->rule.data()[i] = -1;
    }
    if (m_decomposer || m_grammar->hasQueries())  // the axiom is decomposed and queried too
        m_axiomOutcome = finishStep(0, *axiom, axiomAges.get(), axiomOrigins.get());
    if (axiomOrigins) m_origins.push_back(std::move(axiomOrigins));
    m_stats.push_back({0, axiom->size(), axiom->params.size(), 0.0});
    if (m_options.holdQueries) m_last = axiom;
    m_steps.push_back(std::move(axiom));
    if (axiomAges) m_ages.push_back(std::move(axiomAges));
}

Derivation::~Derivation() = default;

// [SECTION] After each step: decomposition and queries

DeriveOutcome Derivation::predictDecomposition(int step, const ModuleString& s) const {
    const Grammar& g = *m_grammar;
    const RuleSet& rules = g.decomposition;
    const size_t A = g.alphabet.size();
    std::vector<const Production*> always(A, nullptr);
    for (size_t k = 0; k < A && k < rules.bySymbol.size(); ++k) {
        if (rules.bySymbol[k].empty()) continue;
        const Production& first = rules.productions[rules.bySymbol[k].front()];
        if (first.hasContext() || first.condition || first.stochastic() || first.hasBlocks()) return {};  // not followed
        always[k] = &first;
    }
    if (g.usesCut()) return {};
    for (const Production& p : rules.productions)
        for (SymbolId t : p.successor.symbols)
            if (t == Alphabet::kCut) return {};
    std::vector<double> count(A, 0), next(A);
    for (size_t i = 0; i < s.size(); ++i) count[s.symbols.data()[i]] += 1;
    for (int pass = 0; pass < g.decompositionDepth; ++pass) {
        bool changes = false;
        std::fill(next.begin(), next.end(), 0.0);
        for (size_t k = 0; k < A; ++k) {
            if (!count[k]) continue;
            const Production* p = always[k];
            if (!p) {
                next[k] += count[k];
                continue;
            }
            const auto& succ = p->successor.symbols;
            changes |= !(succ.size() == 1 && succ[0] == SymbolId(k));
            for (SymbolId t : succ) next[t] = std::min(next[t] + count[k], 1e30);
        }
        if (!changes) return {};  // the passes end here: the string stays as it is
        double modules = 0, params = 0;
        for (size_t k = 0; k < A; ++k) modules += next[k], params += next[k] * g.alphabet[SymbolId(k)].arity;
        auto clamp = [](double v) { return v >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max() : std::uint64_t(v); };
        DeriveOutcome o = checkSize(step, clamp(modules), clamp(params));
        if (!o.ok()) {
            // The passes are followed exactly: "would produce N", not "up to".
            std::string rest = o.message.substr(o.message.find(' ', 5) + 1);
            if (rest.starts_with("would produce up to ")) rest = "would produce " + rest.substr(20);
            o.message = "step " + std::to_string(step) + ", decomposition pass " + std::to_string(pass + 1) + ", " + rest;
            return o;
        }
        count.swap(next);
    }
    return {};
}

DeriveOutcome Derivation::finishStep(int step, ModuleString& s, PodBuffer<std::uint16_t>* ages, Origins* origins) {
    if (m_decomposer && (step > 0 || m_grammar->decomposeAxiom)) {
        if (m_rewriter && !m_grammar->globals.empty()) m_decomposer->copyGlobals(*m_rewriter);  // cpfg's globals
        if (DeriveOutcome predicted = predictDecomposition(step, s); !predicted.ok()) return predicted;
        // Repeated passes of the (context-free) decomposition rules: pass d rewrites what
        // pass d-1 produced, which is applying them depth-first to each module (cpfg / lpfg).
        const int depth = m_grammar->decompositionDepth;
        for (int pass = 0;; ++pass) {
            std::uint64_t modules, params;
            m_decomposer->bound(s, modules, params, true);
            DeriveOutcome o = checkSize(step, modules, params);
            if (!o.ok()) return o;
            ModuleString out;
            PodBuffer<std::uint16_t> outAges;
            Origins passOrigins;
            StepRewriter::Ages ageArgs{};
            if (ages) ageArgs = {ages->data(), &outAges, std::uint16_t(std::min(step, 65535))};
            if (origins) ageArgs.parent = &passOrigins.parent, ageArgs.rule = &passOrigins.rule;
            Rng passRng = Rng::forStream(m_seed, 0xdec0000ull + std::uint64_t(step) * 1024 + std::uint64_t(pass));
            if (!m_decomposer->rewrite(s, out, m_cpfgRng ? *m_cpfgRng : passRng, m_options.cancel, {}, ages || origins ? &ageArgs : nullptr))
                return {DeriveStatus::Cancelled, step, 0, 0, "cancelled"};
            if (sameString(out, s)) break;
            if (pass == depth) {
                DeriveOutcome o;
                o.status = DeriveStatus::Failed;
                o.step = step;
                o.message = "step " + std::to_string(step) + ": the decomposition rules still apply after " +
                            std::to_string(depth) + " levels (maximum depth): they never end. A decomposition must end "
                            "in modules no decomposition rule rewrites; raise 'maximum depth:' if it is this deep on purpose";
                return o;
            }
            s = std::move(out);
            if (ages) *ages = std::move(outAges);
            if (origins) {
                // A module the decomposition made comes from the module of the step before that
                // its source came from; the decomposition rule is what made it.
                const std::uint32_t* before = origins->parent.data();
                const std::int32_t* beforeRule = origins->rule.data();
                std::uint32_t* parent = passOrigins.parent.data();
                std::int32_t* rule = passOrigins.rule.data();
                for (size_t j = 0; j < passOrigins.parent.size(); ++j) {
                    const std::uint32_t src = parent[j];
                    rule[j] = rule[j] >= 0 ? -(rule[j] + 2) : beforeRule[src];
                    parent[j] = before[src];
                }
                *origins = std::move(passOrigins);
            }
        }
    }
    if (m_grammar->hasQueries() && !m_options.holdQueries) {
        std::string error;
        if (!answerQueries(*m_grammar, s, step, m_seed, &error, m_environmentRun.get(), !m_programBefore)) {
            DeriveOutcome o;
            o.status = DeriveStatus::Failed;
            o.step = step;
            o.message = "step " + std::to_string(step) + ": " + error;
            return o;
        }
    }
    return {};
}

// [SECTION] Size limits, checked before a step is made; the figures of each step

DeriveOutcome Derivation::checkSize(int step, std::uint64_t modules, std::uint64_t params) const {
    DeriveOutcome o;
    std::uint64_t bytes = modules * sizeof(SymbolId) + params * sizeof(double);
    std::uint64_t kept = 0;
    for (const auto& s : m_steps)
        if (s) kept += s->bytes();
    for (const auto& a : m_ages)
        if (a) kept += a->size() * sizeof(std::uint16_t);
    for (const auto& o : m_origins)
        if (o) kept += o->parent.size() * (sizeof(std::uint32_t) + sizeof(std::int32_t));
    if (m_options.trackAges) bytes += modules * sizeof(std::uint16_t);
    if (m_options.trackOrigins) bytes += modules * (sizeof(std::uint32_t) + sizeof(std::int32_t));
    o.step = step;
    o.predictedModules = modules;
    o.predictedBytes = bytes;
    const auto& lim = m_options.limits;
    // A D0L count is exact, and each step is checked in turn: the step before fits.
    const std::string lower = m_d0l ? "lower n (to " + std::to_string(step - 1) + " at most)" : "lower n";
    if (modules > lim.maxModules) {
        o.status = DeriveStatus::TooBig;
        o.message = "step " + std::to_string(step) + " would produce " +
                    (m_d0l ? "" : "up to ") + withThousands(modules) + " modules (" + humanBytes(bytes) +
                    "), over the limit of " + withThousands(lim.maxModules) +
                    " modules; " + lower + " or raise the limit (--max-modules)";
    } else if (bytes + kept > lim.maxBytes) {
        o.status = DeriveStatus::TooBig;
        o.message = "step " + std::to_string(step) + " would need " + humanBytes(bytes) + " for " +
                    withThousands(modules) + " modules on top of " + humanBytes(kept) +
                    " already kept, over the memory budget of " + humanBytes(lim.maxBytes) +
                    "; " + lower + " or raise the budget (--max-memory)";
    }
    return o;
}

void Derivation::record(int step, const ModuleString& s, double millis) {
    if (int(m_stats.size()) <= step) m_stats.resize(size_t(step) + 1);
    m_stats[size_t(step)] = {step, s.size(), s.params.size(), millis};
}

// [SECTION] Deriving to step n: D0L counts, predicted growth, general steps

DeriveOutcome Derivation::deriveTo(int n) {
    if (!m_axiomOutcome.ok()) return m_axiomOutcome;
    if (n <= m_reached) return {};
    if (!m_d0l) return deriveGeneral(n);
    std::vector<std::uint64_t> counts = m_d0l->countsUpTo(m_grammar->axiom, n);
    DeriveOutcome o = checkSize(n, counts[size_t(n)], 0);
    if (!o.ok()) {
        // Name the first step over the limit, so the user knows which n still works.
        for (int k = m_reached + 1; k <= n; ++k) {
            DeriveOutcome first = checkSize(k, counts[size_t(k)], 0);
            if (!first.ok()) return first;
        }
        return o;
    }
    auto t0 = std::chrono::steady_clock::now();
    auto out = std::make_shared<ModuleString>();
    std::function<void(double)> progress;
    if (m_options.progress) progress = [&](double f) { m_options.progress(n, n, f); };
    if (!m_d0l->expand(m_grammar->axiom, n, *out, m_options.cancel, progress))
        return {DeriveStatus::Cancelled, n, 0, 0, "cancelled"};
    m_steps.resize(size_t(n) + 1);
    m_steps[size_t(n)] = std::move(out);
    record(n, *m_steps[size_t(n)], millisSince(t0));
    m_reached = n;
    return {};
}

DeriveOutcome Derivation::predictGrowth(int n) const {
    // What each symbol becomes after j steps, at least (modules, and bytes: 4 a symbol, 8 a
    // parameter): a symbol whose first rule always applies (no context, condition, block or
    // probability) becomes that rule's successor; any other may also stay as it is, or become
    // any of its rules' successors. Exact when every rule applies always. A cut ('%') or a
    // decomposition can make a string shorter: then nothing is predicted.
    const Grammar& g = *m_grammar;
    if (m_decomposer || g.usesCut() || n <= m_reached || !m_steps[size_t(m_reached)]) return {};
    const ModuleString& in = *m_steps[size_t(m_reached)];
    const size_t A = g.alphabet.size();
    const RuleSet& rules = g.rules;
    std::vector<std::uint64_t> count(A, 0);
    for (size_t i = 0; i < in.size(); ++i) ++count[in.symbols.data()[i]];
    std::vector<char> stays(A, 1);
    std::vector<std::vector<const Production*>> options(A);
    bool exact = true;
    for (size_t s = 0; s < A && s < rules.bySymbol.size(); ++s) {
        const auto& list = rules.bySymbol[s];
        if (list.empty()) continue;
        // The rules tried before the first that always applies, and that one: one of them
        // rewrites the symbol, which never stays as it is.
        for (auto idx : list) {
            const Production& p = rules.productions[idx];
            options[s].push_back(&p);
            if (!p.hasContext() && !p.condition && !p.stochastic() && !p.hasBlocks() && g.subLsystems.empty()) {
                stays[s] = 0;
                break;
            }
        }
        if (stays[s] || options[s].size() > 1) exact = false;
    }
    constexpr double kHuge = 1e30;
    std::vector<double> mods(A, 1.0), bytes(A), nextMods(A), nextBytes(A);
    for (size_t s = 0; s < A; ++s) bytes[s] = double(sizeof(SymbolId) + sizeof(double) * g.alphabet[SymbolId(s)].arity);
    std::uint64_t kept = 0;
    for (const auto& s : m_steps)
        if (s) kept += s->bytes();
    double keptAfter = double(kept);  // with the steps predicted before k
    const auto& lim = m_options.limits;
    const double perModuleExtra = (m_options.trackAges ? 2.0 : 0.0) + (m_options.trackOrigins ? 8.0 : 0.0);
    for (int k = m_reached + 1; k <= n; ++k) {
        double totalMods = 0, totalBytes = 0;
        for (size_t s = 0; s < A; ++s) {
            double m = stays[s] ? mods[s] : kHuge, b = stays[s] ? bytes[s] : kHuge;
            for (const Production* p : options[s]) {
                double pm = 0, pb = 0;
                for (SymbolId t : p->successor.symbols) pm += mods[t], pb += bytes[t];
                m = std::min(m, pm);
                b = std::min(b, pb);
            }
            nextMods[s] = std::min(m, kHuge);
            nextBytes[s] = std::min(b, kHuge);
            if (count[s]) totalMods += double(count[s]) * nextMods[s], totalBytes += double(count[s]) * nextBytes[s];
        }
        mods.swap(nextMods);
        bytes.swap(nextBytes);
        totalBytes += totalMods * perModuleExtra;
        const bool overModules = totalMods > double(lim.maxModules);
        const bool overBytes = totalBytes + keptAfter > double(lim.maxBytes);
        if (overModules || overBytes) {
            auto clamp = [](double v) { return v >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max() : std::uint64_t(v); };
            DeriveOutcome o;
            o.status = DeriveStatus::TooBig;
            o.step = k;
            o.predictedModules = clamp(totalMods);
            o.predictedBytes = clamp(totalBytes);
            const std::string atLeast = exact ? "" : "at least ";
            const std::string modules = totalMods >= 1e19 ? std::string("more than 10^19") : withThousands(o.predictedModules);
            const std::string size = totalBytes >= 1e19 ? std::string("more than 10^19 bytes") : humanBytes(o.predictedBytes);
            const std::string lower = exact ? "lower n (to " + std::to_string(k - 1) + " at most)" : "lower n below " + std::to_string(k);
            if (overModules)
                o.message = "step " + std::to_string(k) + " would produce " + atLeast + modules + " modules (" + size +
                            "), over the limit of " + withThousands(lim.maxModules) + " modules; " + lower +
                            " or raise the limit (--max-modules)";
            else
                o.message = "step " + std::to_string(k) + " would need " + atLeast + size + " for " + modules +
                            " modules on top of " + humanBytes(clamp(keptAfter)) + " already kept, over the memory budget of " +
                            humanBytes(lim.maxBytes) + "; " + lower + " or raise the budget (--max-memory)";
            return o;
        }
        keptAfter += totalBytes;
    }
    return {};
}

DeriveOutcome Derivation::deriveGeneral(int n) {
    if (DeriveOutcome predicted = predictGrowth(n); !predicted.ok()) return predicted;
    for (int k = m_reached + 1; k <= n; ++k) {
        // A cpfg environment program (-e) is asked as the step begins, of the string before it
        // (cpfg's default, `environment display: after`): that step is kept as it was shown.
        // With `environment display: before` it was asked as that step was finished.
        ModuleString asked;
        const bool askFirst = m_environmentRun && m_programBefore && !m_options.holdQueries;
        if (askFirst) {
            asked = *m_steps[size_t(k - 1)];
            std::string error;
            if (!answerQueries(*m_grammar, asked, k - 1, m_seed, &error, m_environmentRun.get()))
                return {DeriveStatus::Failed, k, 0, 0, "step " + std::to_string(k) + ": " + error};
        }
        const ModuleString& in = askFirst ? asked : *m_steps[size_t(k - 1)];
        std::uint64_t modules, params;
        m_rewriter->bound(in, modules, params, false);
        DeriveOutcome o = checkSize(k, modules, params);
        if (!o.ok()) {  // the quick bound is loose: refuse only on the per-symbol one
            m_rewriter->bound(in, modules, params, true);
            o = checkSize(k, modules, params);
            if (!o.ok()) return o;
        }
        if (cancelled()) return {DeriveStatus::Cancelled, k, 0, 0, "cancelled"};
        auto t0 = std::chrono::steady_clock::now();
        auto out = std::make_shared<ModuleString>();
        Rng stepRng = Rng::forStream(m_seed, std::uint64_t(k));
        Rng& rng = m_cpfgRng ? *m_cpfgRng : stepRng;  // cpfg: one stream through the derivation
        std::function<void(double)> progress;
        if (m_options.progress) progress = [&](double f) { m_options.progress(k, n, f); };
        std::shared_ptr<PodBuffer<std::uint16_t>> ages;
        std::shared_ptr<Origins> origins;
        StepRewriter::Ages ageArgs{};
        if (m_options.trackAges) {
            ages = std::make_shared<PodBuffer<std::uint16_t>>();
            ageArgs = {m_ages[size_t(k - 1)]->data(), ages.get(), std::uint16_t(std::min(k, 65535))};
        }
        if (m_options.trackOrigins) {
            origins = std::make_shared<Origins>();
            ageArgs.parent = &origins->parent;
            ageArgs.rule = &origins->rule;
        }
        // cpfg: a '%' of the last step removes the rest of its branch as this step is derived.
        const ModuleString* src = &in;
        ModuleString cutCopy;
        PodBuffer<std::uint16_t> cutAges;
        PodBuffer<std::uint32_t> cutIndex;  // origins: where each module of the cut copy was
        PodBuffer<std::int32_t> cutRule;
        if (m_grammar->cutInNextStep &&
            std::find(in.symbols.data(), in.symbols.data() + in.size(), Alphabet::kCut) != in.symbols.data() + in.size()) {
            cutCopy = in;
            if (ages) {
                cutAges = *m_ages[size_t(k - 1)];
                ageArgs.in = cutAges.data();
            }
            if (origins) {
                cutIndex.resizeUninitialized(in.size());
                cutRule.resizeUninitialized(in.size());
                for (size_t i = 0; i < in.size(); ++i) cutIndex.data()[i] = std::uint32_t(i), cutRule.data()[i] = -1;
            }
            applyCut(cutCopy, m_grammar->alphabet, ages ? &cutAges : nullptr, origins ? &cutIndex : nullptr,
                     origins ? &cutRule : nullptr);
            src = &cutCopy;
        }
        if (!m_grammar->startEachBlock.empty()) runStatements(m_grammar->startEachBlock, m_rewriter->slots(), rng);
        if (!m_rewriter->rewrite(*src, *out, rng, m_options.cancel, progress, ages || origins ? &ageArgs : nullptr))
            return {DeriveStatus::Cancelled, k, 0, 0, "cancelled"};
        if (origins && src == &cutCopy)
            for (size_t j = 0; j < origins->parent.size(); ++j) origins->parent.data()[j] = cutIndex.data()[origins->parent.data()[j]];
        if (m_decomposer || m_grammar->hasQueries()) {
            DeriveOutcome f = finishStep(k, *out, ages.get(), origins.get());
            if (!f.ok()) return f;
        }
        if (!m_grammar->endEachBlock.empty()) runStatements(m_grammar->endEachBlock, m_rewriter->slots(), rng);
        if (ages) m_ages.push_back(std::move(ages));
        if (origins) m_origins.push_back(std::move(origins));
        record(k, *out, millisSince(t0));
        if (m_options.holdQueries) m_last = out;
        m_steps.push_back(std::move(out));
        m_reached = k;
        if (m_options.progress) m_options.progress(k, n, 1.0);
    }
    return {};
}

// [SECTION] The steps kept, and derive()

std::shared_ptr<const ModuleString> Derivation::step(int k) {
    if (k < 0 || k > m_reached) return nullptr;
    if (m_steps.size() <= size_t(k)) m_steps.resize(size_t(k) + 1);
    if (!m_steps[size_t(k)] && m_d0l) {
        auto t0 = std::chrono::steady_clock::now();
        auto out = std::make_shared<ModuleString>();
        m_d0l->expand(m_grammar->axiom, k, *out, nullptr, {});
        record(k, *out, millisSince(t0));
        m_steps[size_t(k)] = std::move(out);
    }
    return m_steps[size_t(k)];
}

std::shared_ptr<const Origins> Derivation::origins(int k) const {
    if (k < 0 || size_t(k) >= m_origins.size()) return nullptr;
    return m_origins[size_t(k)];
}

std::shared_ptr<const PodBuffer<std::uint16_t>> Derivation::ages(int k) const {
    if (k < 0 || size_t(k) >= m_ages.size()) return nullptr;
    return m_ages[size_t(k)];
}

DeriveResult derive(std::shared_ptr<const Grammar> grammar, int n, const DeriveOptions& options) {
    Derivation d(std::move(grammar), options);
    DeriveResult r;
    r.outcome = d.deriveTo(n);
    if (r.outcome.ok()) r.string = d.step(n);
    return r;
}

}  // namespace sprout
