#pragma once
// Random streams. Every random draw in esc comes from an Rng whose seed is derived from
// the master seed and the coordinates of the work that uses it (run, generation,
// individual, epoch, purpose). Work scheduled on any thread or rank therefore sees the
// same numbers, which is what makes results independent of the thread count.
//
// The generator is xoshiro256++ and the distributions are written out here rather than
// taken from <random>: the standard specifies the engines' output but not the
// distributions', so std::normal_distribution may differ between library versions.
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>

namespace esc {

// SplitMix64 finaliser: a bijective mixer with good avalanche, used to derive seeds.
[[nodiscard]] constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30U)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27U)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31U);
}

// Seed of the stream at `path` under `seed`; the order of the coordinates matters.
[[nodiscard]] constexpr std::uint64_t derive_seed(std::uint64_t seed,
                                                  std::initializer_list<std::uint64_t> path) noexcept {
  std::uint64_t h = mix64(seed);
  for (std::uint64_t c : path) h = mix64(h ^ mix64(c + 0x632be59bd9b4e019ULL));
  return h;
}

// Purposes of streams, so two uses of the same coordinates never share numbers.
enum class Stream : std::uint64_t {
  Init = 1,         // initial population of a run
  Breed = 2,        // recombination and mutation of one generation
  Evaluate = 3,     // start poses and sensor noise of one evaluation
  RunSeed = 4,      // per-run seed derived from the master seed
};

class Rng {
 public:
  explicit constexpr Rng(std::uint64_t seed) noexcept {
    for (auto& w : s_) w = seed = mix64(seed);
  }
  Rng(std::uint64_t seed, std::initializer_list<std::uint64_t> path) noexcept
      : Rng(derive_seed(seed, path)) {}

  constexpr std::uint64_t next() noexcept {
    const std::uint64_t result = rotl(s_[0] + s_[3], 23) + s_[0];
    const std::uint64_t t = s_[1] << 17U;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  // Uniform in [0, 1) with 53 random bits.
  constexpr double uniform() noexcept { return static_cast<double>(next() >> 11U) * 0x1.0p-53; }
  constexpr double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }

  // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift, bias below 2^-64 * n).
  constexpr std::uint64_t below(std::uint64_t n) noexcept {
    __extension__ using u128 = unsigned __int128;   // GCC/Clang extension, 128-bit product
    return static_cast<std::uint64_t>((static_cast<u128>(next()) * n) >> 64U);
  }

  // Standard normal by the Box-Muller transform (both values used).
  double normal() noexcept {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u1 = 0.0;
    do { u1 = uniform(); } while (u1 <= 0.0);
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double a = 2.0 * std::numbers::pi * u2;
    spare_ = r * std::sin(a);
    has_spare_ = true;
    return r * std::cos(a);
  }
  double normal(double mean, double sd) noexcept { return mean + sd * normal(); }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) noexcept {
    return (x << k) | (x >> (64 - k));
  }
  std::array<std::uint64_t, 4> s_{};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace esc
