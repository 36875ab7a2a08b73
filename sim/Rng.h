#pragma once

#include <array>
#include <cstdint>

namespace pf {

// xoshiro256** (Blackman & Vigna). Chosen over std::mt19937_64 because its whole
// state is four words: trivial to save in a sheet file and to compare in tests,
// and its output is identical on every platform and standard library.
class Rng {
  public:
    using State = std::array<std::uint64_t, 4>;

    explicit Rng(std::uint64_t seed = 1) { reseed(seed); }

    void reseed(std::uint64_t seed);
    std::uint64_t next();
    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

    const State& state() const { return s_; }
    // Returns false (and keeps the old state) for the all-zero state, which is a fixed point.
    bool setState(const State& s);

  private:
    State s_{};
};

} // namespace pf
