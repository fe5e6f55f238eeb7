// The JSON run summary: pulses per port, axis and direction, rejections, carries, overruns, times.
#pragma once

#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/sim_time.hpp"
#include "output/pulse_counts.hpp"

namespace stepdance::sim {

/// Counts of one output or input port over the run.
struct PortSummary {
  bool is_input = false;  ///< an input port (has rejections) or an output port (has carries)
  PulseCounts pulses;     ///< pulses sent (output) or accepted and rejected (input)
  uint64_t carried = 0;   ///< output: signals that did not fit their frame and went in a later one
};

/// Counts of one board over the run.
struct BoardSummary {
  uint64_t frame_overruns = 0;  ///< frames whose work did not finish before the next frame
};

/// Everything the summary file holds.
struct RunSummary {
  SimTime simulated_time = 0;                  ///< ns simulated
  std::optional<double> wall_time_s;           ///< real seconds the run took; left out when empty
  std::map<std::string, BoardSummary> boards;  ///< by board name
  std::map<std::string, PortSummary> ports;    ///< by "board:OUT_A" / "board:IN_A"
  /// More top-level fields (an object); a key equal to a fixed one is an error.
  nlohmann::json extra = nlohmann::json::object();
};

/// The summary as JSON, every object's keys sorted:
/// {"boards": {name: {"frame_overruns"}}, "ports": {name: {"pulses": {signal: {"forward",
/// "reverse"}}, then "carried" (output ports) or "rejected": {"too_long", "too_short"} (input
/// ports)}}, "simulated_time_s", extra fields…}. Wall time is not included here.
/// Throws std::invalid_argument if `extra` is not an object or repeats a fixed key.
nlohmann::json summary_json(const RunSummary& summary);

/// The summary file's text: summary_json() indented by 2, with "wall_time_s" appended as the
/// very last key when present (so everything before it is identical from run to run), and a
/// final newline.
std::string summary_text(const RunSummary& summary);

/// Writes summary_text() to `path`. Throws std::runtime_error("path: …") if it cannot.
void write_summary(const std::string& path, const RunSummary& summary);

}  // namespace stepdance::sim
