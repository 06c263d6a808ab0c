#pragma once
// A derived string: contiguous symbol ids and, separately, the parameters of the parametric
// modules in string order. Module i's parameters follow those of modules 0..i-1; their count
// is the symbol's arity.
#include <string>

#include "core/language/alphabet.hpp"
#include "core/base/pod_buffer.hpp"

namespace sprout {

struct ModuleString {
    PodBuffer<SymbolId> symbols;
    PodBuffer<double> params;

    size_t size() const { return symbols.size(); }
    size_t bytes() const { return symbols.size() * sizeof(SymbolId) + params.size() * sizeof(double); }
    bool operator==(const ModuleString&) const = default;
};

// Module names concatenated, parameters as name(p1,p2) in shortest round-trip decimal form.
std::string toString(const ModuleString& s, const Alphabet& alphabet);
// With `alphabet`, a parameter written as a quoted name prints as that name.
void appendModule(std::string& out, const SymbolInfo& symbol, const double* params, const Alphabet* alphabet = nullptr);
void appendNumber(std::string& out, double v);

// A rewriting's fixed point, bit for bit: a NaN parameter is the same NaN, not a change.
bool sameString(const ModuleString& a, const ModuleString& b);

}  // namespace sprout
