#include "core/derive/d0l.hpp"

#include <algorithm>
#include <cstring>

namespace sprout {
namespace {
constexpr std::uint32_t kNoBlock = UINT32_MAX;
constexpr std::uint64_t kSaturate = 1ull << 62;
constexpr size_t kMaxPool = 16u << 20;  // modules: bounds the cache for pathological grammars

std::uint64_t satAdd(std::uint64_t a, std::uint64_t b) { return std::min(kSaturate, a + b); }
}  // namespace

bool D0LExpander::applicable(const Grammar& g) { return SuccessorTable::applicable(g); }

D0LExpander::D0LExpander(const Grammar& g) : m_alphabet(g.alphabet.size()), m_table(g) {
    const size_t depths = kBlockDepth + 1;
    m_len.assign(depths * m_alphabet, 1);
    m_blockStart.assign(depths * m_alphabet, kNoBlock);
    for (int d = 1; d < int(depths); ++d) {
        for (size_t s = 0; s < m_alphabet; ++s) {
            std::uint64_t total = 0;
            for (auto i = m_table.starts[s]; i < m_table.starts[s + 1]; ++i) total = satAdd(total, len(m_table.symbols[i], d - 1));
            m_len[size_t(d) * m_alphabet + s] = total;
        }
    }
    // Blocks, shallow depths first, so every block is a concatenation of existing ones.
    for (int d = 1; d < int(depths); ++d) {
        for (size_t s = 0; s < m_alphabet; ++s) {
            std::uint64_t L = len(SymbolId(s), d);
            if (m_table.identities[s] || L > kBlock || m_pool.size() + L > kMaxPool) continue;
            std::uint32_t start = std::uint32_t(m_pool.size());
            bool complete = true;
            for (auto i = m_table.starts[s]; i < m_table.starts[s + 1] && complete; ++i) {
                SymbolId t = m_table.symbols[i];
                if (d - 1 == 0 || m_table.identities[t]) {
                    m_pool.push_back(t);
                    continue;
                }
                std::uint32_t b = m_blockStart[size_t(d - 1) * m_alphabet + t];
                if (b == kNoBlock) {
                    complete = false;
                    break;
                }
                std::uint64_t n = len(t, d - 1);
                m_pool.insert(m_pool.end(), m_pool.begin() + b, m_pool.begin() + b + std::ptrdiff_t(n));
            }
            if (complete) m_blockStart[size_t(d) * m_alphabet + s] = start;
            else m_pool.resize(start);
        }
    }
}

std::uint64_t D0LExpander::countAt(const ModuleString& axiom, int n) const {
    return countsUpTo(axiom, n).back();
}

std::vector<std::uint64_t> D0LExpander::countsUpTo(const ModuleString& axiom, int n) const {
    std::vector<std::uint64_t> counts(m_alphabet, 0), next(m_alphabet), totals;
    for (SymbolId s : axiom.symbols) counts[s] = satAdd(counts[s], 1);
    auto total = [&] {
        std::uint64_t t = 0;
        for (auto c : counts) t = satAdd(t, c);
        return t;
    };
    totals.push_back(total());
    for (int step = 0; step < n; ++step) {
        std::fill(next.begin(), next.end(), 0);
        bool changed = false;
        for (size_t s = 0; s < m_alphabet; ++s) {
            if (!counts[s]) continue;
            if (m_table.identities[s]) {
                next[s] = satAdd(next[s], counts[s]);
                continue;
            }
            changed = true;
            for (auto i = m_table.starts[s]; i < m_table.starts[s + 1]; ++i)
                next[m_table.symbols[i]] = satAdd(next[m_table.symbols[i]], counts[s]);
        }
        counts.swap(next);
        totals.push_back(total());
        if (!changed) {  // only identity symbols left: the string is final
            totals.resize(size_t(n) + 1, totals.back());
            break;
        }
    }
    return totals;
}

template <class Piece>
bool D0LExpander::forEachPiece(const ModuleString& axiom, int n, Piece&& piece) const {
    struct Frame {
        const SymbolId* cur;
        const SymbolId* end;
        int depth;
    };
    std::vector<Frame> stack;
    stack.push_back({axiom.symbols.begin(), axiom.symbols.end(), n});
    while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.cur == f.end) {
            stack.pop_back();
            continue;
        }
        const SymbolId* at = f.cur++;
        const SymbolId s = *at;
        const int d = f.depth;
        if (d == 0 || m_table.identities[s]) {
            if (!piece(at, 1)) return false;
            continue;
        }
        if (d <= kBlockDepth) {
            std::uint32_t b = m_blockStart[size_t(d) * m_alphabet + s];
            if (b != kNoBlock) {
                if (!piece(m_pool.data() + b, len(s, d))) return false;
                continue;
            }
        }
        stack.push_back({m_table.symbols.data() + m_table.starts[s], m_table.symbols.data() + m_table.starts[s + 1], d - 1});
    }
    return true;
}

bool D0LExpander::expand(const ModuleString& axiom, int n, ModuleString& out,
                         const std::atomic<bool>* cancel,
                         const std::function<void(double)>& progress) const {
    const std::uint64_t total = countAt(axiom, n);
    out.symbols.resizeUninitialized(total);
    out.params.clear();
    SymbolId* dst = out.symbols.data();
    SymbolId* const begin = dst;
    std::uint64_t nextCheck = 1u << 20;
    return forEachPiece(axiom, n, [&](const SymbolId* src, std::uint64_t L) {
        if (L == 1) {
            *dst++ = *src;
            return true;
        }
        if (L) std::memcpy(dst, src, L * sizeof(SymbolId));
        dst += L;
        if (std::uint64_t(dst - begin) >= nextCheck) {
            nextCheck += 1u << 20;
            if (cancel && cancel->load(std::memory_order_relaxed)) return false;
            if (progress && total) progress(double(dst - begin) / double(total));
        }
        return true;
    });
}

bool D0LExpander::matches(const ModuleString& axiom, int n, const ModuleString& s) const {
    if (!s.params.empty() || countAt(axiom, n) != s.size()) return false;
    const SymbolId* at = s.symbols.data();
    return forEachPiece(axiom, n, [&](const SymbolId* src, std::uint64_t L) {
        if (L == 1 ? *at != *src : L && std::memcmp(at, src, L * sizeof(SymbolId)) != 0) return false;
        at += L;
        return true;
    });
}

}  // namespace sprout
