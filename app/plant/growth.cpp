#include "app/plant/growth.hpp"

#include "app/plant/vlab_background.hpp"

namespace sprout {

Growth::Growth(std::shared_ptr<const Grammar> grammar, DeriveOptions options) : m_derivation(std::move(grammar), std::move(options)) {}

DeriveOutcome Growth::derive(int n) { return m_derivation.deriveTo(n); }

DeriveOutcome Growth::grow(int n, const DeriveLimits& limits) {
    DeriveOutcome outcome = m_derivation.deriveTo(n);
    if (outcome.ok()) outcome = checkDrawing(*m_derivation.step(n), m_derivation.grammar(), limits, n);
    return outcome;
}

TurtleStats Growth::draw(int n, const TurtleOptions& options, Geometry& out) {
    const TurtleStats stats = interpret(*m_derivation.step(n), m_derivation.grammar(), options, out);
    drawPictureBackground(m_derivation.grammar().settings, out);  // a VLab object's background scene
    return stats;
}

bool growAndDraw(std::shared_ptr<const Grammar> grammar, int n, const DeriveOptions& options, Geometry& out,
                 std::string& error, std::uint64_t* seed) {
    Growth growth(std::move(grammar), options);
    DeriveOutcome outcome = growth.grow(n, options.limits);
    if (!outcome.ok()) {
        error = outcome.message;
        return false;
    }
    growth.draw(n, {n, growth.seed(), nullptr}, out);
    if (seed) *seed = growth.seed();
    return true;
}

TurtleStats drawAsIs(const ModuleString& s, const Grammar& grammar, const TurtleOptions& options, Geometry& out) {
    const TurtleStats stats = interpret(s, grammar, options, out);
    drawPictureBackground(grammar.settings, out);
    return stats;
}

}  // namespace sprout
