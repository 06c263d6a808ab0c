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

    // cpfg's random numbers (the Algorithmic Botany lab's cpfg, utility.c and control.c): the
    // 48-bit generator of drand48, one stream for choosing among stochastic productions
    // (seed48 of {seed, 0, 155}; seed 0: glibc's zero state, where cpfg -g starts)
    // and one for the expressions' ran/nran/bran/biran (cpfg's main_xsubi, {0x330E, 0, 0},
    // which srand(a) sets to {0x330E, a, a >> 16}); the same draws give cpfg's string.
    static Rng cpfg(std::int64_t seed) {
        Rng r;
        r.m_cpfg = true;
        r.m_state = seed != 0 ? (std::uint64_t(155) << 32) | (std::uint64_t(seed) & 0xFFFF) : 0;
        r.m_expr = 0x330E;
        return r;
    }
    bool isCpfg() const { return m_cpfg; }

    // SplitMix64 (Steele, Lea, Flood 2014): passes BigCrush, one add and three multiplies.
    std::uint64_t next() {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1) with 53 random bits (cpfg: drand48's 48).
    double uniform() {
        if (m_cpfg) return lcg48(m_state);
        return double(next() >> 11) * 0x1.0p-53;
    }
    // The expressions' draws: uniform(), or cpfg's second stream.
    double exprUniform() { return m_cpfg ? lcg48(m_expr) : uniform(); }
    double exprNormal(double mean, double sigma) {
        if (!m_cpfg) return normal(mean, sigma);
        // cpfg's nrand (Numerical Recipes' polar method, keeping the second value; its flag
        // starts at 10, so the first draw before any srand() is the mean itself).
        if (m_iset != 0) {
            m_iset = 0;
            return m_gset * sigma + mean;
        }
        double v1, v2, rsq;
        do {
            v1 = 2.0 * exprUniform() - 1.0;
            v2 = 2.0 * exprUniform() - 1.0;
            rsq = v1 * v1 + v2 * v2;
        } while (rsq >= 1.0 || rsq == 0.0);
        const double fac = std::sqrt(-2.0 * std::log(rsq) / rsq);
        m_gset = v1 * fac;
        m_iset = 1;
        return v2 * fac * sigma + mean;
    }
    // The expressions' srand(a).
    void exprSeed(std::int64_t a) {
        if (!m_cpfg) {
            *this = Rng(std::uint64_t(a));
            return;
        }
        m_expr = 0x330E | ((std::uint64_t(a) & 0xFFFF) << 16) | (((std::uint64_t(a) >> 16) & 0xFFFF) << 32);
        m_iset = 0;
    }
    // Box-Muller; one draw per call so the stream position never depends on earlier calls.
    double normal(double mean, double sigma) {
        double u1 = 1.0 - uniform();  // (0, 1]
        double u2 = uniform();
        return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

private:
    static double lcg48(std::uint64_t& x) {
        x = (0x5DEECE66Dull * x + 0xB) & 0xFFFFFFFFFFFFull;
        return double(x) * 0x1.0p-48;
    }

    std::uint64_t m_state;
    bool m_cpfg = false;
    int m_iset = 10;
    double m_gset = 0;
    std::uint64_t m_expr = 0;
};

}  // namespace sprout
