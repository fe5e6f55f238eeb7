// Decode report formatting: aligned text columns and sorted-key JSON.
#include "decode/decode_report.hpp"

#include "common/plural.hpp"

#include "output/number_format.hpp"

namespace stepdance::sim {
namespace {

std::string us_text(SimTime ns) { return format_time(ns, kMicrosecond, 3); }

double us_value(SimTime ns) { return static_cast<double>(ns) / static_cast<double>(kMicrosecond); }

std::string padded(const std::string& text, size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

const char* mode_name(InputMode mode) { return mode == INPUT_MODE_STEP_DIR ? "STEP_DIR" : "STEPDANCE"; }

}  // namespace

const char* verdict_text(protocol::PulseVerdict verdict) {
  switch (verdict) {
    case protocol::PulseVerdict::kAccepted: return "accepted";
    case protocol::PulseVerdict::kTooShort: return "too short";
    case protocol::PulseVerdict::kTooLong: return "too long";
  }
  return "?";
}

std::string format_decode_report(const DecodeResult& result, const std::string& title) {
  const DecodeOptions& options = result.options;
  std::string out = title + "\n";
  out += "  mode     ";
  out += mode_name(options.mode);
  if (options.mode == INPUT_MODE_STEP_DIR) {
    out += std::string(" (signal ") + signal_name(options.step_dir_signal) + ", DIR at STEP rising edge)";
  } else {
    out += " (DIR at STEP falling edge)";
  }
  out += ", clock " + std::to_string(options.clock.ticks_per_us) + " ticks/us\n";
  const uint64_t rejected = result.counts.rejected();
  out += "  pulses   " + std::to_string(result.accepted) + " accepted, " + std::to_string(rejected) + " rejected (" +
         std::to_string(result.counts.too_short) + " too short, " + std::to_string(result.counts.too_long) +
         " too long), " + std::to_string(result.incomplete) + " incomplete\n";
  out += "  signal   forward   reverse\n";
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    out += std::string("  ") + signal_name(signal) + "     " +
           padded(std::to_string(result.counts[signal].forward), 10) +
           padded(std::to_string(result.counts[signal].reverse), 10) + "\n";
  }
  for (const RejectedPulse& pulse : result.first_rejected) {
    out += "  rejected " + us_text(pulse.rise) + " us: " + us_text(pulse.fall - pulse.rise) + " us wide (" +
           std::to_string(pulse.width_us) + " us) " + verdict_text(pulse.reason) + "\n";
  }
  if (rejected > result.first_rejected.size()) {
    out += "  rejected and " + std::to_string(rejected - result.first_rejected.size()) + " more\n";
  }
  const FrameStats& frames = result.frames;
  out += "  frames   " + std::to_string(frames.count) + " of " + std::to_string(result.options.frame_period_us) +
         " us, at most " + counted(frames.max_pulses, "pulse", "pulses") + " per frame";
  if (frames.count >= 2) {
    out += ", start spacing " + us_text(frames.min_start_spacing) + " to " + us_text(frames.max_start_spacing) + " us";
  }
  out += "\n";
  return out;
}

nlohmann::json decode_report_json(const DecodeResult& result) {
  nlohmann::json examples = nlohmann::json::array();
  for (const RejectedPulse& pulse : result.first_rejected) {
    examples.push_back({{"reason", pulse.reason == protocol::PulseVerdict::kTooLong ? "too_long" : "too_short"},
                        {"rise_us", us_value(pulse.rise)},
                        {"width_us", us_value(pulse.fall - pulse.rise)}});
  }
  nlohmann::json out = {
      {"accepted", result.accepted},
      {"clock_ticks_per_us", result.options.clock.ticks_per_us},
      {"frames",
       {{"count", result.frames.count},
        {"max_pulses_per_frame", result.frames.max_pulses},
        {"max_start_spacing_us", us_value(result.frames.max_start_spacing)},
        {"min_start_spacing_us", us_value(result.frames.min_start_spacing)},
        {"period_us", result.options.frame_period_us}}},
      {"incomplete", result.incomplete},
      {"mode", mode_name(result.options.mode)},
      {"pulses", signal_counts_json(result.counts)},
      {"rejected",
       {{"examples", examples}, {"too_long", result.counts.too_long}, {"too_short", result.counts.too_short}}},
  };
  if (result.options.mode == INPUT_MODE_STEP_DIR) out["step_dir_signal"] = signal_name(result.options.step_dir_signal);
  return out;
}

}  // namespace stepdance::sim
