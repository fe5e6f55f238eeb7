// How long a simulated SD card takes for each transfer, and when it fails.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A card's speed and faults. The defaults are an ideal card: instant, never failing.
struct SdCardSettings {
  /// Sustained write and read rates, kB/s (1 kB = 1000 bytes); 0 = instant.
  double write_kb_per_s = 0;
  double read_kb_per_s = 0;
  /// Every `stall_every_kb` kB written, one write also waits `stall` (a block erase or
  /// wear-levelling pause, the SD card's worst case); 0 = never.
  double stall_every_kb = 0;
  SimTime stall = 0;
  /// Writes beyond this many bytes fail (a full or dying card); 0 = never.
  uint64_t fail_after_bytes = 0;
};

/// The time each transfer takes on a card with these settings. Pure: the board sleeps its loop
/// for the time returned (the frame keeps running meanwhile, as on the Teensy).
class SdCardTiming {
 public:
  explicit SdCardTiming(const SdCardSettings& settings = {}) : settings_(settings) {}

  /// Outcome of one write of `bytes`: the time it takes, or that it fails (and writes nothing).
  struct Write {
    SimTime duration = 0;
    bool fails = false;
  };
  Write write(size_t bytes);
  /// Time one read of `bytes` takes.
  SimTime read(size_t bytes) const;

  /// Bytes written so far and stalls taken.
  uint64_t bytes_written() const { return written_; }
  uint64_t stalls() const { return stalls_; }

 private:
  SdCardSettings settings_;
  uint64_t written_ = 0;
  uint64_t stalls_ = 0;
};

}  // namespace stepdance::sim
