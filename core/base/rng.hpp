#pragma once
// Sprout's own random numbers: the same seed gives the same plant with every compiler and
// standard library (std::*_distribution output is implementation-defined).
#include <cmath>
#include <cstdint>

namespace sprout {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 0) : m_state(seed) {}

    // An independent stream for (seed, stream), e.g. one per derivation step.
    static Rng forStream(std::uint64_t seed, std::uint64_t stream) {
        Rng r(seed ^ (stream * 0xD1B54A32D192ED03ull));
        r.next();
        return r;
    }

    // SplitMix64 (Steele, Lea, Flood 2014): passes BigCrush, one add and three multiplies.
    std::uint64_t next() {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    // Box-Muller; one draw per call so the stream position never depends on earlier calls.
    double normal(double mean, double sigma) {
        double u1 = 1.0 - uniform();  // (0, 1]
        double u2 = uniform();
        return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

private:
    std::uint64_t m_state;
};

}  // namespace sprout
