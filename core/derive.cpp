#include "core/derive.hpp"

#include <chrono>

#include "core/d0l.hpp"
#include "core/step_rewriter.hpp"

namespace sprout {
namespace {

double millisSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string humanBytes(std::uint64_t b) {
    char buf[32];
    if (b >= (1ull << 30)) std::snprintf(buf, sizeof buf, "%.1f GB", double(b) / double(1ull << 30));
    else std::snprintf(buf, sizeof buf, "%.1f MB", double(b) / double(1ull << 20));
    return buf;
}

}  // namespace

std::string withThousands(std::uint64_t v) {
    std::string digits = std::to_string(v), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

Derivation::Derivation(std::shared_ptr<const Grammar> grammar, DeriveOptions options)
    : m_grammar(std::move(grammar)),
      m_options(std::move(options)),
      m_seed(m_options.seed.value_or(m_grammar->settings.seed)) {
    m_steps.push_back(std::make_shared<const ModuleString>(m_grammar->axiom));
    m_stats.push_back({0, m_grammar->axiom.size(), m_grammar->axiom.params.size(), 0.0});
    if (m_options.trackAges) {
        auto a = std::make_shared<PodBuffer<std::uint16_t>>();
        a->resizeUninitialized(m_grammar->axiom.size());
        std::fill(a->data(), a->data() + a->size(), std::uint16_t(0));
        m_ages.push_back(std::move(a));
    }
    if (D0LExpander::applicable(*m_grammar) && !m_options.trackAges) m_d0l = std::make_unique<D0LExpander>(*m_grammar);
    else m_rewriter = std::make_unique<StepRewriter>(*m_grammar, m_grammar->rules);
}

Derivation::~Derivation() = default;

DeriveOutcome Derivation::checkSize(int step, std::uint64_t modules, std::uint64_t params) const {
    DeriveOutcome o;
    std::uint64_t bytes = modules * sizeof(SymbolId) + params * sizeof(double);
    std::uint64_t kept = 0;
    for (const auto& s : m_steps)
        if (s) kept += s->bytes();
    for (const auto& a : m_ages)
        if (a) kept += a->size() * sizeof(std::uint16_t);
    if (m_options.trackAges) bytes += modules * sizeof(std::uint16_t);
    o.step = step;
    o.predictedModules = modules;
    o.predictedBytes = bytes;
    const auto& lim = m_options.limits;
    if (modules > lim.maxModules) {
        o.status = DeriveStatus::TooBig;
        o.message = "step " + std::to_string(step) + " would produce " +
                    (m_d0l ? "" : "up to ") + withThousands(modules) + " modules (" + humanBytes(bytes) +
                    "), over the limit of " + withThousands(lim.maxModules) +
                    " modules; lower n or raise the limit (--max-modules)";
    } else if (bytes + kept > lim.maxBytes) {
        o.status = DeriveStatus::TooBig;
        o.message = "step " + std::to_string(step) + " would need " + humanBytes(bytes) + " for " +
                    withThousands(modules) + " modules on top of " + humanBytes(kept) +
                    " already kept, over the memory limit of " + humanBytes(lim.maxBytes) +
                    "; lower n or raise the limit (--max-memory)";
    }
    return o;
}

void Derivation::record(int step, const ModuleString& s, double millis) {
    if (int(m_stats.size()) <= step) m_stats.resize(size_t(step) + 1);
    m_stats[size_t(step)] = {step, s.size(), s.params.size(), millis};
}

DeriveOutcome Derivation::deriveTo(int n) {
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

DeriveOutcome Derivation::deriveGeneral(int n) {
    for (int k = m_reached + 1; k <= n; ++k) {
        const ModuleString& in = *m_steps[size_t(k - 1)];
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
        Rng rng = Rng::forStream(m_seed, std::uint64_t(k));
        std::function<void(double)> progress;
        if (m_options.progress) progress = [&](double f) { m_options.progress(k, n, f); };
        std::shared_ptr<PodBuffer<std::uint16_t>> ages;
        StepRewriter::Ages ageArgs{};
        if (m_options.trackAges) {
            ages = std::make_shared<PodBuffer<std::uint16_t>>();
            ageArgs = {m_ages[size_t(k - 1)]->data(), ages.get(), std::uint16_t(std::min(k, 65535))};
        }
        if (!m_rewriter->rewrite(in, *out, rng, m_options.cancel, progress, ages ? &ageArgs : nullptr))
            return {DeriveStatus::Cancelled, k, 0, 0, "cancelled"};
        if (ages) m_ages.push_back(std::move(ages));
        record(k, *out, millisSince(t0));
        m_steps.push_back(std::move(out));
        m_reached = k;
        if (m_options.progress) m_options.progress(k, n, 1.0);
    }
    return {};
}

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

ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& s, std::uint64_t seed) {
    if (grammar.interpretation.productions.empty()) return s;
    StepRewriter rewriter(grammar, grammar.interpretation);
    ModuleString out;
    Rng rng = Rng::forStream(seed, 0x1e7e7);
    rewriter.rewrite(s, out, rng, nullptr, {});
    return out;
}

}  // namespace sprout
