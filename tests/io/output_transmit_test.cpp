// OutputPort transmission count: every port puts exactly one frame on the wire per engine frame,
// whoever asks for it (the engine's output-port stage, transmit_frames_on_all_output_ports(), or
// a sketch's own transmit_frame()). Two frames in one period would overlap on the wire.
#include "stepdance/io/output_port.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

class OutputTransmitTest : public test_support::EngineFixture {};

// Ports the frame functions below reach (a frame function takes no argument).
OutputPort* g_manual = nullptr;
OutputPort* g_on_frame = nullptr;

void transmit_all() { transmit_frames_on_all_output_ports(); }
void transmit_manual_twice() {
  g_manual->transmit_frame();
  g_manual->transmit_frame();
}
void transmit_on_frame_port() { g_on_frame->transmit_frame(); }

constexpr uint32_t kFrames = 10;  // the wire must carry exactly this many frames per port

// Runs kFrames frames with `function` added before dance_start() (it then runs ahead of the
// stages) or after it (behind them).
void run_with(void (*function)(), bool ahead_of_stages) {
  if (ahead_of_stages) {
    ASSERT_EQ(add_function_to_frame(function), Status::kOk);
  }
  ASSERT_EQ(dance_start(), Status::kOk);
  if (!ahead_of_stages) {
    ASSERT_EQ(add_function_to_frame(function), Status::kOk);
  }
  hal_manual::run_frames(kFrames);
}

TEST_F(OutputTransmitTest, TransmitAllFromAFrameFunctionSendsEachPortOnceAFrame) {
  for (const bool ahead : {true, false}) {
    test_support::reset_global_state();
    OutputPort on_frame;
    OutputPort manual;
    ASSERT_EQ(on_frame.begin(OUTPUT_A), Status::kOk);
    ASSERT_EQ(manual.begin(OUTPUT_B, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
    run_with(&transmit_all, ahead);
    EXPECT_EQ(hal_manual::frames_written(OUTPUT_A), kFrames) << (ahead ? "ahead" : "behind");
    EXPECT_EQ(hal_manual::frames_written(OUTPUT_B), kFrames) << (ahead ? "ahead" : "behind");
  }
}

TEST_F(OutputTransmitTest, OnFramePortPulsesLeaveOneAFrameWhateverTheSketchCalls) {
  OutputPort on_frame;
  ASSERT_EQ(on_frame.begin(OUTPUT_A), Status::kOk);
  g_on_frame = &on_frame;
  for (int i = 0; i < 3; ++i) on_frame.add_signal(SIGNAL_X, DIRECTION_FORWARD);
  ASSERT_EQ(add_function_to_frame(&transmit_all), Status::kOk);
  ASSERT_EQ(add_function_to_frame(&transmit_on_frame_port), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  // One X pulse a frame (spec "Frames": a signal occurs at most once in a frame): 1, 2, 3.
  for (uint32_t frame = 1; frame <= 3; ++frame) {
    hal_manual::run_frames(1);
    EXPECT_EQ(on_frame.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), frame);
    EXPECT_EQ(hal_manual::frames_written(OUTPUT_A), frame);
  }
  EXPECT_EQ(on_frame.transmits_refused(), 3u);  // the sketch's own call, once a frame
}

TEST_F(OutputTransmitTest, ManualPortTransmitsAtMostOnceAFrame) {
  OutputPort manual;
  ASSERT_EQ(manual.begin(OUTPUT_B, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  g_manual = &manual;
  run_with(&transmit_manual_twice, false);
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_B), kFrames);
  EXPECT_EQ(manual.transmits_refused(), kFrames);
}

TEST_F(OutputTransmitTest, StoppedEngineLeavesTransmissionToTheSketch) {
  OutputPort on_frame;
  OutputPort manual;
  ASSERT_EQ(on_frame.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(manual.begin(OUTPUT_B, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  for (int i = 0; i < 4; ++i) transmit_frames_on_all_output_ports();
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_A), 4u);
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_B), 4u);
  EXPECT_EQ(on_frame.transmits_refused(), 0u);
}

// begin() again (on another port) in manual mode takes the object out of the engine's output
// stage: otherwise the engine and the sketch would both send it.
TEST_F(OutputTransmitTest, BegunAgainInManualModeTheEngineNoLongerSendsIt) {
  OutputPort port;
  ASSERT_EQ(port.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(port.begin(OUTPUT_B, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  EXPECT_EQ(engine().count(Stage::kOutputPorts), 0u);
  run_with(&transmit_all, false);
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_B), kFrames);
}

}  // namespace
}  // namespace stepdance
