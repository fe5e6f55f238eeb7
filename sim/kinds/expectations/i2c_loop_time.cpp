// Expectation kind "i2c_loop_pass_max_us": i2c_loop_pass_max_us = bound (µs, > 0),
// board = "<board>" — no loop pass of the board spent more wire time than that in I2C transfers.
#include "kinds/expectations/i2c_loop_time.hpp"

#include <cmath>
#include <cstdio>

#include "kinds/expectations/expectation_parts.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  I2cLoopTimeCheck check;
  const auto bound = reader.number("i2c_loop_pass_max_us");
  bool ok = bound.has_value();
  if (bound && (!std::isfinite(*bound) || *bound <= 0)) {
    reader.error("i2c_loop_pass_max_us", "'i2c_loop_pass_max_us' must be a time > 0 (µs)");
    ok = false;
  }
  if (bound) check.max_us = *bound;
  const auto board = reader.string("board", scenario::Need::kRequired);
  if (board && reading.context.scenario.board(*board) == nullptr) {
    reader.error("board", "unknown board '" + *board + "'");
    ok = false;
  }
  if (board) check.board = *board;
  reading.settings = check;
  return ok && board.has_value();
}

// The most wire time one loop pass of the board spent on I2C.
ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<I2cLoopTimeCheck>(expectation);
  const std::optional<I2cLoopTiming> timing = run.i2c_timing(check.board);
  if (!timing) return {false, "i2c: no such board"};
  const double worst_us = static_cast<double>(timing->max_loop_pass_ns) / 1000.0;
  char text[200];
  std::snprintf(text, sizeof text, "board '%s': longest loop pass in I2C %.1f us (limit %.1f us; %llu transfers)",
                check.board.c_str(), worst_us, check.max_us, static_cast<unsigned long long>(timing->transfers));
  return {timing->transfers > 0 && worst_us <= check.max_us, text};
}

}  // namespace

const ExpectationKind& i2c_loop_time_expectation() {
  static const ExpectationKind kind{"i2c_loop_pass_max_us", {"board"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
