#pragma once
// A growable array of trivially copyable values that does not zero what it allocates.
// std::vector::resize writes every element once before the derivation writes it again;
// on a 6 M-module string that first pass costs as much as the derivation step itself.
//
// Big buffers are mapped with transparent huge pages: a 33 M-module parametric step writes
// 130 MB of fresh memory, and with 4 KB pages the kernel's page faults took more time than
// the derivation (measured: 184 ms of system time in a 330 ms run).
#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>

#include "core/base/huge_pages.hpp"

namespace sprout {

// `HugeFrom`: the size in bytes from which a buffer is mapped with huge pages.
template <class T, size_t HugeFrom = (8u << 20)>
class PodBuffer {
    static_assert(std::is_trivially_copyable_v<T>);

public:
    PodBuffer() = default;
    PodBuffer(const T* data, size_t n) { append(data, n); }
    PodBuffer(const PodBuffer& o) { append(o.m_data, o.m_size); }
    PodBuffer(PodBuffer&& o) noexcept
        : m_data(std::exchange(o.m_data, nullptr)),
          m_size(std::exchange(o.m_size, 0)),
          m_capacity(std::exchange(o.m_capacity, 0)),
          m_mapped(std::exchange(o.m_mapped, false)) {}
    PodBuffer& operator=(PodBuffer o) noexcept {
        swap(o);
        return *this;
    }
    ~PodBuffer() { release(); }

    void swap(PodBuffer& o) noexcept {
        std::swap(m_data, o.m_data);
        std::swap(m_size, o.m_size);
        std::swap(m_capacity, o.m_capacity);
        std::swap(m_mapped, o.m_mapped);
    }

    T* data() { return m_data; }
    const T* data() const { return m_data; }
    size_t size() const { return m_size; }
    size_t capacity() const { return m_capacity; }
    bool empty() const { return m_size == 0; }
    T& operator[](size_t i) { return m_data[i]; }
    const T& operator[](size_t i) const { return m_data[i]; }
    const T* begin() const { return m_data; }
    const T* end() const { return m_data + m_size; }
    T* begin() { return m_data; }
    T* end() { return m_data + m_size; }

    // Capacity for at least n elements; the new tail is left uninitialised.
    void reserve(size_t n) {
        if (n <= m_capacity) return;
        const size_t bytes = n * sizeof(T);
        if (bytes < kHugeThreshold && !m_mapped) {
            // Nothing to keep (a derivation step's string, cleared): not realloc, which copies
            // the whole old allocation, whatever size says.
            if (m_size == 0 && m_data) {
                std::free(m_data);
                m_data = nullptr;
                m_capacity = 0;
            }
            void* p = std::realloc(m_data, bytes);
            if (!p) throw std::bad_alloc();
            m_data = static_cast<T*>(p);
            m_capacity = n;
            return;
        }
        growMapped(bytes);
    }
    // Size n; elements past the old size are uninitialised.
    void resizeUninitialized(size_t n) {
        reserve(n);
        m_size = n;
    }
    void clear() { m_size = 0; }
    void pop_back() { --m_size; }
    T& back() { return m_data[m_size - 1]; }
    const T& back() const { return m_data[m_size - 1]; }
    const T& front() const { return m_data[0]; }
    void push_back(const T& v) {
        if (m_size == m_capacity) reserve(m_capacity ? m_capacity * 2 : 16);
        m_data[m_size++] = v;
    }
    void append(const T* src, size_t n) {
        if (n == 0) return;
        if (m_size + n > m_capacity) reserve(std::max(m_size + n, m_capacity * 2));
        std::memcpy(m_data + m_size, src, n * sizeof(T));
        m_size += n;
    }
    // Gives back unused capacity (after a derivation step sized by an upper bound).
    void shrinkToFit() {
        if (m_capacity == m_size) return;
        if (m_mapped) {
            size_t keep = roundUp(std::max<size_t>(m_size * sizeof(T), 1));
            size_t have = roundUp(m_capacity * sizeof(T));
            if (keep < have) munmap(reinterpret_cast<char*>(m_data) + keep, have - keep);
            m_capacity = keep / sizeof(T);
            return;
        }
        if (m_size == 0) {
            release();
            return;
        }
        if (void* p = std::realloc(m_data, m_size * sizeof(T))) {
            m_data = static_cast<T*>(p);
            m_capacity = m_size;
        }
    }
    bool operator==(const PodBuffer& o) const {
        return m_size == o.m_size && (m_size == 0 || std::memcmp(m_data, o.m_data, m_size * sizeof(T)) == 0);
    }

private:
    static constexpr size_t kHugeThreshold = HugeFrom;
    static size_t roundUp(size_t bytes) { return huge_pages::roundUp(bytes); }

    // Out of the callers' loops (a derivation step's): rare, and big.
    [[gnu::noinline]] void growMapped(size_t bytes) {
        size_t got = 0;
        if (m_mapped && m_size == 0) {
            // Nothing to keep: a kept mapping that holds it (its pages in) rather than this one
            // grown (its new pages cleared by the kernel on first touch).
            if (void* kept = huge_pages::takeKept(bytes, got)) {
                release();
                m_data = static_cast<T*>(kept);
                m_mapped = true;
                m_capacity = got / sizeof(T);
                return;
            }
        }
        if (m_mapped) {
            // Grown by moving the pages, not copying them: a copy would hold the old and the
            // new buffer at once (the turtle's 390 MB of segments for a 9.8 M-segment curve
            // peaked at 700 MB while its buffer doubled).
            const size_t have = roundUp(m_capacity * sizeof(T)), want = roundUp(bytes);
            void* moved = mremap(m_data, have, want, MREMAP_MAYMOVE);
            if (moved != MAP_FAILED) {
                madvise(moved, want, MADV_HUGEPAGE);
                m_data = static_cast<T*>(moved);
                m_capacity = want / sizeof(T);
                return;
            }
        }
        T* p = static_cast<T*>(huge_pages::take(bytes, got));
        const size_t size = m_size;
        if (size) std::memcpy(p, m_data, size * sizeof(T));
        release();
        m_size = size;
        m_data = p;
        m_mapped = true;
        m_capacity = got / sizeof(T);
    }
    void release() {
        if (m_mapped) huge_pages::give(m_data, roundUp(m_capacity * sizeof(T)));
        else std::free(m_data);
        m_data = nullptr;
        m_capacity = m_size = 0;
        m_mapped = false;
    }

    T* m_data = nullptr;
    size_t m_size = 0;
    size_t m_capacity = 0;
    bool m_mapped = false;
};

}  // namespace sprout
