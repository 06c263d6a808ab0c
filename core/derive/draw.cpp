#include "core/derive/draw.hpp"

#include "core/base/rng.hpp"
#include "core/derive/derive.hpp"
#include "core/derive/d0l.hpp"
#include "core/derive/step_rewriter.hpp"

namespace sprout {

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

constexpr int kTreeMaxDepth = 1024;  // the tree walk recurses once per step
constexpr size_t kTreeMaxTable = 1 << 22;

TurtleStats interpret(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out) {
    // A big D0L string is drawn from its derivation tree when it is exactly step n of the
    // grammar. Interpretation rules, if simple, are applied at the tree's leaves.
    const int n = options.derivationSteps;
    if (options.fromTree && s.size() >= options.treeMinModules && n > 0 && n <= kTreeMaxDepth && D0LExpander::applicable(g) &&
        (size_t(n) + 1) * g.alphabet.size() <= kTreeMaxTable && treeDrawable(g, options)) {
        D0LExpander tree(g);
        if (tree.matches(g.axiom, n, s))
            if (TurtleStats stats = drawTree({tree.successors(), g.axiom, n}, g, options, out); stats.fromTree) return stats;
    }
    if (g.interpretation.productions.empty()) {
        drawString(s, g, options, out);
        return {};
    }
    ModuleString drawn = applyInterpretation(g, s, options.seed);
    TurtleOptions o = options;
    o.ages = nullptr;  // the interpretation changes positions: ages no longer line up
    drawString(drawn, g, o, out);
    return {};
}

DeriveOutcome checkDrawing(const ModuleString& s, const Grammar& g, const DeriveLimits& limits, int step) {
    if (!g.interpretation.productions.empty()) {
        // The string the interpretation rules make (their first level), bounded per symbol as
        // a production step is: what is drawn from it is not known before it is made.
        StepRewriter rewriter(g, g.interpretation);
        std::uint64_t modules = 0, params = 0;
        rewriter.bound(s, modules, params, true);
        const std::uint64_t made = modules * sizeof(SymbolId) + params * sizeof(double), total = made + s.bytes();
        if (modules <= limits.maxModules && total <= limits.maxBytes) return {};
        DeriveOutcome o;
        o.status = DeriveStatus::TooBig;
        o.step = step;
        o.predictedModules = modules;
        o.predictedBytes = total;
        o.message = "drawing step " + std::to_string(step) + ": its interpretation rules would make up to " + withThousands(modules) +
                    " modules (" + humanBytes(made) + "), with the string " + humanBytes(total) + ", over the " +
                    (modules > limits.maxModules ? "limit of " + withThousands(limits.maxModules) + " modules; lower n below " +
                                                       std::to_string(step) + " or raise the limit (--max-modules)"
                                                 : "memory budget of " + humanBytes(limits.maxBytes) + "; lower n below " +
                                                       std::to_string(step) + " or raise the budget (--max-memory)");
        return o;
    }
    std::vector<std::uint8_t> draws(g.alphabet.size());
    for (size_t k = 0; k < draws.size(); ++k) draws[k] = drawsSegment(g.alphabet[SymbolId(k)].name);
    std::uint64_t segments = 0;
    const SymbolId* symbols = s.symbols.data();
    for (size_t i = 0; i < s.size(); ++i) segments += draws[symbols[i]];
    const std::uint64_t drawing = segments * sizeof(CylinderInstance), total = drawing + s.bytes();
    if (total <= limits.maxBytes) return {};
    DeriveOutcome o;
    o.status = DeriveStatus::TooBig;
    o.step = step;
    o.predictedModules = s.size();
    o.predictedBytes = total;
    o.message = "drawing step " + std::to_string(step) + " would take about " + humanBytes(drawing) + " for its " + withThousands(segments) +
                " segments, with its string " + humanBytes(total) + ", over the memory budget of " + humanBytes(limits.maxBytes) +
                "; lower n below " + std::to_string(step) + " or raise the budget (--max-memory)";
    return o;
}

}  // namespace sprout
