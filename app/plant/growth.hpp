#pragma once
// The one way from a grammar to a plant (docs/architecture.md): a grammar derived step by step
// (core's Derivation), a step checked before the turtle draws it (checkDrawing: what the
// turtle may draw within the limits) and drawn (interpret). `sprout expand | render | export`,
// snapshots, animations, the viewer's worker and Python's Plant all grow their plants here;
// nothing else in app/ or python/ calls core's derivation or turtle.
#include <cstdint>
#include <memory>

#include "core/derive/derive.hpp"
#include "core/derive/draw.hpp"

namespace sprout {

class Growth {
public:
    Growth(std::shared_ptr<const Grammar> grammar, DeriveOptions options = {});

    // Step n derived (what is missing of it); only derived, as `sprout expand` prints it.
    DeriveOutcome derive(int n);
    // Step n derived and checked against what the turtle may draw within `limits` (too many
    // segments or polygons: TooBig, at once, not after the turtle ran out of memory).
    DeriveOutcome grow(int n, const DeriveLimits& limits);
    // Step n drawn by the turtle, once derive() or grow() reached it, with a VLab object's
    // background scene after it (vlab_background.hpp).
    TurtleStats draw(int n, const TurtleOptions& options, Geometry& out);
    // Step n as derived, its modules' ages (DeriveOptions::trackAges) and its seed.
    std::shared_ptr<const ModuleString> step(int n) { return m_derivation.step(n); }
    std::shared_ptr<const PodBuffer<std::uint16_t>> ages(int n) const { return m_derivation.ages(n); }
    std::uint64_t seed() const { return m_derivation.seed(); }
    // The derivation itself: its statistics and records (`sprout expand --stats`, provenance).
    Derivation& derivation() { return m_derivation; }

private:
    Derivation m_derivation;
};

// Step n of `grammar` grown and drawn in one go (a picture, an export): false with the
// outcome's message in `error` when it cannot be; `seed`, when given, receives the seed used.
bool growAndDraw(std::shared_ptr<const Grammar> grammar, int n, const DeriveOptions& options, Geometry& out,
                 std::string& error, std::uint64_t* seed = nullptr);

// A string drawn as it is with `grammar`'s interpretation (and its background scene): an L-Py
// model's kept drawing (a grammar with no rules whose axiom is its string), a step Python's
// Plant keeps.
TurtleStats drawAsIs(const ModuleString& s, const Grammar& grammar, const TurtleOptions& options, Geometry& out);

}  // namespace sprout
