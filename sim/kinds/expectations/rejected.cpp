// Expectation kind "rejected": rejected = N, port = "board:IN_A" — the pulses an input port
// refused (too short or too long).
#include "kinds/expectations/rejected.hpp"

#include "kinds/expectations/expectation_parts.hpp"
#include "output/pulse_counts.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  const auto port = read_port_line(reading);
  bool ok = port.has_value();
  if (port && port->output) {
    reader.error("port", "'rejected' counts pulses an input port refused: 'port' must be \"board:IN_" +
                             std::string(1, port->port) + "\"");
    ok = false;
  }
  const auto count = reader.integer("rejected");
  if (!ok || !count) return false;
  reading.settings = RejectedCheck{*port, *count};
  return true;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<RejectedCheck>(expectation);
  const PulseCounts* counts = run.pulses(check.port);
  if (counts == nullptr) return {false, port_name(check.port) + ": no such board"};
  return compare(port_name(check.port) + " rejected pulses", check.rejected, static_cast<int64_t>(counts->rejected()));
}

}  // namespace

const ExpectationKind& rejected_expectation() {
  static const ExpectationKind kind{"rejected", {"port"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
