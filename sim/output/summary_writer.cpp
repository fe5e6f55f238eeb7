// Summary writer: sorted JSON from nlohmann::json, wall time appended last in insertion order.
#include "output/summary_writer.hpp"

#include <stdexcept>

#include "output/text_file.hpp"

namespace stepdance::sim {

nlohmann::json summary_json(const RunSummary& summary) {
  nlohmann::json boards = nlohmann::json::object();
  for (const auto& [name, board] : summary.boards) boards[name] = {{"frame_overruns", board.frame_overruns}};
  nlohmann::json ports = nlohmann::json::object();
  for (const auto& [name, port] : summary.ports) {
    nlohmann::json entry = {{"pulses", signal_counts_json(port.pulses)}};
    if (port.is_input) {
      entry["rejected"] = {{"too_long", port.pulses.too_long}, {"too_short", port.pulses.too_short}};
    } else {
      entry["carried"] = port.carried;
    }
    ports[name] = entry;
  }
  nlohmann::json out = {
      {"boards", boards},
      {"ports", ports},
      {"simulated_time_s", to_seconds(summary.simulated_time)},
  };
  if (!summary.extra.is_object()) throw std::invalid_argument("summary extra fields must be a JSON object");
  for (const auto& [key, value] : summary.extra.items()) {
    if (out.contains(key) || key == "wall_time_s") {
      throw std::invalid_argument("summary extra field '" + key + "' repeats a fixed field");
    }
    out[key] = value;
  }
  return out;
}

std::string summary_text(const RunSummary& summary) {
  const nlohmann::json sorted = summary_json(summary);
  if (!summary.wall_time_s) return sorted.dump(2) + "\n";
  // ordered_json keeps insertion order: the sorted keys, then wall time last.
  nlohmann::ordered_json ordered = nlohmann::ordered_json::object();
  for (const auto& [key, value] : sorted.items()) ordered[key] = nlohmann::ordered_json::parse(value.dump());
  ordered["wall_time_s"] = *summary.wall_time_s;
  return ordered.dump(2) + "\n";
}

void write_summary(const std::string& path, const RunSummary& summary) { write_text_file(path, summary_text(summary)); }

}  // namespace stepdance::sim
