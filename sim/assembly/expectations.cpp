// Evaluation of [[expect]] entries: motor steps, pen position, strokes, port pulses, cables, rejections.
#include "assembly/expectations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "models/ssd1306_display.hpp"
#include "output/pulse_counts.hpp"
#include "assembly/simulation.hpp"

namespace stepdance::sim {
namespace {

using scenario::Expectation;
using scenario::ExpectationType;

std::string place(const scenario::Scenario& scenario, const Expectation& expectation) {
  return scenario.file + ":" + std::to_string(expectation.line) + ": ";
}

std::string port_name(const scenario::PortLineRef& port) {
  return port.board + (port.output ? ":OUT_" : ":IN_") + port.port;
}

std::string millimetres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

ExpectationResult compare(const std::string& what, int64_t expected, int64_t actual) {
  return {expected == actual,
          what + ": expected " + std::to_string(expected) + ", got " + std::to_string(actual)};
}

ExpectationResult motor_steps(const Expectation& expectation, const Simulation& simulation) {
  const std::string name = expectation.motor.board + ":" + expectation.motor.port;
  const StepperDriver* motor = simulation.stepper(expectation.motor.board, expectation.motor.port);
  if (motor == nullptr) return {false, "motor " + name + ": no stepper in that socket"};
  return compare("motor " + name + " steps", expectation.steps, motor->position_steps());
}

ExpectationResult pen_position(const Expectation& expectation, const Simulation& simulation) {
  if (simulation.machine() == nullptr) return {false, "pen_mm: the scenario has no machine"};
  const PenPoint pen = simulation.machine()->pen_position();
  const double off = std::hypot(pen.x_mm - expectation.pen_x_mm, pen.y_mm - expectation.pen_y_mm);
  return {off <= expectation.tolerance_mm,
          "pen at [" + millimetres(expectation.pen_x_mm) + ", " + millimetres(expectation.pen_y_mm) + "] mm ± " +
              millimetres(expectation.tolerance_mm) + ": got [" + millimetres(pen.x_mm) + ", " +
              millimetres(pen.y_mm) + "]"};
}

ExpectationResult strokes(const Expectation& expectation, const Simulation& simulation) {
  if (simulation.machine() == nullptr) return {false, "strokes: the scenario has no machine"};
  return compare("pen-down strokes", expectation.strokes, static_cast<int64_t>(simulation.machine()->strokes().size()));
}

ExpectationResult bounds(const Expectation& expectation, const Simulation& simulation) {
  if (simulation.machine() == nullptr) return {false, "bounds_mm: the scenario has no machine"};
  double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Polyline& stroke : simulation.machine()->strokes()) {
    for (const PenPoint& point : stroke) {
      box[0] = std::min(box[0], point.x_mm);
      box[1] = std::min(box[1], point.y_mm);
      box[2] = std::max(box[2], point.x_mm);
      box[3] = std::max(box[3], point.y_mm);
    }
  }
  const auto text = [](const double* edges) {
    return "[" + millimetres(edges[0]) + ", " + millimetres(edges[1]) + ", " + millimetres(edges[2]) + ", " +
           millimetres(edges[3]) + "]";
  };
  const std::string what = "pen-down bounds " + text(expectation.bounds_mm) + " mm ± " +
                           millimetres(expectation.tolerance_mm);
  if (box[0] > box[2]) return {false, what + ": nothing was drawn"};
  bool met = true;
  for (int i = 0; i < 4; ++i) met = met && std::fabs(box[i] - expectation.bounds_mm[i]) <= expectation.tolerance_mm;
  return {met, what + ": got " + text(box)};
}

ExpectationResult drawn_length(const Expectation& expectation, const Simulation& simulation) {
  if (simulation.machine() == nullptr) return {false, "drawn_mm: the scenario has no machine"};
  const double drawn = simulation.machine()->stats().pen_down_mm;
  return {std::fabs(drawn - expectation.drawn_mm) <= expectation.tolerance_mm,
          "pen-down length " + millimetres(expectation.drawn_mm) + " mm ± " + millimetres(expectation.tolerance_mm) +
              ": got " + millimetres(drawn)};
}

ExpectationResult z_position(const Expectation& expectation, const Simulation& simulation) {
  const std::optional<double> z = simulation.machine() ? simulation.machine()->axis_mm(MachineAxis::kZ) : std::nullopt;
  if (!z) return {false, "z_mm: the machine has no z axis"};
  return {std::fabs(*z - expectation.z_mm) <= expectation.tolerance_mm,
          "z at " + millimetres(expectation.z_mm) + " mm ± " + millimetres(expectation.tolerance_mm) + ": got " +
              millimetres(*z)};
}

double polyline_length_mm(const std::vector<Polyline>& strokes) {
  double length = 0;
  for (const Polyline& stroke : strokes) {
    for (size_t i = 1; i < stroke.size(); ++i) {
      length += std::hypot(stroke[i].x_mm - stroke[i - 1].x_mm, stroke[i].y_mm - stroke[i - 1].y_mm);
    }
  }
  return length;
}

// Both lengths come from the machine's motors: the extruder's advance, and the pen-down
// (extruding) toolpath as stored — polylines that smooth out the axes' stair steps, which would
// otherwise add up to a fifth to a curve's length.
ExpectationResult extrusion_ratio(const Expectation& expectation, const Simulation& simulation) {
  const std::optional<double> e = simulation.machine() ? simulation.machine()->axis_mm(MachineAxis::kE) : std::nullopt;
  if (!e) return {false, "extruded_per_mm: the machine has no extruder"};
  const double path = polyline_length_mm(simulation.machine()->strokes());
  char text[160];
  std::snprintf(text, sizeof text, "extruded %.4f mm over %.3f mm of path: %.6f per mm (expected %.6f ± %.2f %%)", *e,
                path, path > 0 ? *e / path : 0.0, expectation.extruded_per_mm, expectation.relative_tolerance * 100);
  if (path <= 0) return {false, text};
  return {std::fabs(*e / path - expectation.extruded_per_mm) <= expectation.relative_tolerance * expectation.extruded_per_mm, text};
}

/// Distance from p to the segment ab.
double to_segment_mm(const PenPoint& p, const PenPoint& a, const PenPoint& b) {
  const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm;
  const double span = dx * dx + dy * dy;
  double k = span > 0 ? ((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / span : 0.0;
  k = std::clamp(k, 0.0, 1.0);
  return std::hypot(p.x_mm - (a.x_mm + k * dx), p.y_mm - (a.y_mm + k * dy));
}

/// Distance from p to the nearest point of any of the polylines (a one-point line is a dot).
double to_polylines_mm(const PenPoint& p, const std::vector<Polyline>& lines) {
  double nearest = INFINITY;
  for (const Polyline& line : lines) {
    if (line.size() == 1) nearest = std::min(nearest, std::hypot(p.x_mm - line[0].x_mm, p.y_mm - line[0].y_mm));
    for (size_t i = 1; i < line.size(); ++i) nearest = std::min(nearest, to_segment_mm(p, line[i - 1], line[i]));
  }
  return nearest;
}

// Both ways: every drawn point lies near the stylus's path, and every path point from
// `from_point` on lies near the drawing — so nothing extra is drawn and nothing is left out.
ExpectationResult traces(const Expectation& expectation, const Simulation& simulation) {
  const FiveBarArm* arm = simulation.five_bar_arm(expectation.traces);
  if (arm == nullptr || simulation.machine() == nullptr) return {false, "traces: no such arm or no machine"};
  Polyline path;
  for (const PenPoint& point : arm->path()) {
    path.push_back({point.x_mm + expectation.offset_mm[0], point.y_mm + expectation.offset_mm[1]});
  }
  const std::vector<Polyline>& strokes = simulation.machine()->strokes();
  double drawn_off = 0;
  for (const Polyline& stroke : strokes) {
    for (const PenPoint& point : stroke) drawn_off = std::max(drawn_off, to_polylines_mm(point, {path}));
  }
  double missed = 0;
  // path[0] is the arm's home; path_mm[i] is path[i + 1].
  for (size_t i = static_cast<size_t>(expectation.from_point) + 1; i < path.size(); ++i) {
    missed = std::max(missed, to_polylines_mm(path[i], strokes));
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "drawing traces arm '%s' within %.3f mm: farthest drawn point %.4f mm off its path, farthest "
                "path point %.4f mm from the drawing",
                expectation.traces.c_str(), expectation.tolerance_mm, drawn_off, missed);
  const bool drew = !strokes.empty();
  return {drew && drawn_off <= expectation.tolerance_mm && missed <= expectation.tolerance_mm, text};
}

// The OLED's rows at the end of the run, read back in Stepdance's font.
ExpectationResult screen_text(const Expectation& expectation, const Simulation& simulation) {
  const Ssd1306Display* oled = model_of<Ssd1306Display>(simulation.device(expectation.screen));
  if (oled == nullptr) return {false, "screen: no such oled"};
  const std::vector<std::string> rows = oled->text_rows();
  std::string shown;
  bool found = false;
  for (size_t row = 0; row < rows.size(); ++row) {
    shown += (row == 0 ? "\"" : " | \"") + rows[row] + "\"";
    if (expectation.screen_row < 0 || static_cast<size_t>(expectation.screen_row) == row) {
      found = found || rows[row] == expectation.shows;
    }
  }
  const std::string where = expectation.screen_row < 0 ? "a row" : "row " + std::to_string(expectation.screen_row);
  return {found, "screen '" + expectation.screen + "' " + where + " shows \"" + expectation.shows + "\": rows " + shown};
}

// The most wire time one loop pass of the board spent on I2C.
ExpectationResult i2c_loop_time(const Expectation& expectation, const Simulation& simulation) {
  const SimBoard* board = simulation.board(expectation.i2c_board);
  if (board == nullptr) return {false, "i2c: no such board"};
  const SimBoard::I2cTiming& timing = board->i2c_timing();
  const double worst_us = static_cast<double>(timing.max_loop_pass_ns) / 1000.0;
  char text[200];
  std::snprintf(text, sizeof text, "board '%s': longest loop pass in I2C %.1f us (limit %.1f us; %llu transfers)",
                expectation.i2c_board.c_str(), worst_us, expectation.i2c_loop_pass_max_us,
                static_cast<unsigned long long>(timing.transfers));
  return {timing.transfers > 0 && worst_us <= expectation.i2c_loop_pass_max_us, text};
}

const PulseCounts* counts_of(const scenario::PortLineRef& port, const Simulation& simulation) {
  const SimBoard* board = simulation.board(port.board);
  if (board == nullptr) return nullptr;
  const uint8_t index = static_cast<uint8_t>(port.port - 'A');
  return port.output ? &board->sent(index) : &board->received(index);
}

ExpectationResult port_pulses(const Expectation& expectation, const Simulation& simulation) {
  const PulseCounts* counts = counts_of(expectation.port, simulation);
  const uint8_t signal = static_cast<uint8_t>(expectation.signal);
  const std::string what = port_name(expectation.port) + " " + signal_name(signal);
  if (counts == nullptr) return {false, what + ": no such board"};
  const int64_t forward = static_cast<int64_t>((*counts)[signal].forward);
  const int64_t reverse = static_cast<int64_t>((*counts)[signal].reverse);
  ExpectationResult result{true, what + ":"};
  if (expectation.forward) {
    const ExpectationResult check = compare(" forward", *expectation.forward, forward);
    result.met = result.met && check.met;
    result.message += check.message;
  }
  if (expectation.reverse) {
    const ExpectationResult check = compare(" reverse", *expectation.reverse, reverse);
    result.met = result.met && check.met;
    result.message += check.message;
  }
  return result;
}

ExpectationResult rejected(const Expectation& expectation, const Simulation& simulation) {
  const PulseCounts* counts = counts_of(expectation.port, simulation);
  if (counts == nullptr) return {false, port_name(expectation.port) + ": no such board"};
  return compare(port_name(expectation.port) + " rejected pulses", expectation.rejected,
                 static_cast<int64_t>(counts->rejected()));
}

// Every cable: the receiving port accepted exactly the pulses (per signal and direction) the
// sending port put on the wire.
ExpectationResult cable_counts(const scenario::Scenario& scenario, const Simulation& simulation) {
  ExpectationResult result{true, "cable counts match:"};
  for (const scenario::CableConfig& cable : scenario.cables) {
    const PulseCounts& sent = simulation.board(cable.from.board)->sent(static_cast<uint8_t>(cable.from.port - 'A'));
    const PulseCounts& got = simulation.board(cable.to.board)->received(static_cast<uint8_t>(cable.to.port - 'A'));
    const bool same = sent.signals == got.signals;
    result.met = result.met && same;
    result.message += " " + cable.from.board + ":OUT_" + cable.from.port + " → " + cable.to.board + ":IN_" +
                      cable.to.port + " sent " + std::to_string(sent.accepted()) + ", accepted " +
                      std::to_string(got.accepted()) + (same ? "" : " (differs)");
  }
  return result;
}

/// Received lines of a host client, with their times.
std::vector<const HostClient::Entry*> received(const HostClient& client) {
  std::vector<const HostClient::Entry*> lines;
  for (const HostClient::Entry& entry : client.transcript()) {
    if (!entry.from_host) lines.push_back(&entry);
  }
  return lines;
}

std::string quoted_list(const std::vector<std::string>& patterns) {
  std::string text;
  for (const std::string& pattern : patterns) text += (text.empty() ? "\"" : ", \"") + pattern + "\"";
  return text;
}

/// Replies in order; or one reply (count, within_ms after a sent line).
ExpectationResult host_replies(const Expectation& expectation, const Simulation& simulation) {
  const HostClient* client = simulation.host_client(expectation.host);
  if (client == nullptr) return {false, "host " + expectation.host + ": no client"};
  const std::vector<const HostClient::Entry*> lines = received(*client);
  const std::string what = "host " + expectation.host + " received " + quoted_list(expectation.replies);
  if (expectation.replies.size() > 1) {
    std::vector<scenario::LinePattern> patterns;
    for (const std::string& reply : expectation.replies) patterns.emplace_back(reply);
    size_t next = 0;
    for (const HostClient::Entry* line : lines) {
      if (next < patterns.size() && patterns[next].found_in(line->text)) ++next;
    }
    return {next == expectation.replies.size(), what + " in order: matched " + std::to_string(next) + " of " +
                                                    std::to_string(expectation.replies.size())};
  }
  const scenario::LinePattern reply(expectation.replies[0]);
  int64_t matches = 0;
  for (const HostClient::Entry* line : lines) matches += reply.found_in(line->text) ? 1 : 0;
  if (expectation.count) return compare(what + " (lines)", *expectation.count, matches);
  if (!expectation.within) return {matches > 0, what + ": " + std::to_string(matches) + " matching lines"};
  // Timed: from the first sent line matching `after` (or the client's first line) to the reply.
  const scenario::LinePattern after(expectation.after.empty() ? std::string(".*") : expectation.after);
  std::optional<SimTime> from;
  for (const HostClient::Entry& entry : client->transcript()) {
    if (!from && entry.from_host && after.found_in(entry.text)) from = entry.time;
    if (from && !entry.from_host && reply.found_in(entry.text)) {
      const SimTime took = entry.time - *from;
      char text[64];
      std::snprintf(text, sizeof text, " within %.3f ms: took %.3f ms", to_seconds(*expectation.within) * 1e3,
                    to_seconds(took) * 1e3);
      return {took <= *expectation.within, what + text};
    }
  }
  return {false, what + ": no such reply" + (from ? "" : " (nothing sent matched 'after')")};
}

ExpectationResult host_completed(const Expectation& expectation, const Simulation& simulation) {
  const HostClient* client = simulation.host_client(expectation.host);
  if (client == nullptr) return {false, "host " + expectation.host + ": no client"};
  if (client->completed()) return {true, "host " + expectation.host + " ran every step"};
  return {false, client->failure().empty() ? "host " + expectation.host + " was still running when the run ended"
                                           : client->failure()};
}

ExpectationResult evaluate(const scenario::Scenario& scenario, const Expectation& expectation,
                           const Simulation& simulation) {
  switch (expectation.type) {
    case ExpectationType::kMotorSteps: return motor_steps(expectation, simulation);
    case ExpectationType::kPenPosition: return pen_position(expectation, simulation);
    case ExpectationType::kStrokes: return strokes(expectation, simulation);
    case ExpectationType::kBounds: return bounds(expectation, simulation);
    case ExpectationType::kDrawnLength: return drawn_length(expectation, simulation);
    case ExpectationType::kZPosition: return z_position(expectation, simulation);
    case ExpectationType::kExtrusionRatio: return extrusion_ratio(expectation, simulation);
    case ExpectationType::kTraces: return traces(expectation, simulation);
    case ExpectationType::kPortPulses: return port_pulses(expectation, simulation);
    case ExpectationType::kCableCountsMatch: return cable_counts(scenario, simulation);
    case ExpectationType::kRejected: return rejected(expectation, simulation);
    case ExpectationType::kHostReplies: return host_replies(expectation, simulation);
    case ExpectationType::kHostCompleted: return host_completed(expectation, simulation);
    case ExpectationType::kScreenText: return screen_text(expectation, simulation);
    case ExpectationType::kI2cLoopTime: return i2c_loop_time(expectation, simulation);
  }
  return {false, "unknown expectation"};
}

}  // namespace

std::vector<ExpectationResult> evaluate_expectations(const scenario::Scenario& scenario, const Simulation& simulation) {
  std::vector<ExpectationResult> results;
  for (const Expectation& expectation : scenario.expectations) {
    ExpectationResult result = evaluate(scenario, expectation, simulation);
    result.message = place(scenario, expectation) + result.message;
    results.push_back(std::move(result));
  }
  return results;
}

std::vector<ExpectationResult> unchecked_expectations(const scenario::Scenario& scenario, const std::string& reason) {
  std::vector<ExpectationResult> results;
  for (const Expectation& expectation : scenario.expectations) {
    results.push_back({false, place(scenario, expectation) + "not checked: " + reason, false});
  }
  return results;
}

}  // namespace stepdance::sim
