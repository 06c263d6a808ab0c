#include "core/derive.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

#include <glm/geometric.hpp>

#include "core/d0l.hpp"
#include "core/step_rewriter.hpp"
#include "core/turtle.hpp"

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

// A rewriting's fixed point, bit for bit: a NaN parameter is the same NaN, not a change.
static bool sameString(const ModuleString& a, const ModuleString& b) {
    return a.symbols == b.symbols && a.params.size() == b.params.size() &&
           (a.params.size() == 0 || std::memcmp(a.params.data(), b.params.data(), a.params.size() * sizeof(double)) == 0);
}

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
    std::shared_ptr<PodBuffer<std::uint16_t>> axiomAges;
    if (m_options.trackAges) {
        axiomAges = std::make_shared<PodBuffer<std::uint16_t>>();
        axiomAges->resizeUninitialized(m_grammar->axiom.size());
        std::fill(axiomAges->data(), axiomAges->data() + axiomAges->size(), std::uint16_t(0));
    }
    if (D0LExpander::applicable(*m_grammar) && !m_options.trackAges && !m_options.holdQueries && !m_options.trackOrigins) m_d0l = std::make_unique<D0LExpander>(*m_grammar);
    else m_rewriter = std::make_unique<StepRewriter>(*m_grammar, m_grammar->rules);
    if (!m_grammar->decomposition.productions.empty())
        m_decomposer = std::make_unique<StepRewriter>(*m_grammar, m_grammar->decomposition);
    auto axiom = std::make_shared<ModuleString>(m_grammar->axiom);
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

DeriveOutcome Derivation::finishStep(int step, ModuleString& s, PodBuffer<std::uint16_t>* ages, Origins* origins) {
    if (m_decomposer) {
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
            Rng rng = Rng::forStream(m_seed, 0xdec0000ull + std::uint64_t(step) * 1024 + std::uint64_t(pass));
            if (!m_decomposer->rewrite(s, out, rng, m_options.cancel, {}, ages || origins ? &ageArgs : nullptr))
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
        if (!answerQueries(*m_grammar, s, step, m_seed, &error)) {
            DeriveOutcome o;
            o.status = DeriveStatus::Failed;
            o.step = step;
            o.message = "step " + std::to_string(step) + ": " + error;
            return o;
        }
    }
    return {};
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
    for (const auto& o : m_origins)
        if (o) kept += o->parent.size() * (sizeof(std::uint32_t) + sizeof(std::int32_t));
    if (m_options.trackAges) bytes += modules * sizeof(std::uint16_t);
    if (m_options.trackOrigins) bytes += modules * (sizeof(std::uint32_t) + sizeof(std::int32_t));
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
        if (!m_rewriter->rewrite(*src, *out, rng, m_options.cancel, progress, ages || origins ? &ageArgs : nullptr))
            return {DeriveStatus::Cancelled, k, 0, 0, "cancelled"};
        if (origins && src == &cutCopy)
            for (size_t j = 0; j < origins->parent.size(); ++j) origins->parent.data()[j] = cutIndex.data()[origins->parent.data()[j]];
        if (m_decomposer || m_grammar->hasQueries()) {
            DeriveOutcome f = finishStep(k, *out, ages.get(), origins.get());
            if (!f.ok()) return f;
        }
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

ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& s, std::uint64_t seed) {
    if (grammar.interpretation.productions.empty()) return s;
    StepRewriter rewriter(grammar, grammar.interpretation);
    ModuleString out;
    Rng rng = Rng::forStream(seed, 0x1e7e7);
    rewriter.rewrite(s, out, rng, nullptr, {});
    // Recursion (cpfg `maximum depth:`): each level rewrites what the one before produced;
    // it stops early when nothing changes, and at a size no screen could use.
    for (int level = 1; level < grammar.interpretationDepth; ++level) {
        std::uint64_t modules, params;
        rewriter.bound(out, modules, params, true);
        if (modules > 200'000'000) break;
        ModuleString next;
        Rng r = Rng::forStream(seed, 0x1e7e7 + std::uint64_t(level));
        rewriter.rewrite(out, next, r, nullptr, {});
        const bool same = sameString(next, out);
        out = std::move(next);
        if (same) break;
    }
    return out;
}

bool answerQueries(const Grammar& grammar, ModuleString& s, int step, std::uint64_t seed, std::string* error) {
    std::vector<QueryTarget> one{{&grammar, &s, step, seed}};
    return answerQueriesTogether(grammar.environment, seed, one, error);
}

