// Human-readable text and JSON renderings of a DecodeResult (the output of `stepdance decode`).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "decode/capture_decoder.hpp"

namespace stepdance::sim {

/// "too short" / "too long" / "accepted".
const char* verdict_text(protocol::PulseVerdict verdict);

/// A stable, human-readable report, headed by `title` (e.g. "driver.OUT_A"). Times in µs with
/// three decimals. Example:
///
///     driver.OUT_A
///       mode     STEPDANCE (DIR at STEP falling edge), clock 150 ticks/us
///       pulses   14 accepted, 2 rejected (1 too short, 1 too long), 0 incomplete
///       signal   forward   reverse
///       X              1         1
///       …
///       rejected 10.000 us: 0.500 us wide (0 us) too short
///       frames   2 of 40 us, at most 12 pulses per frame, start spacing 40.000 to 40.000 us
std::string format_decode_report(const DecodeResult& result, const std::string& title);

/// The same as JSON, keys sorted:
/// {"accepted", "clock_ticks_per_us", "frames": {"count", "max_pulses_per_frame",
///  "max_start_spacing_us", "min_start_spacing_us", "period_us"}, "incomplete", "mode", "pulses": {signal:
///  {"forward", "reverse"}}, "rejected": {"examples": [{"reason", "rise_us", "width_us"}],
///  "too_long", "too_short"}, "step_dir_signal" (STEP_DIR mode only)}.
nlohmann::json decode_report_json(const DecodeResult& result);

}  // namespace stepdance::sim
