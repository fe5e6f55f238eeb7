// Decode report: exact text and JSON for a hand-made result, and STEP_DIR wording.
#include <gtest/gtest.h>

#include "decode/decode_report.hpp"

namespace stepdance::sim {
namespace {

DecodeResult sample_result() {
  DecodeResult result;
  result.counts[SIGNAL_X] = {1, 1};
  result.counts[SIGNAL_Y] = {2, 0};
  result.counts[SIGNAL_E] = {0, 12345678};
  result.accepted = 12345682;
  result.counts.too_short = 2;
  result.counts.too_long = 1;
  result.incomplete = 1;
  result.first_rejected = {{310000, 310500, 0, protocol::PulseVerdict::kTooShort},
                           {500000, 508000, 8, protocol::PulseVerdict::kTooLong}};
  result.frames = {3, 5, 40000, 80001};
  return result;
}

TEST(DecodeReport, TextIsExact) {
  EXPECT_EQ(format_decode_report(sample_result(), "driver.OUT_A"),
            "driver.OUT_A\n"
            "  mode     STEPDANCE (DIR at STEP falling edge), clock 150 ticks/us\n"
            "  pulses   12345682 accepted, 3 rejected (2 too short, 1 too long), 1 incomplete\n"
            "  signal   forward   reverse\n"
            "  X              1         1\n"
            "  Y              2         0\n"
            "  R              0         0\n"
            "  T              0         0\n"
            "  Z              0         0\n"
            "  E              0  12345678\n"
            "  rejected 310.000 us: 0.500 us wide (0 us) too short\n"
            "  rejected 500.000 us: 8.000 us wide (8 us) too long\n"
            "  rejected and 1 more\n"
            "  frames   3 of 40 us, at most 5 pulses per frame, start spacing 40.000 to 80.001 us\n");
}

TEST(DecodeReport, JsonIsExact) {
  EXPECT_EQ(
      decode_report_json(sample_result()).dump(),
      R"({"accepted":12345682,"clock_ticks_per_us":150,)"
      R"("frames":{"count":3,"max_pulses_per_frame":5,"max_start_spacing_us":80.001,"min_start_spacing_us":40.0,"period_us":40},)"
      R"("incomplete":1,"mode":"STEPDANCE",)"
      R"("pulses":{"E":{"forward":0,"reverse":12345678},"R":{"forward":0,"reverse":0},)"
      R"("T":{"forward":0,"reverse":0},"X":{"forward":1,"reverse":1},"Y":{"forward":2,"reverse":0},)"
      R"("Z":{"forward":0,"reverse":0}},)"
      R"("rejected":{"examples":[{"reason":"too_short","rise_us":310.0,"width_us":0.5},)"
      R"({"reason":"too_long","rise_us":500.0,"width_us":8.0}],"too_long":1,"too_short":2}})");
}

TEST(DecodeReport, StepDirModeNamesItsSignalAndFewFramesOmitSpacing) {
  DecodeResult result;
  result.options.mode = INPUT_MODE_STEP_DIR;
  result.options.step_dir_signal = SIGNAL_Z;
  result.options.clock.ticks_per_us = 600;
  result.counts[SIGNAL_Z] = {4, 0};
  result.accepted = 4;
  result.frames = {1, 4, 0, 0};
  EXPECT_EQ(format_decode_report(result, "D0/D1"),
            "D0/D1\n"
            "  mode     STEP_DIR (signal Z, DIR at STEP rising edge), clock 600 ticks/us\n"
            "  pulses   4 accepted, 0 rejected (0 too short, 0 too long), 0 incomplete\n"
            "  signal   forward   reverse\n"
            "  X              0         0\n"
            "  Y              0         0\n"
            "  R              0         0\n"
            "  T              0         0\n"
            "  Z              4         0\n"
            "  E              0         0\n"
            "  frames   1 of 40 us, at most 4 pulses per frame\n");
  const nlohmann::json json = decode_report_json(result);
  EXPECT_EQ(json["mode"], "STEP_DIR");
  EXPECT_EQ(json["step_dir_signal"], "Z");
  EXPECT_EQ(json["clock_ticks_per_us"], 600);
}

TEST(DecodeReport, VerdictTexts) {
  EXPECT_STREQ(verdict_text(protocol::PulseVerdict::kAccepted), "accepted");
  EXPECT_STREQ(verdict_text(protocol::PulseVerdict::kTooShort), "too short");
  EXPECT_STREQ(verdict_text(protocol::PulseVerdict::kTooLong), "too long");
}

}  // namespace
}  // namespace stepdance::sim
