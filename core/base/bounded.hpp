#pragma once
// Numbers from a grammar (written, or computed by its expressions and its turtle) become
// integers in many places: grid cells, indices, counts, sizes. A C++ cast of a double that is
// NaN, infinite or out of the integer type's range is undefined behaviour (a fuzz find: a point
// 1e37 away cast to a cell index). Every such conversion goes through one of these:
//
//   saturate<Int>(v)        defined for every double: NaN -> 0, below / above the type's range
//                           -> its lowest / highest value, otherwise the cast (toward zero).
//                           For places where clamping is the meaning (a point far beyond every
//                           cell lies in the last one).
//   floorCell<Int>(v)       saturate(floor(v)): the unit cell of v, for grid keys.
//   wholeIn(v, lo, hi)      a count, index or size the user wrote: the whole number v when it
//                           is finite, whole and in [lo, hi], else nothing (the caller says so
//                           at the number's line and column, naming the range).
//   inRange(v, lo, hi)      finite and in [lo, hi] (NaN and infinities are not).
//   toFloat(v)              double -> float, beyond float's range -> +-FLT_MAX (a cast of a
//                           double out of float's range is undefined too); NaN stays NaN.
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

namespace sprout {

template <std::integral Int>
constexpr Int saturate(double v) noexcept {
    using L = std::numeric_limits<Int>;
    if (v != v) return 0;
    // double(L::max()) rounds up to a power of two for 64-bit types: any v below it casts.
    if (v >= double(L::max())) return L::max();
    if (v <= double(L::min())) return L::min();
    return static_cast<Int>(v);
}

template <std::integral Int>
inline Int floorCell(double v) noexcept {
    return saturate<Int>(std::floor(v));
}

constexpr float toFloat(double v) noexcept {
    constexpr double hi = std::numeric_limits<float>::max();
    return v > hi ? float(hi) : v < -hi ? -float(hi) : static_cast<float>(v);
}

constexpr bool inRange(double v, double lo, double hi) noexcept { return v >= lo && v <= hi; }

inline std::optional<long long> wholeIn(double v, long long lo, long long hi) noexcept {
    if (!(v >= double(lo) && v <= double(hi)) || v != std::floor(v)) return std::nullopt;
    return static_cast<long long>(v);
}

// A number as messages show it ("%g": 1e+09, 0.5, nan).
inline std::string formatNumber(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

}  // namespace sprout
