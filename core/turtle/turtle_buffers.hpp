#pragma once
// Where the turtle writes before the Geometry holds it: the segment writer that streams
// instances past the caches, and the tree turtle's per-thread workspace of blocks. Apart
// from the Turtle class (turtle_class.hpp) because they are plain buffers with no turtle
// in them.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <deque>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/turtle/turtle.hpp"
#include "core/turtle/turtle_state.hpp"

namespace sprout::turtle_impl {

// Segments go through a small staging buffer that is flushed with non-temporal stores: the
// 40-byte instances of a big plant are far more than the caches hold, and plain stores would
// first read every destination line (measured: 63 MB of instances for the fractal plant n=10).
class SegmentWriter {
public:
    // `stream`: non-temporal stores, for output that is not read again soon.
    explicit SegmentWriter(PodBuffer<CylinderInstance>& out, bool stream = true) : m_out(out), m_stream(stream) {}
    ~SegmentWriter() { flush(); }
    CylinderInstance& next() {
        if (m_staged == kStage) flush();
        return m_stage[m_staged++];
    }
    std::size_t count() const { return m_out.size() + m_staged; }
    CylinderInstance& at(std::size_t i) { return i >= m_out.size() ? m_stage[i - m_out.size()] : m_out[i]; }
    void flush() {
        if (!m_staged) return;
        const std::size_t size = m_out.size();
        if (size + m_staged > m_out.capacity()) m_out.reserve(std::max<std::size_t>(2 * m_out.capacity(), size + kStage * 64));
        m_out.resizeUninitialized(size + m_staged);
        char* dst = reinterpret_cast<char*>(m_out.data() + size);
        const char* src = reinterpret_cast<const char*>(m_stage);
        const std::size_t bytes = m_staged * sizeof(CylinderInstance);
#if defined(__SSE2__)
        if (m_stream && (reinterpret_cast<std::uintptr_t>(dst) & 15) == 0 && bytes % 16 == 0) {
            for (std::size_t o = 0; o < bytes; o += 16)
                _mm_stream_si128(reinterpret_cast<__m128i*>(dst + o), _mm_load_si128(reinterpret_cast<const __m128i*>(src + o)));
        } else {
            std::memcpy(dst, src, bytes);
        }
#else
        std::memcpy(dst, src, bytes);
#endif
        m_staged = 0;
    }
    void finish() {
        flush();
#if defined(__SSE2__)
        _mm_sfence();
#endif
    }

private:
    static constexpr std::size_t kStage = 128;  // 5 KB: 128 x 40 bytes, a multiple of 16
    PodBuffer<CylinderInstance>& m_out;
    bool m_stream;
    alignas(16) CylinderInstance m_stage[kStage];
    std::size_t m_staged = 0;
};

// What drawing from the derivation tree works in: blocks being built (on the heap: builds
// nest as deep as the derivation, and a writer holds 5 KB) and the blocks made. Kept per
// thread between interpretations: fresh buffers each time cost more in page faults (the
// kernel zeroing new pages) than placing the blocks.
struct TreeScratch {
    PodBuffer<CylinderInstance> segments;
    PodBuffer<SurfaceInstance> surfaces;
    std::vector<v4> points;
    SegmentWriter writer{segments, false};
};
struct TreeWorkspace {
    PodBuffer<CylinderInstance> blockSegments;
    PodBuffer<SurfaceInstance> blockSurfaces;
    std::vector<v4> blockPoints;
    std::deque<TreeScratch> scratch;  // one per block being built, nested (stable addresses)
    void clear() {
        blockSegments.clear();
        blockSurfaces.clear();
        blockPoints.clear();
    }
    // A pathological grammar's 80 MB is not kept for the rest of the thread's life.
    void trim() {
        if (blockSegments.capacity() > (4u << 20) / sizeof(CylinderInstance)) *this = TreeWorkspace{};
    }
};
inline TreeWorkspace& treeWorkspace() {
    thread_local TreeWorkspace w;
    return w;
}

}  // namespace sprout::turtle_impl
