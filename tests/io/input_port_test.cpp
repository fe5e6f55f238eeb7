// InputPort: pulse decoding through the capture sink, statistics, modes and the ISR/frame hand-off.
#include "stepdance/io/input_port.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/boards/board.hpp"
#include "stepdance/core/dance.hpp"
#include "support/collector_block.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

using protocol::CapturedPulse;
using protocol::DirSampleEdge;

// The manual backend's capture clock runs at 150 ticks per µs.
constexpr uint32_t kTicksPerUs = 150;

CapturedPulse pulse_ticks(uint32_t width_ticks, bool forward, uint32_t rise_ticks = 1000) {
  return CapturedPulse{rise_ticks, (rise_ticks + width_ticks) & 0xFFFFu, forward};
}

// A pulse of the width that encodes `signal` (2 µs for X ... 7 µs for E).
CapturedPulse signal_pulse(uint8_t signal, bool forward) { return pulse_ticks((2u + signal) * kTicksPerUs, forward); }

void inject(const CapturedPulse& pulse, int times = 1) {
  for (int i = 0; i < times; ++i) ASSERT_TRUE(hal_manual::inject_pulse(INPUT_A, pulse));
}

using test_support::Collector;

// A pre-channel block that injects one X-forward pulse per frame while `remaining` > 0,
// i.e. after the input-port stage of that frame has already taken its snapshot.
class MidFrameInjector : public Block {
 public:
  void begin(int frames) {
    remaining = frames;
    register_in(Stage::kPreChannel);
  }
  void run() override {
    if (remaining == 0) return;
    --remaining;
    hal_manual::inject_pulse(INPUT_A, signal_pulse(SIGNAL_X, true));
  }
  int remaining = 0;
};

void inject_x_forward() { hal_manual::inject_pulse(INPUT_A, signal_pulse(SIGNAL_X, true)); }

class InputPortTest : public test_support::EngineFixture {
 protected:
  void TearDown() override {
    select_board(kDriverModuleV1);
    EngineFixture::TearDown();
  }
};

TEST_F(InputPortTest, EachWidthDrivesItsAxisInTheSampledDirection) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(hal_manual::input_edge(INPUT_A), DirSampleEdge::kFalling);

  // X +1, Y −2, R +3, T −1, Z +2, E −3.
  inject(signal_pulse(SIGNAL_X, true));
  inject(signal_pulse(SIGNAL_Y, false), 2);
  inject(signal_pulse(SIGNAL_R, true), 3);
  inject(signal_pulse(SIGNAL_T, false));
  inject(signal_pulse(SIGNAL_Z, true), 2);
  inject(signal_pulse(SIGNAL_E, false), 3);
  hal_manual::run_frames(1);

  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 1.0);
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), -2.0);
  EXPECT_DOUBLE_EQ(port.output_r.read(ABSOLUTE), 3.0);
  EXPECT_DOUBLE_EQ(port.output_t.read(ABSOLUTE), -1.0);
  EXPECT_DOUBLE_EQ(port.output_z.read(ABSOLUTE), 2.0);
  EXPECT_DOUBLE_EQ(port.output_e.read(ABSOLUTE), -3.0);
  EXPECT_EQ(port.pulses_received(SIGNAL_Y, DIRECTION_REVERSE), 2u);
  EXPECT_EQ(port.pulses_received(SIGNAL_Y, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(port.pulses_received(SIGNAL_R, DIRECTION_FORWARD), 3u);
  EXPECT_EQ(port.pulses_received(SIGNAL_E, DIRECTION_REVERSE), 3u);
  EXPECT_EQ(port.rejected_too_short(), 0u);
  EXPECT_EQ(port.rejected_too_long(), 0u);
  EXPECT_EQ(port.ignored(), 0u);
}

TEST_F(InputPortTest, WidthsRoundToTheNearestMicrosecondAndRejectionsAreCountedByReason) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);

  inject(pulse_ticks(225, true));   // 1.5 µs → 1 µs (ties round down): too short
  inject(pulse_ticks(226, true));   // 1.507 µs → 2 µs: X
  inject(pulse_ticks(375, true));   // 2.5 µs → 2 µs: X
  inject(pulse_ticks(376, true));   // 2.507 µs → 3 µs: Y
  inject(pulse_ticks(1125, true));  // 7.5 µs → 7 µs: E
  inject(pulse_ticks(1126, true));  // 7.507 µs → 8 µs: too long
  inject(pulse_ticks(0, true));     // no width at all: too short
  inject(pulse_ticks(3000, true));  // 20 µs: too long
  // The 16-bit capture counter wrapped between the edges: 65 400 → 164 is 300 ticks, an X.
  inject(CapturedPulse{65400, 164, false});
  hal_manual::run_frames(1);

  EXPECT_EQ(port.rejected_too_short(), 2u);
  EXPECT_EQ(port.rejected_too_long(), 2u);
  EXPECT_EQ(port.pulses_received(SIGNAL_X, DIRECTION_FORWARD), 2u);
  EXPECT_EQ(port.pulses_received(SIGNAL_X, DIRECTION_REVERSE), 1u);
  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 1.0);  // +2 −1
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), 1.0);
  EXPECT_DOUBLE_EQ(port.output_e.read(ABSOLUTE), 1.0);
}

