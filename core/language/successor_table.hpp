#pragma once
// A deterministic context-free grammar's rules as a table (D0L): for each symbol, its successor,
// or the symbol itself when it has no rule. What the derivation's D0L expander walks to write
// a step, and what the turtle walks to draw a step from its derivation tree instead of its
// string: the two share the grammar's rules through this, not through each other.
#include <cstdint>
#include <vector>

#include "core/language/grammar.hpp"

namespace sprout {

struct SuccessorTable {
    // Deterministic, context-free, without parameters, conditions, stochastic choices or cut:
    // one successor per symbol, whatever its neighbours.
    static bool applicable(const Grammar& g);
    SuccessorTable() = default;
    explicit SuccessorTable(const Grammar& g);  // g must be applicable

    const SymbolId* successorBegin(SymbolId s) const { return symbols.data() + starts[s]; }
    const SymbolId* successorEnd(SymbolId s) const { return symbols.data() + starts[s + 1]; }
    bool identity(SymbolId s) const { return identities[s] != 0; }  // no rule: the symbol rewrites to itself

    std::vector<std::uint32_t> starts;   // alphabet + 1 entries into symbols
    std::vector<SymbolId> symbols;       // the successors, one after the other
    std::vector<std::uint8_t> identities;
};

}  // namespace sprout
