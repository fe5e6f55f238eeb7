// What the boards tell the run's summary and its end: per board frames, load, faults, warnings,
// counters, I2C time, motors and firmware figures; per port the pulses sent and received.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/board_set.hpp"
#include "output/summary_writer.hpp"

namespace stepdance::sim {

/// Adds the boards' entries to the summary's extra object: "faults", "warnings", "frames",
/// "console" (when bytes were dropped), "motors", "counters", "cpu_load", "i2c" (when there were
/// transfers) and "firmware" (when a board runs an image). Context: host, at any time.
void add_board_extras(const BoardSet& boards, nlohmann::json& extra);
/// Each board's frame overruns, and each claimed output port's and begun input port's pulses.
void add_port_summaries(const BoardSet& boards, RunSummary& summary);
/// One line per kind of warning on each board's fault path, with its count and the first
/// report's detail: "[driver] warning ×3: Eibotboard: overrun (first: …)".
std::vector<std::string> board_warning_lines(const BoardSet& boards);

}  // namespace stepdance::sim
