#pragma once
// The D0L fast path. S(s, d), the expansion of symbol s after d steps, is cached as a block
// while it is at most kBlock modules long; step n is written from the axiom by descending
// the derivation tree only until a cached block covers a subtree, then copying that block.
// Nearly every module is written by a memcpy of a block that sits in cache.
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/language/grammar.hpp"
#include "core/language/successor_table.hpp"

namespace sprout {

class D0LExpander {
public:
    static constexpr std::uint64_t kBlock = 4096;  // modules; 8 KB blocks stay in L1/L2
    static constexpr int kBlockDepth = 64;

    static bool applicable(const Grammar& g);
    explicit D0LExpander(const Grammar& g);

    // Exact module count of step n of `axiom` (saturates at 2^62).
    std::uint64_t countAt(const ModuleString& axiom, int n) const;
    // The counts of steps 0..n in one pass.
    std::vector<std::uint64_t> countsUpTo(const ModuleString& axiom, int n) const;
    // Writes step n into `out`. Returns false when cancelled.
    bool expand(const ModuleString& axiom, int n, ModuleString& out,
                const std::atomic<bool>* cancel, const std::function<void(double)>& progress) const;

    // Whether `s` is exactly step n of `axiom`: the same walk as expand, comparing.
    bool matches(const ModuleString& axiom, int n, const ModuleString& s) const;

    // The rules it expands with: what the turtle may draw the tree of step n from.
    const SuccessorTable& successors() const { return m_table; }

private:
    // Calls piece(symbols, count) for consecutive runs of step n, in order, until it
    // returns false; returns whether it got to the end.
    template <class Piece>
    bool forEachPiece(const ModuleString& axiom, int n, Piece&& piece) const;
    std::uint64_t len(SymbolId s, int d) const { return m_len[size_t(d) * m_alphabet + s]; }

    size_t m_alphabet;
    SuccessorTable m_table;
    std::vector<std::uint64_t> m_len;        // (kBlockDepth + 1) x alphabet
    std::vector<std::uint32_t> m_blockStart;  // (kBlockDepth + 1) x alphabet, kNoBlock if none
    std::vector<SymbolId> m_pool;
};

}  // namespace sprout
