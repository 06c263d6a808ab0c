#pragma once
// Derivation: grammar + n -> the module string of step n, step by step, with a progress
// callback, a cancellation flag and a size cap checked *before* each step allocates.
//
// Deterministic context-free non-parametric grammars (D0L) take a fast path: step n is
// written straight from the axiom by copying cached expansions of each symbol (memcpy
// speed), so any step can be re-made cheaply and only the steps asked for are stored.
// Every other grammar derives step k from step k-1 and keeps all steps, so stepping
// through iterations 0..n costs nothing extra.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/language/grammar.hpp"
#include "core/language/module_string.hpp"
// What the derivation hands the turtle (interpret, applyInterpretation) and open L-systems
// (answerQueries): the derivation's public API is these three headers.
#include "core/derive/draw.hpp"
#include "core/derive/queries.hpp"

namespace sprout {

// The memory a derivation may take by default: half of what the machine has available now
// (MemAvailable), read once; 8 GB where that cannot be read.
std::uint64_t defaultMemoryBudget();

struct DeriveLimits {
    // 500 M modules is 2 GB of symbols, leaving room for the steps kept before it, the
    // turtle's geometry and the renderer.
    std::uint64_t maxModules = 500'000'000;
    std::uint64_t maxBytes = defaultMemoryBudget();  // all kept steps plus the next one
};

struct DeriveOptions {
    DeriveLimits limits;
    const std::atomic<bool>* cancel = nullptr;  // set to true to drop the work
    // step being derived (1-based), total steps, fraction of that step done
    std::function<void(int step, int total, double fraction)> progress;
    std::optional<std::uint64_t> seed;  // overrides the grammar's `seed:`
    // Also record the step that created each module (2 more bytes per module), for growth
    // animation; uses the step-by-step engine for every grammar.
    bool trackAges = false;
    // Leave the query modules of each step unanswered: the caller answers them in
    // unansweredStep() before deriving the next step (forests that share one environment
    // derive their plants in lockstep). Uses the step-by-step engine.
    bool holdQueries = false;
    // Also record where each module came from (the module of the step before and the rule
    // that made it; 8 bytes per module), for picking and the derivation inspector. Uses the
    // step-by-step engine.
    bool trackOrigins = false;
};

// Where the modules of one step came from (DeriveOptions::trackOrigins).
struct Origins {
    PodBuffer<std::uint32_t> parent;  // index of the module in the step before (step 0: in the axiom as written)
    // The rule that made it: >= 0 a production of grammar.rules, <= -2 the decomposition
    // production -(rule + 2), -1 none (copied unchanged; the axiom).
    PodBuffer<std::int32_t> rule;
};

struct StepStats {
    int step = 0;
    std::uint64_t modules = 0;
    std::uint64_t params = 0;
    double millis = 0;  // time to produce this step
};

enum class DeriveStatus { Ok, Cancelled, TooBig, Failed };  // Failed: a decomposition that never ends

struct DeriveOutcome {
    DeriveStatus status = DeriveStatus::Ok;
    int step = 0;                         // the step that was refused or interrupted
    std::uint64_t predictedModules = 0;   // TooBig: the prediction that was refused
    std::uint64_t predictedBytes = 0;
    std::string message;                  // for the user; empty when Ok
    bool ok() const { return status == DeriveStatus::Ok; }
};

class Derivation {
public:
    explicit Derivation(std::shared_ptr<const Grammar> grammar, DeriveOptions options = {});
    ~Derivation();
    Derivation(const Derivation&) = delete;
    Derivation& operator=(const Derivation&) = delete;

