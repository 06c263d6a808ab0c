#pragma once
// A growable array of trivially copyable values that does not zero what it allocates.
// std::vector::resize writes every element once before the derivation writes it again;
// on a 6 M-module string that first pass costs as much as the derivation step itself.
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace sprout {

template <class T>
class PodBuffer {
    static_assert(std::is_trivially_copyable_v<T>);

public:
    PodBuffer() = default;
    PodBuffer(const T* data, size_t n) { append(data, n); }
    PodBuffer(const PodBuffer& o) { append(o.m_data, o.m_size); }
    PodBuffer(PodBuffer&& o) noexcept
        : m_data(std::exchange(o.m_data, nullptr)),
          m_size(std::exchange(o.m_size, 0)),
          m_capacity(std::exchange(o.m_capacity, 0)) {}
    PodBuffer& operator=(PodBuffer o) noexcept {
        swap(o);
        return *this;
    }
    ~PodBuffer() { std::free(m_data); }

    void swap(PodBuffer& o) noexcept {
        std::swap(m_data, o.m_data);
        std::swap(m_size, o.m_size);
        std::swap(m_capacity, o.m_capacity);
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

    // Capacity for at least n elements; the new tail is left uninitialised.
    void reserve(size_t n) {
        if (n <= m_capacity) return;
        void* p = std::realloc(m_data, n * sizeof(T));
        if (!p) throw std::bad_alloc();
        m_data = static_cast<T*>(p);
        m_capacity = n;
    }
    // Size n; elements past the old size are uninitialised.
    void resizeUninitialized(size_t n) {
        reserve(n);
        m_size = n;
    }
    void clear() { m_size = 0; }
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
        if (m_size == 0) {
            std::free(m_data);
            m_data = nullptr;
            m_capacity = 0;
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
    T* m_data = nullptr;
    size_t m_size = 0;
    size_t m_capacity = 0;
};

}  // namespace sprout
