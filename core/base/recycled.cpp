#include "core/base/recycled.hpp"

#include <bit>
#include <cstdint>
#include <mutex>
#include <vector>

namespace sprout::recycled {
namespace {

// Size classes: 4 a power of two (2^k, 1.25, 1.5 and 1.75 times it), from kSmallest.
constexpr int kFirstPower = 12;  // log2(kSmallest)
constexpr int kClasses = 4 * (23 - kFirstPower) + 1;  // to kLargest = 2^23

int classOf(std::size_t bytes) {
    if (bytes <= kSmallest) return 0;
    const int power = int(std::bit_width(bytes - 1)) - 1;  // 2^power < bytes <= 2^(power+1)
    const std::size_t base = std::size_t(1) << power, quarter = base >> 2;
    const int steps = int((bytes - base + quarter - 1) / quarter);  // 1..4 quarters above 2^power
    return 4 * (power - kFirstPower) + steps;
}

std::size_t sizeOf(int cls) {
    if (cls == 0) return kSmallest;
    const int power = kFirstPower + (cls - 1) / 4, steps = (cls - 1) % 4 + 1;
    const std::size_t base = std::size_t(1) << power;
    return base + std::size_t(steps) * (base >> 2);
}

struct Cache {
    std::mutex lock;
    std::vector<void*> free[kClasses];
    std::size_t bytes = 0;
};
// Never destroyed: strings held by statics are freed after static destructors ran.
Cache& cache() {
    static Cache* c = new Cache();
    return *c;
}

bool kept(std::size_t bytes) { return kKeeps && bytes >= kSmallest && bytes <= kLargest; }

}  // namespace

void* take(std::size_t bytes) {
    if (!kept(bytes)) return ::operator new(bytes);
    const int cls = classOf(bytes);
    Cache& c = cache();
    {
        std::lock_guard<std::mutex> lock(c.lock);
        if (!c.free[cls].empty()) {
            void* p = c.free[cls].back();
            c.free[cls].pop_back();
            c.bytes -= sizeOf(cls);
            return p;
        }
    }
    return ::operator new(sizeOf(cls));
}

void give(void* p, std::size_t bytes) noexcept {
    if (!p) return;
    if (!kept(bytes)) {
        ::operator delete(p);
        return;
    }
    const int cls = classOf(bytes);
    const std::size_t size = sizeOf(cls);
    Cache& c = cache();
    {
        std::lock_guard<std::mutex> lock(c.lock);
        if (c.bytes + size <= kKept) {
            try {
                c.free[cls].push_back(p);
                c.bytes += size;
                return;
            } catch (...) {  // no memory for the list: the block goes
            }
        }
    }
    ::operator delete(p);
}

std::size_t keptBytes() {
    Cache& c = cache();
    std::lock_guard<std::mutex> lock(c.lock);
    return c.bytes;
}

}  // namespace sprout::recycled
