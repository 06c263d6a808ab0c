#include "core/base/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <mutex>
#include <new>
#include <vector>

namespace sprout::huge_pages {
namespace {

struct Kept {
    void* p;
    std::size_t bytes;
};

std::mutex g_lock;
std::vector<Kept>* g_kept = nullptr;  // oldest first; never destroyed (buffers outlive statics)
std::size_t g_keptBytes = 0;

void* mapNew(std::size_t size) {
    void* raw = mmap(nullptr, size + kPage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    char* base = static_cast<char*>(raw);
    char* aligned = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(base) + kPage - 1) & ~(kPage - 1));
    if (aligned > base) munmap(base, std::size_t(aligned - base));
    char* end = aligned + size;
    char* rawEnd = base + size + kPage;
    if (rawEnd > end) munmap(end, std::size_t(rawEnd - end));
    madvise(aligned, size, MADV_HUGEPAGE);
    return aligned;
}

}  // namespace

void* takeKept(std::size_t bytes, std::size_t& got) {
    const std::size_t want = roundUp(bytes ? bytes : 1);
    std::lock_guard<std::mutex> lock(g_lock);
    if (!g_kept) return nullptr;
    // The smallest kept mapping that holds it, and not one far bigger than asked for.
    std::size_t best = g_kept->size();
    for (std::size_t k = 0; k < g_kept->size(); ++k) {
        const std::size_t b = (*g_kept)[k].bytes;
        if (b >= want && b <= 4 * want && (best == g_kept->size() || b < (*g_kept)[best].bytes)) best = k;
    }
    if (best == g_kept->size()) return nullptr;
    const Kept k = (*g_kept)[best];
    g_kept->erase(g_kept->begin() + std::ptrdiff_t(best));
    g_keptBytes -= k.bytes;
    got = k.bytes;
    return k.p;
}

void* take(std::size_t bytes, std::size_t& got) {
    if (void* p = takeKept(bytes, got)) return p;
    got = roundUp(bytes ? bytes : 1);
    return mapNew(got);
}

void give(void* p, std::size_t bytes) {
    if (!p || !bytes) return;
    if (bytes > kKept) {
        munmap(p, bytes);
        return;
    }
    std::vector<Kept> drop;
    {
        std::lock_guard<std::mutex> lock(g_lock);
        if (!g_kept) g_kept = new std::vector<Kept>();
        while (g_keptBytes + bytes > kKept && !g_kept->empty()) {
            drop.push_back(g_kept->front());
            g_keptBytes -= g_kept->front().bytes;
            g_kept->erase(g_kept->begin());
        }
        g_kept->push_back({p, bytes});
        g_keptBytes += bytes;
    }
    for (const Kept& k : drop) munmap(k.p, k.bytes);
}

}  // namespace sprout::huge_pages
