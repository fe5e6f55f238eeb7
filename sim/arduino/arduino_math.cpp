// Arduino's random(): a small deterministic generator, so simulations repeat exactly.
#include "arduino_math.h"

#include "arduino_state.hpp"

namespace {

constexpr unsigned long kPowerOnSeed = 1;
uint64_t state = kPowerOnSeed;

// splitmix64: a 64-bit counter stepped by an odd constant, then mixed.
uint64_t next_random() {
  state += 0x9E3779B97F4A7C15ull;
  uint64_t mixed = state;
  mixed = (mixed ^ (mixed >> 30)) * 0xBF58476D1CE4E5B9ull;
  mixed = (mixed ^ (mixed >> 27)) * 0x94D049BB133111EBull;
  return mixed ^ (mixed >> 31);
}

}  // namespace

namespace stepdance::arduino::internal {
void reset_random_state() { randomSeed(kPowerOnSeed); }
}  // namespace stepdance::arduino::internal

void randomSeed(unsigned long seed) { state = seed; }

long random(long howbig) {
  if (howbig <= 0) return 0;
  return static_cast<long>(next_random() % static_cast<uint64_t>(howbig));
}

long random(long howsmall, long howbig) {
  if (howsmall >= howbig) return howsmall;
  const uint64_t span = static_cast<uint64_t>(howbig) - static_cast<uint64_t>(howsmall);
  return static_cast<long>(static_cast<uint64_t>(howsmall) + next_random() % span);
}
