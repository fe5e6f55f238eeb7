// A 100 kHz stream between two boards at 10 µs frames, across a late, stretching, glitching
// cable (fixtures/HighSpeed/stream_100khz.toml): every count arrives, and `stepdance decode`'s
// decoder reads the recorded wires to the same counts.
#include "decode/capture_decoder.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

TEST(HighSpeedScenario, A100kHzStreamCrossesABadCableExactly) {
  auto simulation = create(load(source_path("tests/sim/assembly/fixtures/HighSpeed/stream_100khz.toml")), "high_speed");
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  ASSERT_FALSE(report.expectations.empty());
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;

  const VcdReadResult read = read_vcd_file(test_output_dir("high_speed") + "/stream.vcd");
  ASSERT_TRUE(read.ok) << read.error;
  // The sender's wire (before the cable) and the driver's (after it: late, stretched, glitched).
  for (const char* prefix : {"sender.OUT_A", "driver.IN_A"}) {
    const WireLookup step = find_wire(read.capture, std::string(prefix) + "_STEP");
    const WireLookup dir = find_wire(read.capture, std::string(prefix) + "_DIR");
    ASSERT_TRUE(step.ok && dir.ok) << prefix;
    DecodeOptions options;
    options.frame_period_us = 10;
    const DecodeResult decoded =
        decode_step_dir(read.capture.wires[step.index].edges, read.capture.wires[dir.index].edges, options);
    EXPECT_EQ(decoded.counts[SIGNAL_X].forward, 300000u) << prefix;
    EXPECT_EQ(decoded.counts[SIGNAL_X].reverse, 100000u) << prefix;
    EXPECT_EQ(decoded.accepted, 400000u) << prefix;
    EXPECT_EQ(decoded.counts.too_long, 0u) << prefix;
    // One X pulse in every 10 µs frame, frames 10 µs apart (the cable delays them all alike).
    EXPECT_EQ(decoded.frames.count, 400000u) << prefix;
    EXPECT_EQ(decoded.frames.max_pulses, 1u) << prefix;
    EXPECT_EQ(decoded.frames.min_start_spacing, 10 * kMicrosecond) << prefix;
  }
}

}  // namespace
}  // namespace stepdance::sim::test
