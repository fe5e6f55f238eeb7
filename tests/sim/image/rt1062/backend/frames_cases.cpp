// The Teensy backend's own frame engine (flexio3.cpp, frame_timer.cpp, output_ports.cpp, as
// compiled for the register model) running on the FLEXIO3 model: the frame clock it configures
// must tick every 40 µs, a staged step must leave at the next tick with the frame encoder's words,
// and a commit that comes too late must go out whole at no tick at all. Expected numbers: the
// frame period and guard of docs/hardware-backend.md, the encoder's words, the RM's IRQ numbers.
#include <gtest/gtest.h>

#include <vector>

#include "backend_rig.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/frame_diagnostics.hpp"
#include "stepdance/platform/teensy/timers.hpp"
#include "stepdance/protocol/frame_encoder.hpp"

namespace {

namespace hal = stepdance::hal;
namespace teensy = stepdance::platform::teensy;
using stepdance::Status;
using stepdance::sim::SimTime;

constexpr unsigned kTickIrq = 156;   // RM table 4-2: FLEXIO3
constexpr unsigned kFrameIrq = 155;  // the reserved line the backend pends for the frame ISR
constexpr SimTime kPeriodNs = 40000;

// What the frame ISR does in each test: stage one forward X step in frame `step_frame`, after
// spinning until `spin_to_ns` past the tick that started that frame.
struct Script {
  int frame = 0;
  int step_frame = -1;
  SimTime spin_to_ns = 0;
  std::vector<SimTime> isr_times;
};
Script script;

stepdance::protocol::FrameWords step_words() {
  return stepdance::protocol::encode_frame(stepdance::protocol::FrameRequest{1, 1, 0}).words;
}

void on_frame() {
  backend_rig::World& w = backend_rig::world();
  script.isr_times.push_back(w.chip.now_ns());
  if (script.frame == script.step_frame) {
    if (script.spin_to_ns > 0) backend_rig::spin_until(w.io.frames.back().start_ns + script.spin_to_ns);
    hal::port_out_frame(0, step_words());
  }
  ++script.frame;
}

class BackendFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    backend_rig::reset();
    // All four output ports: their shifters' FLEXIO3 pins must reach ports A–D (pads 23/22,
    // 21/20 on AD_B1, 37/36 and 35/34 on B1).
    static const bool begun = hal::port_out_begin(0) == Status::kOk && hal::port_out_begin(1) == Status::kOk &&
                              hal::port_out_begin(2) == Status::kOk && hal::port_out_begin(3) == Status::kOk;
    ASSERT_TRUE(begun) << "ports A–D claimed on FLEXIO3";
    script = Script{};
    before_ = teensy::frame_diagnostics();
  }
  void TearDown() override { teensy::frame_timer_stop(); }
  // The frames launched on `port`.
  static std::vector<stepdance::sim::image::testing::PortFrame> frames_of(uint8_t port) {
    std::vector<stepdance::sim::image::testing::PortFrame> frames;
    for (const auto& frame : backend_rig::world().io.frames) {
      if (frame.port == port) frames.push_back(frame);
    }
    return frames;
  }
  // Indices of port A's frames with any bit set, and whether any other port had one.
  std::vector<size_t> busy_frames() const {
    std::vector<size_t> busy;
    const auto frames = frames_of(0);
    for (size_t i = 0; i < frames.size(); ++i) {
      if (frames[i].words.step_bits != 0 || frames[i].words.dir_bits != 0) busy.push_back(i);
    }
    for (const auto& frame : backend_rig::world().io.frames) {
      if (frame.port != 0 && (frame.words.step_bits != 0 || frame.words.dir_bits != 0)) busy.push_back(999);
    }
    return busy;
  }
  teensy::FrameDiagnostics before_{};
};

TEST_F(BackendFrames, TheFrameClockTicksEvery40MicrosecondsAndAStepLeavesAtTheNextTick) {
  script.step_frame = 2;
  const uint64_t ticks_before = backend_rig::taken(kTickIrq);
  ASSERT_EQ(hal::frame_timer_start(40, on_frame), Status::kOk) << "the first tick must arrive";
  backend_rig::idle_for(10 * kPeriodNs);
  const auto frames = frames_of(0);
  ASSERT_GE(frames.size(), 10u);
  for (size_t i = 1; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].start_ns - frames[i - 1].start_ns, kPeriodNs) << i;
    EXPECT_EQ(frames[i].frame_ns, kPeriodNs);
  }
  for (uint8_t port = 1; port < 4; ++port) {  // every port launches at the same ticks
    const auto others = frames_of(port);
    ASSERT_EQ(others.size(), frames.size()) << int(port);
    EXPECT_EQ(others.back().start_ns, frames.back().start_ns) << int(port);
  }
  // One tick ISR and one frame ISR per launch, each frame ISR within a microsecond of its tick.
  EXPECT_EQ(backend_rig::taken(kTickIrq) - ticks_before, frames.size());
  ASSERT_EQ(script.isr_times.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_GT(script.isr_times[i], frames[i].start_ns);
    EXPECT_LT(script.isr_times[i], frames[i].start_ns + 1000) << i;
  }
  // Staged in frame 2 (after tick 2), launched at tick 3, once, with the encoder's words.
  ASSERT_EQ(busy_frames(), std::vector<size_t>{3});
  EXPECT_EQ(frames[3].words.step_bits, step_words().step_bits);
  EXPECT_EQ(frames[3].words.dir_bits, step_words().dir_bits);
  const teensy::FrameDiagnostics after = teensy::frame_diagnostics();
  EXPECT_EQ(after.late_frames - before_.late_frames, 0u);
  EXPECT_EQ(after.ticks_without_frame - before_.ticks_without_frame, 0u);
  EXPECT_GT(backend_rig::taken(kFrameIrq), 0u);
}

TEST_F(BackendFrames, ACommitJustBeforeTheGuardStillGoesOut) {
  script.step_frame = 1;
  script.spin_to_ns = 36000;  // 4 µs before the next tick: outside the 3 µs guard
  ASSERT_EQ(hal::frame_timer_start(40, on_frame), Status::kOk);
  backend_rig::idle_for(5 * kPeriodNs);
  ASSERT_EQ(busy_frames(), std::vector<size_t>{2});
  EXPECT_EQ(teensy::frame_diagnostics().late_frames - before_.late_frames, 0u);
}

TEST_F(BackendFrames, ACommitInsideTheGuardIsDroppedWhole) {
  script.step_frame = 1;
  script.spin_to_ns = 37500;  // 2.5 µs before the next tick: inside the guard
  ASSERT_EQ(hal::frame_timer_start(40, on_frame), Status::kOk);
  backend_rig::idle_for(5 * kPeriodNs);
  EXPECT_TRUE(busy_frames().empty()) << "a late frame is never sent, late or at all";
  EXPECT_EQ(teensy::frame_diagnostics().late_frames - before_.late_frames, 1u);
}

TEST_F(BackendFrames, AFrameOverrunningTheTickIsDroppedAndCounted) {
  script.step_frame = 1;
  script.spin_to_ns = 41000;  // past the next tick (the tick ISR preempts the frame ISR)
  ASSERT_EQ(hal::frame_timer_start(40, on_frame), Status::kOk);
  backend_rig::idle_for(5 * kPeriodNs);
  EXPECT_TRUE(busy_frames().empty());
  EXPECT_EQ(teensy::frame_diagnostics().late_frames - before_.late_frames, 1u);
}

}  // namespace
