// The VCD's size told before a run: long runs could fill a disk unasked (issue 38: a day's run
// would have written about 2.6 GB).
#pragma once

#include <stdint.h>

#include <cstddef>
#include <string>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// The most a recorded port can add to a VCD per simulated second at the default 25 kHz frame
/// rate: a STEP pulse (two edges) and a DIR change every frame, each edge on its own timestamp
/// line ("#" and 14 digits of ns, newline: 16 bytes) and value line (3 bytes): 25,000 × 3 × 19.
constexpr double kVcdBytesPerPortSecond = 25000.0 * 3 * 19;
/// The default cap on that estimate (SimulationOptions::vcd_max_bytes): 1 GB.
constexpr uint64_t kDefaultVcdMaxBytes = 1000ull * 1000 * 1000;

/// The estimate for `ports` recorded ports over `duration`, in bytes. Context: any.
double estimate_vcd_bytes(size_t ports, SimTime duration);

/// "" when the estimate is within `max_bytes`; else the refusal: the estimate, how it was made,
/// and the options that raise the cap or skip the VCD. Context: any.
std::string vcd_size_problem(const std::string& path, size_t ports, SimTime duration, uint64_t max_bytes);

}  // namespace stepdance::sim
