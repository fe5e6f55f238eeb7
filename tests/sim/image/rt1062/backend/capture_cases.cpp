// The Teensy backend's own input capture (input_capture.cpp, register-model build) on the eFlexPWM
// model: port_in_begin() programs PWM2 SM0 for port A, a pulse delivered the way the lead will
// deliver it (InputCapture::pulse_arrived at the falling edge) runs the backend's capture ISR,
// and its sink gets the pulse: width 150 ticks per µs (the IPG clock, StepdanceCapturedPulseV1),
// DIR from the GPIO the ISR reads.
#include <gtest/gtest.h>

#include <vector>

#include "backend_rig.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace {

namespace hal = stepdance::hal;
namespace protocol = stepdance::protocol;
using stepdance::Status;
using stepdance::sim::ArrivingPulse;
using stepdance::sim::SimTime;

std::vector<protocol::CapturedPulse> pulses;
void sink(void*, const protocol::CapturedPulse& pulse) { pulses.push_back(pulse); }

// Port A's DIR is Teensy pin 6 = GPIO_B0_10: fast GPIO7 (GPIO2's twin) bit 10, PSR at +0x08.
void set_dir_a(bool high) {
  auto& psr = backend_rig::world().gpio[1].registers[0x08];
  psr = high ? (psr | (1u << 10)) : (psr & ~(1u << 10));
}

class BackendCapture : public ::testing::Test {
 protected:
  void SetUp() override {
    backend_rig::reset();
    static const bool begun = hal::port_in_begin(0, protocol::DirSampleEdge::kFalling, sink, nullptr) == Status::kOk;
    ASSERT_TRUE(begun);
    pulses.clear();
  }
  void deliver(SimTime width_ns, bool dir_high) {
    auto& w = backend_rig::world();
    set_dir_a(dir_high);
    const SimTime rise = w.chip.now_ns() + 5000;
    const SimTime fall = rise + width_ns;
    backend_rig::idle_for(fall - w.chip.now_ns());
    w.blocks->capture().pulse_arrived(0, ArrivingPulse{rise, fall, dir_high, dir_high});
    backend_rig::idle_for(2000);  // the capture ISR runs
  }
};

TEST_F(BackendCapture, APulseOfWMicrosecondsReachesTheSinkAs150WTicks) {
  const protocol::CaptureClock clock = hal::port_in_clock(0);
  EXPECT_EQ(clock.ticks_per_us, 150u);
  for (int width_us : {2, 3, 7, 20}) {
    pulses.clear();
    deliver(width_us * 1000, width_us % 2 == 1);
    ASSERT_EQ(pulses.size(), 1u) << width_us;
    EXPECT_EQ(protocol::width_ticks(pulses[0], clock), 150u * width_us);
    EXPECT_EQ(pulses[0].dir_high, width_us % 2 == 1);
  }
  EXPECT_GT(backend_rig::taken(137), 0u);  // PWM2 SM0 (RM table 4-2)
}

TEST_F(BackendCapture, APulseLongerThanTheCounterPeriodKeepsItsWholePeriods) {
  // 600 µs = 90000 ticks: one 65536-tick wrap inside. Delivered edge by edge (the rise first).
  auto& w = backend_rig::world();
  set_dir_a(true);
  const SimTime rise = w.chip.now_ns() + 5000;
  w.blocks->capture().pulse_arrived(0, ArrivingPulse{rise, rise + 600000, true, true});
  backend_rig::idle_for(rise + 602000 - w.chip.now_ns());
  ASSERT_EQ(pulses.size(), 1u);
  EXPECT_EQ(protocol::width_ticks(pulses[0], hal::port_in_clock(0)), 90000u);
  EXPECT_EQ(pulses[0].extra_periods, 1u);
}

}  // namespace