    // Makes step n available (deriving what is missing).
    DeriveOutcome deriveTo(int n);
    // Step k (0 = axiom), for k <= the last step reached; D0L steps are made on demand.
    std::shared_ptr<const ModuleString> step(int k);
    // The creation step of each module of step k (with DeriveOptions::trackAges), else null.
    std::shared_ptr<const PodBuffer<std::uint16_t>> ages(int k) const;
    // Where the modules of step k came from (with DeriveOptions::trackOrigins), else null.
    std::shared_ptr<const Origins> origins(int k) const;
    int stepsDerived() const { return m_reached; }
    // Statistics for the steps produced so far (D0L: the ones made).
    const std::vector<StepStats>& stats() const { return m_stats; }
    bool fastPath() const { return m_d0l != nullptr; }
    const Grammar& grammar() const { return *m_grammar; }
    const std::shared_ptr<const Grammar>& sharedGrammar() const { return m_grammar; }
    std::uint64_t seed() const { return m_seed; }
    // With DeriveOptions::holdQueries: the last step made, to answer its query modules in.
    ModuleString* unansweredStep() { return m_last.get(); }

private:
    DeriveOutcome checkSize(int step, std::uint64_t modules, std::uint64_t params) const;
    // Before any step is derived: the sizes the steps up to n will at least have, whatever rule
    // applies; the first one over a limit is refused at once (TooBig), so explosive growth is
    // refused before it takes the memory.
    DeriveOutcome predictGrowth(int n) const;
    // The same for the passes of a decomposition over `s`, when each of its rules always
    // applies (the passes are then followed exactly on the counts of each symbol).
    DeriveOutcome predictDecomposition(int step, const ModuleString& s) const;
    DeriveOutcome deriveGeneral(int n);
    // cpfg: the decomposition rules until none applies, then the query modules' frames.
    DeriveOutcome finishStep(int step, ModuleString& s, PodBuffer<std::uint16_t>* ages, Origins* origins = nullptr);
    bool cancelled() const { return m_options.cancel && m_options.cancel->load(std::memory_order_relaxed); }
    void record(int step, const ModuleString& s, double millis);

    std::shared_ptr<const Grammar> m_grammar;
    DeriveOptions m_options;
    std::uint64_t m_seed;
    std::vector<std::shared_ptr<const ModuleString>> m_steps;  // null where not made (D0L)
    std::shared_ptr<ModuleString> m_last;  // holdQueries: the last step, still to be answered
    std::vector<std::shared_ptr<const PodBuffer<std::uint16_t>>> m_ages;  // trackAges only
    std::vector<std::shared_ptr<const Origins>> m_origins;                // trackOrigins only
    std::vector<StepStats> m_stats;
    int m_reached = 0;
    std::unique_ptr<class D0LExpander> m_d0l;
    std::unique_ptr<class StepRewriter> m_rewriter;
    std::unique_ptr<class StepRewriter> m_decomposer;
    std::optional<Rng> m_cpfgRng;  // cpfg's random numbers, one stream through the steps (Grammar::cpfgRandom)
    // A cpfg environment program's run (`-e`): its state goes from step to step.
    std::unique_ptr<ProgramRun> m_environmentRun;
    bool m_programBefore = false;  // asked as each step begins (EnvironmentProgram::afterStep false)
    DeriveOutcome m_axiomOutcome;  // the axiom's decomposition, reported by deriveTo
};

// One-shot helper: step n of the grammar (or the refusal). For tests and the CLI.
struct DeriveResult {
    std::shared_ptr<const ModuleString> string;
    DeriveOutcome outcome;
};
DeriveResult derive(std::shared_ptr<const Grammar> grammar, int n, const DeriveOptions& options = {});

// Before `s` (step `step`) is drawn: its drawing takes a segment (sizeof(CylinderInstance)) for
// each module that draws one, about as much as a polygon's vertex; with the string, over
// limits.maxBytes it is refused (TooBig, the message naming the step and the sizes), before
// the turtle takes the memory. Not predicted where interpretation rules make what is drawn.
DeriveOutcome checkDrawing(const ModuleString& s, const Grammar& g, const DeriveLimits& limits, int step);
// (in core/derive/draw.cpp)

// "12,345,678"
std::string withThousands(std::uint64_t v);
std::string humanBytes(std::uint64_t bytes);  // "0.6 MB", "10.8 GB"

}  // namespace sprout
