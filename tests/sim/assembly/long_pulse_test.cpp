// Long STEP pulses between simulated boards: a cable stretches the knob board's 2 µs X pulses to
// 8 µs, 437 µs, 439 µs, 1 ms and 1 s. Past 436.9 µs the 16-bit capture counter wraps inside the
// pulse: a STEPDANCE-mode port must still reject every one as too long (a wrapped difference
// alone would read 439 µs as a 2 µs X step), a STEP_DIR-mode port must count each as one step.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

constexpr int64_t kWidthsNs[] = {8'000, 437'000, 439'000, 1'000'000, 1'000'000'000};
/// The knob board sends two X pulses 1.2 s apart, so even 1 s pulses stay apart.
constexpr uint64_t kPulses = 2;

/// The knob board cabled to `receiver` (a sketch path relative to examples/ChainedPlotterDriver),
/// the cable stretching every pulse to `width_ns` (the knob board's X pulses are 2 µs wide).
scenario::Scenario knob_to(const std::string& receiver, int64_t width_ns) {
  const std::string text = R"(
duration_s = 4

[[board]]
name = "knobs"
sketch = "../ChainedKnobsBasic/ChainedKnobsBasic.ino"
module = "basic"

[[board]]
name = "receiver"
sketch = ")" + receiver + R"("

[[device]]
name = "knob_x"
type = "encoder"
board = "knobs"
connector = "ENC1"

[[cable]]
from = "knobs:A"
to = "receiver:A"
stretch_ns = )" + std::to_string(width_ns - 2000) +
                           R"(

[[at]]
time_s = 0.1
turn = "knob_x"
counts = 2
over_s = 2.4

[output]
svg = ""
png = ""
summary = ""
)";
  return parse(text, source_path("examples/ChainedPlotterDriver/long_pulse_test.toml"));
}

struct Received {
  PulseCounts sent;
  PulseCounts host_decoded;    // the simulator's own decode of what reached the port
  uint64_t port_too_long = 0;  // the sketch's InputPort counters
  uint64_t port_accepted = 0;
};

Received run(const std::string& receiver, int64_t width_ns, const std::string& name) {
  auto simulation = create(knob_to(receiver, width_ns), name, false);
  simulation->finish();
  const SimBoard& board = *simulation->board("receiver");
  Received received{simulation->board("knobs")->ports().sent(0), board.ports().received(0), 0, 0};
  received.port_too_long = board.port_counter("InputPort", 0, "rejected_too_long");
  for (const char* counter : {"received_x_forward", "received_x_reverse", "received_y_forward", "received_y_reverse"}) {
    received.port_accepted += board.port_counter("InputPort", 0, counter);
  }
  return received;
}

TEST(LongPulseTest, AStepdancePortRejectsEveryLongPulseAsTooLong) {
  for (int64_t width_ns : kWidthsNs) {
    const Received got = run("ChainedPlotterDriver.ino", width_ns, "long_pulse_stepdance");
    ASSERT_EQ(got.sent.accepted(), kPulses) << width_ns;
    EXPECT_EQ(got.host_decoded.too_long, kPulses) << width_ns << " ns";
    EXPECT_EQ(got.host_decoded.accepted(), 0u) << width_ns << " ns";
    EXPECT_EQ(got.port_too_long, kPulses) << width_ns << " ns";
    EXPECT_EQ(got.port_accepted, 0u) << width_ns << " ns";
  }
}

TEST(LongPulseTest, AStepDirPortCountsEveryLongPulseAsOneStep) {
  const std::string receiver = source_path("tests/sim/assembly/fixtures/StepDirReceiver/StepDirReceiver.ino");
  for (int64_t width_ns : kWidthsNs) {
    const Received got = run(receiver, width_ns, "long_pulse_step_dir");
    ASSERT_EQ(got.sent.accepted(), kPulses) << width_ns;
    EXPECT_EQ(got.host_decoded.accepted(), kPulses) << width_ns << " ns";
    EXPECT_EQ(got.host_decoded.too_long, 0u) << width_ns << " ns";
    EXPECT_EQ(got.port_accepted, kPulses) << width_ns << " ns";
    EXPECT_EQ(got.port_too_long, 0u) << width_ns << " ns";
  }
}

}  // namespace
}  // namespace stepdance::sim::test