namespace {

// A plant's frame turned by `yaw` degrees about +Y (forests), and back.
glm::dvec3 turnBy(const glm::dvec3& v, double yaw) {
    const double c = std::cos(yaw * 3.14159265358979 / 180), s = std::sin(yaw * 3.14159265358979 / 180);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

}  // namespace

bool answerQueriesTogether(const Environment& env, std::uint64_t envSeed, std::vector<QueryTarget>& targets, std::string* error) {
    if (targets.empty()) return true;
    struct Pass {
        std::vector<QueryFrame> frames;
        Geometry grown;
        std::vector<char> kind;
        bool answerable = false;
    };
    std::vector<Pass> passes(targets.size());
    for (size_t t = 0; t < targets.size(); ++t) {
        const QueryTarget& q = targets[t];
        Pass& pass = passes[t];
        TurtleOptions o{q.step, q.seed, nullptr};
        o.fromTree = false;
        o.queries = &pass.frames;
        interpret(*q.string, *q.grammar, o, pass.grown);
        // Frames come in drawing order; a homomorphism that drops or repeats query modules
        // would break the correspondence, and then the parameters are left as they were.
        const Alphabet& alphabet = q.grammar->alphabet;
        pass.kind.assign(alphabet.size(), 0);
        for (size_t k = 0; k < alphabet.size(); ++k) pass.kind[k] = queryKind(alphabet[SymbolId(k)].name);
        size_t count = 0;
        for (SymbolId id : q.string->symbols) count += pass.kind[id] != 0;
        pass.answerable = count == pass.frames.size();
    }
    // What the environment sees: every plant where it stands. One plant at the origin is its
    // own geometry.
    const bool placed = targets.size() > 1 || targets[0].yaw != 0 || targets[0].at != glm::dvec3(0.0);
    Geometry world;
    const Geometry* grown = &passes[0].grown;
    if (placed && (env.isLight() || env.isAttraction())) {
        for (size_t t = 0; t < targets.size(); ++t)
            placeGeometry(passes[t].grown, float(targets[t].yaw), glm::vec3(targets[t].at), world);
        grown = &world;
    }
    LightGrid light;
    if (env.isLight()) {
        std::string why;
        if (!env.buildLight(*grown, light, why)) {
            if (error) *error = why;
            return false;
        }
    }
    auto toWorld = [&](const QueryTarget& q, const glm::vec3& p) { return turnBy(glm::dvec3(p), q.yaw) + q.at; };
    // Directions in an answer go back into the plant's own frame.
    auto directionBack = [&](const QueryTarget& q, double* out, int count) {
        if (q.yaw == 0 || count < 3) return;
        const glm::dvec3 v = turnBy(glm::dvec3(out[0], out[1], out[2]), -q.yaw);
        for (int k = 0; k < 3; ++k) out[k] = std::round(v[k] * 1e5) / 1e5 + 0.0;
    };
    if (env.isAttraction()) {
        // Space colonisation answers every bud at once, of every plant: a point pulls only its
        // nearest bud.
        std::vector<glm::dvec3> buds;
        std::vector<double*> params;
        std::vector<int> arities;
        std::vector<size_t> owner;
        for (size_t t = 0; t < targets.size(); ++t) {
            if (!passes[t].answerable) continue;
            ModuleString& s = *targets[t].string;
            const Alphabet& alphabet = targets[t].grammar->alphabet;
            size_t q = 0, pp = 0;
            for (size_t i = 0; i < s.size(); ++i) {
                const SymbolId id = s.symbols[i];
                const unsigned a = alphabet[id].arity;
                if (passes[t].kind[id]) {
                    const QueryFrame& f = passes[t].frames[q++];
                    if (passes[t].kind[id] == 'E') {
                        buds.push_back(toWorld(targets[t], f.position));
                        params.push_back(s.params.data() + pp);  // a ?E without parameters: none there
                        arities.push_back(int(a));
                        owner.push_back(t);
                    }
                }
                pp += a;
            }
        }
        env.answerAttraction(buds, env.freePoints(*grown, envSeed), params, arities);
        for (size_t b = 0; b < buds.size(); ++b) directionBack(targets[owner[b]], params[b], std::min(arities[b], 3));
    }
    for (size_t t = 0; t < targets.size(); ++t) {
        if (!passes[t].answerable) continue;
        const QueryTarget& target = targets[t];
        ModuleString& s = *target.string;
        const Alphabet& alphabet = target.grammar->alphabet;
        const std::vector<char>& kind = passes[t].kind;
        size_t q = 0, pp = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            const SymbolId id = s.symbols[i];
            const unsigned a = alphabet[id].arity;
            if (kind[id] == 'E') {  // a communication module: the environment answers (open L-systems)
                const QueryFrame& f = passes[t].frames[q++];
                if (env.isAttraction()) {  // answered above: the ?E only uses up its frame here
                } else {
                    const glm::dvec3 p = toWorld(target, f.position), h = turnBy(glm::dvec3(f.heading), target.yaw);
                    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && glm::length(h) > 0)) {
                        // No answer can be right there, and a NaN would spread through the rules.
                        if (error)
                            *error = std::string(targets.size() > 1 ? "plant " + std::to_string(t + 1) + ": " : "") + "the ?E at module " +
                                     std::to_string(i + 1) + " of the string is at a point that is not a number (the turtle's "
                                     "moves before it are NaN or infinite, e.g. F of a parameter that overflowed): the "
                                     "environment cannot answer it";
                        return false;
                    }
                    // A ?E without parameters (the string may hold none at all) is asked, and told
                    // nothing: no reference into an empty buffer is made for it.
                    env.answer(p, glm::normalize(h), s.params.data() + pp, int(a), &light);
                    if ((!env.obstacles.empty() || env.ground) && a >= 5) directionBack(target, s.params.data() + pp + 2, int(a) - 2);
                }
            } else if (kind[id]) {
                const QueryFrame& f = passes[t].frames[q++];
                const glm::vec3& v = kind[id] == 'P' ? f.position : kind[id] == 'H' ? f.heading : kind[id] == 'U' ? f.up : f.left;
                // Rounded to 1e-5: the float turtle's last bits would otherwise show as 2.9999998.
                for (unsigned k = 0; k < a && k < 3; ++k) s.params[pp + k] = std::round(double(v[int(k)]) * 1e5) / 1e5 + 0.0;
            }
            pp += a;
        }
    }
    return true;
}

}  // namespace sprout
