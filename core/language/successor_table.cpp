#include "core/language/successor_table.hpp"

namespace sprout {

bool SuccessorTable::applicable(const Grammar& g) {
    if (g.parametric() || g.stochastic() || g.hasContext() || g.usesCut() || g.needsGeneralEngine()) return false;
    for (const auto& list : g.rules.bySymbol) {
        if (list.size() > 1) return false;  // later rules are dead, but keep one code path for lint
        for (auto idx : list)
            if (g.rules.productions[idx].condition) return false;
    }
    return true;
}

SuccessorTable::SuccessorTable(const Grammar& g) {
    const size_t alphabet = g.alphabet.size();
    starts.resize(alphabet + 1);
    identities.assign(alphabet, 1);
    for (size_t s = 0; s < alphabet; ++s) {
        starts[s] = std::uint32_t(symbols.size());
        const auto& list = g.rules.bySymbol[s];
        if (list.empty()) {
            symbols.push_back(SymbolId(s));
        } else {
            const auto& succ = g.rules.productions[list.front()].successor.symbols;
            symbols.insert(symbols.end(), succ.begin(), succ.end());
            identities[s] = succ.size() == 1 && succ[0] == s;
        }
    }
    starts[alphabet] = std::uint32_t(symbols.size());
}

}  // namespace sprout