// A pulse of `width_us` from a capture unit that counts counter wraps (what the Teensy backend
// and the simulator report): rises at 400 µs, near the first wrap at 436.9 µs.
CapturedPulse held_pulse(uint64_t width_us, bool forward) {
  const uint64_t rise = 400 * kTicksPerUs;
  return protocol::captured_from_ticks(rise, rise + width_us * kTicksPerUs, forward, protocol::CaptureClock{});
}

constexpr uint64_t kLongWidthsUs[] = {8, 437, 439, 1000, 1000000};  // 8 µs … 1 s

TEST_F(InputPortTest, LongPulsesAreTooLongInStepdanceModeWhateverTheirLength) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  for (uint64_t width_us : kLongWidthsUs) inject(held_pulse(width_us, true));
  hal_manual::run_frames(1);
  EXPECT_EQ(port.rejected_too_long(), 5u);
  EXPECT_EQ(port.rejected_too_short(), 0u);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    EXPECT_EQ(port.pulses_received(signal, DIRECTION_FORWARD), 0u) << int{signal};  // no phantom X
  }
  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 0.0);
}

TEST_F(InputPortTest, LongPulsesAreStepsInStepDirMode) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(port.set_input_mode(INPUT_MODE_STEP_DIR, SIGNAL_Z), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  for (uint64_t width_us : kLongWidthsUs) inject(held_pulse(width_us, width_us != 1000));
  hal_manual::run_frames(1);
  EXPECT_EQ(port.pulses_received(SIGNAL_Z, DIRECTION_FORWARD), 4u);
  EXPECT_EQ(port.pulses_received(SIGNAL_Z, DIRECTION_REVERSE), 1u);
  EXPECT_EQ(port.rejected_too_long(), 0u);
  EXPECT_DOUBLE_EQ(port.output_z.read(ABSOLUTE), 3.0);
}

TEST_F(InputPortTest, DisabledSignalsAreIgnoredAndCounted) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);

  port.disable_signal(SIGNAL_Y);
  EXPECT_FALSE(port.signal_enabled(SIGNAL_Y));
  inject(signal_pulse(SIGNAL_X, true), 2);
  inject(signal_pulse(SIGNAL_Y, true), 3);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 2.0);
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), 0.0);
  EXPECT_EQ(port.ignored(), 3u);
  EXPECT_EQ(port.pulses_received(SIGNAL_Y, DIRECTION_FORWARD), 0u);

  port.disable_all_signals();
  inject(signal_pulse(SIGNAL_E, false), 2);
  inject(signal_pulse(SIGNAL_X, true));
  port.enable_signal(SIGNAL_E);
  inject(signal_pulse(SIGNAL_E, false));
  hal_manual::run_frames(1);
  EXPECT_EQ(port.ignored(), 6u);
  EXPECT_DOUBLE_EQ(port.output_e.read(ABSOLUTE), -1.0);
  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 2.0);

  port.enable_all_signals();
  inject(signal_pulse(SIGNAL_Y, true));
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), 1.0);
  EXPECT_EQ(port.ignored(), 6u);
}

