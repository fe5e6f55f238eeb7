// Latency across a three-board chain (knob → knobs board → relay → relay): from the knob's count
// to the first STEP edge each board puts on its OUT_A.
//
// Bounds from the frame pipeline: a board reads its inputs in a frame and the words it computes
// play on the wire from the next frame tick, the first pulse 2 µs into that frame. So a knob
// count waits up to one frame to be read, then one frame to be played: at most 2 frames + 2 µs.
// A pulse arriving on an input port is decoded when it ends and handed on at the next frame:
// a relay hop is at most 2 frames.
#include <iostream>

#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

constexpr SimTime kFrame = 40 * kMicrosecond;

/// The first rising STEP edge of `wire` at or after `from`, or −1.
SimTime first_rise(const VcdCapture& capture, const std::string& wire, SimTime from) {
  const WireLookup found = find_wire(capture, wire);
  if (!found.ok) return -1;
  for (const Edge& edge : capture.wires[found.index].edges) {
    if (edge.level && edge.time >= from) return edge.time;
  }
  return -1;
}

TEST(ChainLatency, EachHopTakesAtMostTwoFrames) {  // the knob's hop: + the pulse's 2 µs
  auto simulation = create(load(source_path("tests/sim/assembly/fixtures/Relay/latency.toml")), "chain_latency");
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
  const VcdReadResult read = read_vcd_file(test_output_dir("chain_latency") + "/chain.vcd");
  ASSERT_TRUE(read.ok) << read.error;
  for (const SimTime knob : {from_seconds(1.0), from_seconds(1.5), from_seconds(1.750001)}) {
    const SimTime knobs = first_rise(read.capture, "knobs.OUT_A_STEP", knob);
    const SimTime relay = first_rise(read.capture, "relay.OUT_A_STEP", knobs);
    const SimTime relay2 = first_rise(read.capture, "relay2.OUT_A_STEP", relay);
    ASSERT_GE(knobs, 0);
    ASSERT_GE(relay, 0);
    ASSERT_GE(relay2, 0);
    std::cout << "latency after the count at " << to_seconds(knob) << " s (µs): knob→knobs " << (knobs - knob) / 1000.0
              << ", knobs→relay " << (relay - knobs) / 1000.0 << ", relay→relay2 " << (relay2 - relay) / 1000.0 << "\n";
    EXPECT_LE(knobs - knob, 2 * kFrame + 2 * kMicrosecond);
    EXPECT_LE(relay - knobs, 2 * kFrame);
    EXPECT_LE(relay2 - relay, 2 * kFrame);
  }
}

}  // namespace
}  // namespace stepdance::sim::test
