// Expectation kind "port": port = "board:OUT_A" (or IN_A), axis = "X", forward = N, reverse = N —
// the pulses of one signal a port sent or accepted, per direction.
#include "kinds/expectations/port_pulses.hpp"

#include <string_view>

#include "kinds/expectations/expectation_parts.hpp"
#include "output/pulse_counts.hpp"

namespace stepdance::sim {
namespace {

constexpr std::string_view kSignalLetters = "XYRTZE";

/// axis (required): one of kSignalLetters, as its index.
std::optional<int> read_axis(scenario::TableReader& reader) {
  const auto axis = reader.string("axis", scenario::Need::kRequired);
  if (!axis) return std::nullopt;
  const size_t index = axis->size() == 1 ? kSignalLetters.find((*axis)[0]) : std::string_view::npos;
  if (index != std::string_view::npos) return static_cast<int>(index);
  reader.error("axis", "'axis' must be one of \"X\", \"Y\", \"R\", \"T\", \"Z\", \"E\", got \"" + *axis + "\"");
  return std::nullopt;
}

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  PortPulsesCheck check;
  const auto port = read_port_line(reading);
  const auto signal = read_axis(reader);
  check.forward = reader.integer("forward");
  check.reverse = reader.integer("reverse");
  bool ok = port.has_value() && signal.has_value();
  if (!reader.has("forward") && !reader.has("reverse")) {
    reader.reporter().error(reader.line(), "a 'port' check needs 'forward', 'reverse' or both");
    ok = false;
  }
  if (!ok) return false;
  check.port = *port;
  check.signal = *signal;
  reading.settings = check;
  return true;
}

void add(ExpectationResult& result, const char* what, std::optional<int64_t> expected, uint64_t actual) {
  if (!expected) return;
  const ExpectationResult part = compare(what, *expected, static_cast<int64_t>(actual));
  result.met = result.met && part.met;
  result.message += part.message;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<PortPulsesCheck>(expectation);
  const PulseCounts* counts = run.pulses(check.port);
  const uint8_t signal = static_cast<uint8_t>(check.signal);
  const std::string what = port_name(check.port) + " " + signal_name(signal);
  if (counts == nullptr) return {false, what + ": no such board"};
  ExpectationResult result{true, what + ":"};
  add(result, " forward", check.forward, (*counts)[signal].forward);
  add(result, " reverse", check.reverse, (*counts)[signal].reverse);
  return result;
}

}  // namespace

const ExpectationKind& port_pulses_expectation() {
  static const ExpectationKind kind{"port", {"axis", "forward", "reverse"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