TEST_F(InputPortTest, StepDirModeSamplesDirOnTheRisingEdgeAndFeedsOneAxis) {
  InputPort port;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  ASSERT_EQ(port.set_input_mode(INPUT_MODE_STEP_DIR, SIGNAL_Z), Status::kOk);
  EXPECT_EQ(hal_manual::input_edge(INPUT_A), DirSampleEdge::kRising);
  EXPECT_EQ(port.input_mode(), INPUT_MODE_STEP_DIR);
  ASSERT_EQ(dance_start(), Status::kOk);

  inject(pulse_ticks(150, true));    // 1 µs: the shortest step accepted
  inject(pulse_ticks(450, true));    // 3 µs: would be Y in STEPDANCE mode, a Z step here
  inject(pulse_ticks(3000, false));  // 20 µs: any longer pulse is a step as well
  inject(pulse_ticks(75, true));     // 0.5 µs → 0 µs: a glitch, too short
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_z.read(ABSOLUTE), 1.0);  // +1 +1 −1
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), 0.0);
  EXPECT_EQ(port.pulses_received(SIGNAL_Z, DIRECTION_FORWARD), 2u);
  EXPECT_EQ(port.pulses_received(SIGNAL_Z, DIRECTION_REVERSE), 1u);
  EXPECT_EQ(port.rejected_too_short(), 1u);
  EXPECT_EQ(port.rejected_too_long(), 0u);

  ASSERT_EQ(port.set_input_mode(INPUT_MODE_STEPDANCE), Status::kOk);
  EXPECT_EQ(hal_manual::input_edge(INPUT_A), DirSampleEdge::kFalling);
  inject(pulse_ticks(450, true));
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_y.read(ABSOLUTE), 1.0);
}

TEST_F(InputPortTest, InputModeChosenBeforeBeginArmsTheRisingEdge) {
  InputPort port;
  ASSERT_EQ(port.set_input_mode(INPUT_MODE_STEP_DIR, SIGNAL_E), Status::kOk);
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  EXPECT_EQ(hal_manual::input_edge(INPUT_A), DirSampleEdge::kRising);
  EXPECT_EQ(port.set_input_mode(INPUT_MODE_STEP_DIR, 6), Status::kBadArgument);
  EXPECT_EQ(port.input_mode(), INPUT_MODE_STEP_DIR);
}

TEST_F(InputPortTest, RatioScalesEveryAxisAndEachAxisCanBeOverridden) {
  InputPort port;
  Collector x_sink;
  Collector y_sink;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  port.set_ratio(0.25);        // 0.25 world units per pulse on all six ports
  port.output_y.set_ratio(2);  // then 2 per pulse on Y only
  x_sink.begin();
  y_sink.begin();
  port.output_x.map(&x_sink.input);
  port.output_y.map(&y_sink.input);
  ASSERT_EQ(dance_start(), Status::kOk);

  inject(signal_pulse(SIGNAL_X, true), 6);
  inject(signal_pulse(SIGNAL_Y, false), 3);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_x.read(ABSOLUTE), 1.5);
  EXPECT_DOUBLE_EQ(port.output_x.read(INCREMENTAL), 1.5);
  EXPECT_DOUBLE_EQ(port.output_x.read_target(), 6.0);  // block units are pulses
  EXPECT_DOUBLE_EQ(x_sink.position, 1.5);
  EXPECT_DOUBLE_EQ(y_sink.position, -6.0);
  EXPECT_DOUBLE_EQ(port.output_r.ratio(), 0.25);

  hal_manual::run_frames(3);  // no new pulses: nothing more arrives downstream
  EXPECT_DOUBLE_EQ(x_sink.position, 1.5);
  EXPECT_DOUBLE_EQ(port.output_x.read(INCREMENTAL), 0.0);
}

