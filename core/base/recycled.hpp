#pragma once
// Mid-size blocks (4 KB to 8 MB) kept when freed, for the next ones of their size: a
// derivation that keeps every step (L-Py's strings, lpy/engine/engine.hpp) allocates a few MB, and
// when a plant is dropped and the next one opened (a script's sweep, `import sprout` in a
// loop, an edit in the viewer), malloc had handed the heap back to the kernel in between and
// every page was faulted in and zeroed again: a third of a 100-step stochastic model's 5 ms.
// The blocks given back are kept while they total at most kKept; huge_pages.hpp does this
// for the big buffers, from 1 MB. Under AddressSanitizer nothing is kept (a use after free
// stays visible).
#include <cstddef>
#include <new>

namespace sprout::recycled {

constexpr std::size_t kSmallest = std::size_t(4) << 10;  // below: plain operator new
constexpr std::size_t kLargest = std::size_t(8) << 20;   // above: plain operator new
constexpr std::size_t kKept = std::size_t(64) << 20;     // the most given-back bytes kept

// Whether blocks are kept at all: not under AddressSanitizer.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kKeeps = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kKeeps = false;
#else
constexpr bool kKeeps = true;
#endif
#else
constexpr bool kKeeps = true;
#endif

// A block of at least `bytes` (a size class: at most a quarter more). Throws std::bad_alloc.
void* take(std::size_t bytes);
// Gives back a block that take(bytes) gave, with the same `bytes`.
void give(void* p, std::size_t bytes) noexcept;
// The bytes kept now (for tests).
std::size_t keptBytes();

// An allocator of such blocks, for a container whose buffers come and go by the megabyte.
template <class T>
struct Allocator {
    using value_type = T;
    Allocator() = default;
    template <class U>
    Allocator(const Allocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(take(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { give(p, n * sizeof(T)); }
    template <class U>
    bool operator==(const Allocator<U>&) const noexcept {
        return true;
    }
};

}  // namespace sprout::recycled
