#pragma once

#include <cstdint>

namespace fooball {

/// SplitMix64 (Steele, Lea & Flood 2014): a small, fast generator whose output is defined by
/// 64-bit integer arithmetic alone, and with it every number drawn here, so a seed gives the same
/// balls on every platform (std::uniform_real_distribution may differ between libraries).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, 1): the top 53 bits as a double's mantissa.
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }

  /// Uniform in [low, high).
  double between(double low, double high) { return low + (high - low) * unit(); }

  /// Uniform in [0, n), n > 0; the modulo bias is below n / 2^64, far under anything a scene
  /// can show.
  std::uint64_t below(std::uint64_t n) { return next() % n; }

 private:
  std::uint64_t state_;
};

}  // namespace fooball