TEST_F(InputPortTest, PulsesBetweenFramesArriveExactlyOnce) {
  InputPort port;
  Collector sink;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  sink.begin();
  port.output_x.map(&sink.input);
  ASSERT_EQ(dance_start(), Status::kOk);

  inject(signal_pulse(SIGNAL_X, true), 3);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_x.read(INCREMENTAL), 3.0);
  EXPECT_DOUBLE_EQ(sink.position, 3.0);
  inject(signal_pulse(SIGNAL_X, true), 2);
  inject(signal_pulse(SIGNAL_X, false), 7);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(port.output_x.read(INCREMENTAL), -5.0);
  EXPECT_DOUBLE_EQ(sink.position, -2.0);
  hal_manual::run_frames(2);
  EXPECT_DOUBLE_EQ(sink.position, -2.0);
}

TEST_F(InputPortTest, PulsesArrivingDuringAFrameAreDeliveredByTheNextFrame) {
  InputPort port;
  MidFrameInjector injector;
  Collector sink;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  injector.begin(10);  // injects in frames 1..10, after the input-port stage has run
  sink.begin();
  port.output_x.map(&sink.input);
  ASSERT_EQ(dance_start(), Status::kOk);

  // Frame k delivers the pulses of frames 1..k−1.
  for (int frame = 1; frame <= 10; ++frame) {
    hal_manual::run_frames(1);
    EXPECT_DOUBLE_EQ(sink.position, frame - 1.0) << "frame " << frame;
  }
  hal_manual::run_frames(5);
  EXPECT_DOUBLE_EQ(sink.position, 10.0);
  EXPECT_EQ(port.pulses_received(SIGNAL_X, DIRECTION_FORWARD), 10u);
}

TEST_F(InputPortTest, FrameFunctionsBeforeAndAfterTheStagesLoseNoPulse) {
  InputPort port;
  Collector sink;
  ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  sink.begin();
  port.output_x.map(&sink.input);
  // Added before dance_start(): runs ahead of the input-port stage, so counted the same frame.
  ASSERT_EQ(add_function_to_frame(&inject_x_forward), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(4);
  EXPECT_DOUBLE_EQ(sink.position, 4.0);

  // Added after dance_start(): runs after the post-channel stage, so counted one frame later.
  ASSERT_EQ(add_function_to_frame(&inject_x_forward), Status::kOk);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(sink.position, 5.0);  // + the early one; the late one waits
  hal_manual::run_frames(3);
  EXPECT_DOUBLE_EQ(sink.position, 11.0);  // 5 + 3 early + 3 late (the 4th late still pending)
  EXPECT_EQ(port.pulses_received(SIGNAL_X, DIRECTION_FORWARD), 12u);
}

TEST_F(InputPortTest, BasicModuleHasOnlyInputA) {
  select_board(kBasicModuleV1);
  InputPort a;
  InputPort b;
  InputPort d;
  EXPECT_EQ(b.begin(INPUT_B), Status::kNoSuchPin);
  EXPECT_EQ(d.begin(INPUT_D), Status::kNoSuchPin);
  EXPECT_EQ(a.begin(INPUT_A), Status::kOk);
  EXPECT_EQ(engine().count(Stage::kInputPorts), 1u);
}

TEST_F(InputPortTest, DriverModuleHasFourPortsAndRefusesLegacyOnes) {
  InputPort ports[4];
  for (uint8_t i = 0; i < 4; ++i) EXPECT_EQ(ports[i].begin(i), Status::kOk);
  InputPort legacy;
  EXPECT_EQ(legacy.begin(INPUT_B_LEGACY), Status::kNoSuchPin);
  EXPECT_EQ(engine().count(Stage::kInputPorts), 4u);
}

TEST_F(InputPortTest, ADestroyedPortStopsReceiving) {
  {
    InputPort port;
    ASSERT_EQ(port.begin(INPUT_A), Status::kOk);
  }
  // The HAL still calls the trampoline; it finds no receiver and does nothing.
  EXPECT_TRUE(hal_manual::inject_pulse(INPUT_A, signal_pulse(SIGNAL_X, true)));
  EXPECT_EQ(engine().count(Stage::kInputPorts), 0u);
}

}  // namespace
}  // namespace stepdance
