#pragma once
// Big buffers' memory (PodBuffer): 2 MB-aligned private mappings advised for transparent huge
// pages, and a few of them kept when given back. A derivation writes each step into fresh
// memory, and the kernel zeroes every page of it on first touch: a re-derivation (an edit, a
// slider) that takes back the mappings of the last one skips that (measured on L-Py's native
// path: a third of an 18-step derivation was the kernel clearing pages).
#include <cstddef>

namespace sprout::huge_pages {

constexpr std::size_t kPage = std::size_t(2) << 20;
constexpr std::size_t kKept = std::size_t(64) << 20;  // the most given-back bytes kept mapped

inline std::size_t roundUp(std::size_t bytes) { return (bytes + kPage - 1) & ~(kPage - 1); }

// A mapping of at least `bytes`; `got` says how big (a multiple of kPage). Throws
// std::bad_alloc when there is no memory.
void* take(std::size_t bytes, std::size_t& got);
// A kept mapping of at least `bytes` (the smallest, at most 4 times as big), or null.
void* takeKept(std::size_t bytes, std::size_t& got);
// Gives back a mapping of `bytes` (a multiple of kPage) from take(), or its remains after
// munmap of its tail or mremap: kept for a later take() while the kept ones fit in kKept.
void give(void* p, std::size_t bytes);

}  // namespace sprout::huge_pages
