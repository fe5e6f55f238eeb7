// SdCardTiming: transfer time from a rate, periodic stalls, and a failure point.
#include "models/sd_card.hpp"

namespace stepdance::sim {
namespace {

SimTime transfer_time(size_t bytes, double kb_per_s) {
  if (kb_per_s <= 0) return 0;
  return static_cast<SimTime>(static_cast<double>(bytes) / (kb_per_s * 1000.0) * 1e9 + 0.5);
}

}  // namespace

SdCardTiming::Write SdCardTiming::write(size_t bytes) {
  Write outcome;
  if (settings_.fail_after_bytes != 0 && written_ + bytes > settings_.fail_after_bytes) {
    outcome.fails = true;
    return outcome;
  }
  outcome.duration = transfer_time(bytes, settings_.write_kb_per_s);
  if (settings_.stall_every_kb > 0 && settings_.stall > 0) {
    const auto every = static_cast<uint64_t>(settings_.stall_every_kb * 1000.0);
    const uint64_t stalls_before = every == 0 ? 0 : written_ / every;
    const uint64_t stalls_after = every == 0 ? 0 : (written_ + bytes) / every;
    outcome.duration += static_cast<SimTime>(stalls_after - stalls_before) * settings_.stall;
    stalls_ += stalls_after - stalls_before;
  }
  written_ += bytes;
  return outcome;
}

SimTime SdCardTiming::read(size_t bytes) const { return transfer_time(bytes, settings_.read_kb_per_s); }

}  // namespace stepdance::sim
