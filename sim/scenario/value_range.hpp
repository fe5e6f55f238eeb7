// The unit and allowed range of every number a scenario file or the command line gives: one rule
// per quantity, checked by the scenario reader's typed getters and by `stepdance sim` alike.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace stepdance::sim::scenario {

/// A real quantity: [low, high] (or (low, high] when low_open) in `unit`; nan and inf never fit.
struct NumberRange {
  double low;
  double high;
  bool low_open;
  const char* unit;  ///< "s", "ms", "mm", … ("" for a plain number)
};

/// A whole quantity: [low, high] in `unit`.
struct IntegerRange {
  int64_t low;
  int64_t high;
  const char* unit;
};

/// The ranges, one per quantity. Upper limits keep every derived time in int64 nanoseconds and
/// every count far from overflow; the values are documented in docs/scenario-format.md.
namespace ranges {
/// A run: from one nanosecond (the clock's tick: a shorter run would be no run at all) up to a
/// day (SimTime holds ~292 years; every product below stays far inside it).
inline constexpr NumberRange kDurationS{1e-9, 86400, false, "s"};
/// A moment or span inside a run.
inline constexpr NumberRange kTimeS{0, 86400, false, "s"};
inline constexpr NumberRange kTimeMs{0, 86400000, false, "ms"};
inline constexpr IntegerRange kSeed{0, std::numeric_limits<int64_t>::max(), ""};
/// The simulated loop() period of a board: 1 µs … 1 s.
inline constexpr IntegerRange kLoopPeriodUs{1, 1000000, "µs"};
/// CSV rows: at most one per 40 µs frame, at least one per day.
inline constexpr NumberRange kCsvIntervalMs{0.04, 86400000, false, "ms"};
/// Cables: delay and stretch up to a second, glitches up to a millisecond wide, spaced up to a day.
inline constexpr IntegerRange kCableDelayNs{0, 1000000000, "ns"};
inline constexpr IntegerRange kCableStretchNs{-1000000000, 1000000000, "ns"};
inline constexpr IntegerRange kGlitchEveryUs{0, 86400000000, "µs"};
inline constexpr IntegerRange kGlitchWidthNs{1, 1000000, "ns"};
/// Encoder counts (a start value, one turn): ±10^12, so any day of turns sums inside int64.
inline constexpr IntegerRange kEncoderCounts{-1000000000000, 1000000000000, "counts"};
/// Live pacing: simulated seconds per wall-clock second.
inline constexpr NumberRange kSpeed{0, 1000000, true, "x real time"};
/// `stepdance serve`'s pacing of a simulated board: a thousandth to a thousand times real time.
inline constexpr NumberRange kServeSpeed{0.001, 1000, false, "x real time"};
/// A TCP port to listen on (0: any free one).
inline constexpr IntegerRange kTcpPort{0, 65535, ""};
/// A serial device's baud rate.
inline constexpr IntegerRange kBaudRate{1, 10000000, "baud"};
/// A machine dimension, position or length in mm.
inline constexpr NumberRange kLengthMm{-1000000, 1000000, false, "mm"};
inline constexpr NumberRange kPositiveLengthMm{0, 1000000, true, "mm"};
}  // namespace ranges

/// Whether `value` lies in the range (false for nan). Context: any.
bool in_range(double value, const NumberRange& range);
bool in_range(int64_t value, const IntegerRange& range);

/// The range as people write it: "[1e-09, 86,400] s", "[1, 1,000,000] µs".
std::string describe(const NumberRange& range);
std::string describe(const IntegerRange& range);

/// A number for a message: whole numbers with thousands separators up to 10^15, else six
/// significant digits ("12.5", "1e+300", "nan", "inf"); integers always in full with separators
/// ("9,223,372,036,854,775,807").
std::string readable_number(double value);
std::string readable_integer(int64_t value);

/// "'name' must be in [1e-09, 86,400] s, got 1e+300" (`name` as the user wrote it).
std::string out_of_range(std::string_view name, const NumberRange& range, double got);
std::string out_of_range(std::string_view name, const IntegerRange& range, int64_t got);

/// Parses a command-line number (scenario/decimal_text.hpp: decimal only, nothing around it)
/// and checks it against `range` (so nan and inf never pass). Returns the value, or nothing with
/// `error` = "--option: 'text' is not a decimal number (allowed: range)" or
/// "--option: must be in range, got text". Every number option of `stepdance` goes through
/// this or parse_integer_option. Context: host, command-line checking.
std::optional<double> parse_number_option(std::string_view option, const std::string& text, const NumberRange& range,
                                          std::string& error);
/// The same for a whole number: digits with an optional sign, checked against `range`.
std::optional<int64_t> parse_integer_option(std::string_view option, const std::string& text, const IntegerRange& range,
                                            std::string& error);

}  // namespace stepdance::sim::scenario
