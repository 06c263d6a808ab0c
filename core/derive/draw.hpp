#pragma once
// What the derivation hands the turtle. A derived string is drawn as its grammar means it:
// through the grammar's interpretation rules (cpfg's homomorphism, applied here, never stored),
// or, for a big D0L string that is exactly step n of its grammar, from its derivation tree
// (the turtle places each repeated subtree instead of reading the string). The turtle itself
// (core/turtle/turtle.hpp) draws what it is given and includes no derivation header.
#include <cstdint>

#include "core/language/grammar.hpp"
#include "core/turtle/geometry.hpp"
#include "core/turtle/turtle.hpp"

namespace sprout {

// The cpfg homomorphism: applies the grammar's interpretation rules to `s`, again to what
// they produce up to `maximum depth:` levels (1 unless the grammar says). The result is what
// the turtle draws; it is never fed back into the derivation.
ModuleString applyInterpretation(const Grammar& grammar, const ModuleString& s, std::uint64_t seed);

// Draws `s` (step options.derivationSteps of `g`) into `out`, reusing its buffers: from the
// derivation tree when it is a big D0L string that is exactly that step (checked: comparing
// costs a small part of drawing) and options.fromTree, else the string after the grammar's
// interpretation rules. Never fails (see drawString).
TurtleStats interpret(const ModuleString& s, const Grammar& g, const TurtleOptions& options, Geometry& out);

}  // namespace sprout
