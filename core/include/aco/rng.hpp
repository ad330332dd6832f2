#pragma once
// Small, fast, platform-independent random numbers. std:: distributions are not used because
// their output differs between standard libraries; results must be reproducible everywhere.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace aco {

constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// xoshiro256** (Blackman and Vigna).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    for (auto& word : s_) word = seed = splitmix64(seed);
  }
  // An independent stream for a (seed, a, b) triple, e.g. (run seed, iteration, ant): the same
  // triple gives the same numbers whichever thread draws them.
  static Rng stream(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0) {
    return Rng(splitmix64(splitmix64(splitmix64(seed) ^ a) ^ (b + 0x632BE59BD9B4E019ULL)));
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform integer in [0, n), n > 0.
  std::uint64_t below(std::uint64_t n) {
    __extension__ using wide = unsigned __int128;  // Lemire's multiply-shift: no modulo bias worth the name
    return static_cast<std::uint64_t>((static_cast<wide>(next()) * n) >> 64);
  }
  // Standard normal (Box-Muller; one value per call keeps the stream simple to reason about).
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

// Roulette-wheel selection: index i with probability weights[i] / total, total being their sum
// (> 0). Never an index of weight <= 0: rounding that leaves the draw just above 0 at the end
// picks the last positive one. One draw from `rng`.
inline std::size_t roulette(Rng& rng, std::span<const double> weights, double total) {
  double r = rng.uniform() * total;
  std::size_t last_positive = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] <= 0.0) continue;
    if ((r -= weights[i]) < 0.0) return i;
    last_positive = i;
  }
  return last_positive;
}

}  // namespace aco
