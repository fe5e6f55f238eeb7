// libFuzzer target: arbitrary bytes as a scenario file through the TOML parser and every section
// reader (the simulator's front door).
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmath>
#include <string>
#include <string_view>

#include "scenario/load_scenario.hpp"
#include "scenario/value_range.hpp"

namespace {

using namespace stepdance::sim::scenario;
using stepdance::sim::from_seconds;

/// What an accepted scenario promises the simulator: every checked value inside its range.
void check_accepted(const Scenario& scenario) {
  if (!(scenario.duration > 0) || scenario.duration > from_seconds(ranges::kDurationS.high)) abort();
  for (const BoardConfig& board : scenario.boards) {
    if (!in_range(board.loop_period_us, ranges::kLoopPeriodUs)) abort();
  }
  for (const CableConfig& cable : scenario.cables) {
    const stepdance::sim::CableSettings& settings = cable.settings;
    if (!in_range(settings.delay, ranges::kCableDelayNs) || !in_range(settings.stretch, ranges::kCableStretchNs) ||
        settings.glitch_every % stepdance::sim::kMicrosecond != 0 ||
        !in_range(settings.glitch_every / stepdance::sim::kMicrosecond, ranges::kGlitchEveryUs) ||
        !in_range(settings.glitch_width, ranges::kGlitchWidthNs)) {
      abort();
    }
  }
  // Every device and the machine carry their kind's row and that kind's settings (the simulation
  // builds them from these alone).
  for (const DeviceConfig& device : scenario.devices) {
    if (device.kind == nullptr || !device.settings.has_value()) abort();
  }
  if (scenario.machine && (scenario.machine->kind == nullptr || !scenario.machine->settings.has_value())) abort();
  if (!in_range(scenario.output.csv_interval_ms, ranges::kCsvIntervalMs)) abort();
  for (const Action& action : scenario.timeline) {
    if (action.time < 0 || action.time > scenario.duration) abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const LoadResult result = parse_scenario(text, "fuzz/scenario.toml");
  if (result.ok()) {
    check_accepted(result.scenario);
  } else {
    for (const Diagnostic& error : result.errors) {
      if (error.message.empty() || error.line < 0) abort();  // every refusal says where and why
    }
  }
  return 0;
}
