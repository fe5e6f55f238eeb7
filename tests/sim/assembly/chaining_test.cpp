// Two boards joined by a cable: what the Basic Module sends is what the Driver Module decodes.
#include "decode/capture_decoder.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

void expect_same_pulses(const PulseCounts& sent, const PulseCounts& received) {
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    EXPECT_EQ(sent[signal].forward, received[signal].forward) << "signal " << int{signal};
    EXPECT_EQ(sent[signal].reverse, received[signal].reverse) << "signal " << int{signal};
  }
}

TEST(ChainingTest, TheChainedExampleDeliversEveryPulseAndDrawsItsSquare) {
  auto simulation = create(load(source_path("examples/ChainedPlotterDriver")), "chained");
  const SimulationReport report = simulation->finish();
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;

  const PulseCounts& sent = simulation->board("knobs")->ports().sent(0);
  const PulseCounts& received = simulation->board("plotter")->ports().received(0);
  EXPECT_EQ(sent.accepted(), 10000u);
  expect_same_pulses(sent, received);
  EXPECT_EQ(received.rejected(), 0u);
  EXPECT_EQ(simulation->cables().front()->counters().pulses_removed, 0u);
  EXPECT_EQ(simulation->machine()->strokes().size(), 1u);
}

TEST(ChainingTest, DecodingTheSimulatorsOwnVcdReproducesItsCounts) {
  auto simulation = create(load(source_path("examples/ChainedPlotterDriver")), "chained_decode");
  simulation->finish();
  const VcdReadResult read = read_vcd_file(test_output_dir("chained_decode") + "/cable.vcd");
  ASSERT_TRUE(read.ok) << read.error;
  const std::vector<StepDirPair> pairs = find_step_dir_pairs(read.capture);
  ASSERT_EQ(pairs.size(), 2u);
  for (const StepDirPair& pair : pairs) {
    const VcdWire& step = read.capture.wires[pair.step];
    const VcdWire& dir = read.capture.wires[pair.dir];
    const DecodeResult decoded = decode_step_dir(step.edges, dir.edges, DecodeOptions{}, {step.initial, dir.initial});
    const bool output = pair.label == "knobs.OUT_A";
    const PulseCounts& counted =
        output ? simulation->board("knobs")->ports().sent(0) : simulation->board("plotter")->ports().received(0);
    ASSERT_TRUE(output || pair.label == "plotter.IN_A") << pair.label;
    for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
      EXPECT_EQ(decoded.counts[signal].forward, counted[signal].forward) << pair.label;
      EXPECT_EQ(decoded.counts[signal].reverse, counted[signal].reverse) << pair.label;
    }
    EXPECT_EQ(decoded.counts.too_short, counted.too_short);
  }
}

}  // namespace
}  // namespace stepdance::sim::test
