// Expectation kind "cable_counts_match": cable_counts_match = true — every cable's receiving port
// accepted exactly the pulses (per signal and direction) its sending port put on the wire.
#include "kinds/expectations/cable_counts.hpp"

#include "kinds/expectations/expectation_parts.hpp"
#include "output/pulse_counts.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  const auto match = reader.boolean("cable_counts_match");
  if (!match) return false;
  if (!*match) {
    reader.error("cable_counts_match", "'cable_counts_match' can only be true");
    return false;
  }
  if (reading.context.scenario.cables.empty()) {
    reader.error("cable_counts_match", "'cable_counts_match' needs at least one [[cable]]");
    return false;
  }
  reading.settings = CableCountsCheck{};
  return true;
}

ExpectationResult check(const scenario::Expectation&, const FinishedRun& run) {
  ExpectationResult result{true, "cable counts match:"};
  for (const scenario::CableConfig& cable : run.scenario().cables) {
    const PulseCounts& sent = *run.pulses({cable.from.board, true, cable.from.port});
    const PulseCounts& got = *run.pulses({cable.to.board, false, cable.to.port});
    const bool same = sent.signals == got.signals;
    result.met = result.met && same;
    result.message += " " + cable.from.board + ":OUT_" + cable.from.port + " → " + cable.to.board + ":IN_" +
                      cable.to.port + " sent " + std::to_string(sent.accepted()) + ", accepted " +
                      std::to_string(got.accepted()) + (same ? "" : " (differs)");
  }
  return result;
}

}  // namespace

const ExpectationKind& cable_counts_expectation() {
  static const ExpectationKind kind{"cable_counts_match", {}, read, check};
  return kind;
}

}  // namespace stepdance::sim
