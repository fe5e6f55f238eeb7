// Deterministic pseudo-random numbers (SplitMix64) for bounce patterns and other seeded effects.
#pragma once

#include <cstdint>

namespace stepdance::sim {

/// A small, fast, fully deterministic generator: the same seed always gives the same sequence.
class RandomStream {
 public:
  explicit RandomStream(uint64_t seed) : state_(seed) {}

  /// The next 64 random bits.
  uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// A value in [0, bound). Precondition: bound > 0.
  uint64_t below(uint64_t bound) { return next() % bound; }

 private:
  uint64_t state_;
};

/// Mixes two values into one seed, so that independent streams can be derived from one scenario seed.
inline uint64_t mix_seed(uint64_t seed, uint64_t salt) {
  RandomStream stream(seed ^ (salt * 0xD6E8FEB86659FD93ull));
  return stream.next();
}

}  // namespace stepdance::sim
