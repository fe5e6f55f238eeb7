// The Teensy hardening fixes (issue 16, item 4), checked on the host against the register model:
// the backend's own code runs with every register access redirected to teensy_model (see
// register_model.hpp), and the tests play the hardware (frame clock edges, flags, calibration).
// Expected values are the reference manual's addresses and bits, not the backend's constants.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "register_model.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/frame_diagnostics.hpp"
#include "stepdance/platform/teensy/timers.hpp"

namespace {

using teensy_model::Access;

// ---- Addresses and bits from the RM (i.MX RT1060 Processor Reference Manual) ----------------
constexpr uint32_t kFlexio3 = 0x42020000u;        // §50.5 FLEXIO3 base
constexpr uint32_t kTimstat = kFlexio3 + 0x018u;  // FLEXIO_TIMSTAT
constexpr uint32_t shiftbuf(unsigned n) { return kFlexio3 + 0x200u + 4u * n; }
constexpr uint32_t timctl(unsigned n) { return kFlexio3 + 0x400u + 4u * n; }
constexpr uint32_t kMarkerFlag = 1u << 5;            // timer 5: the tick marker
constexpr uint32_t kGuardFlag = 1u << 6;             // timer 6: the commit guard
constexpr uint32_t kIspr4 = 0xE000E210u;             // NVIC_ISPR4: IRQs 128..159
constexpr uint32_t kIcpr4 = 0xE000E290u;             // NVIC_ICPR4
constexpr uint32_t kFrameIrq = 155, kTickIrq = 156;  // reserved line, FLEXIO3
constexpr uint32_t kTickPriority = 16;               // docs/hardware-backend.md table
constexpr uint32_t kCyclesPerUs = teensy_model::kCoreHz / 1000000u;

// ---- The frame clock as the hardware runs it ------------------------------------------------
struct Launch {
  uint32_t step[4];
  uint32_t dir[4];
};
std::vector<Launch> launches;

// A rising edge of the frame clock: every port timer loads its shifters' buffers (what goes out
// on the wire), and the tick marker raises its flag.
void edge() {
  Launch launch{};
  for (unsigned port = 0; port < 4; ++port) {
    launch.step[port] = teensy_model::peek(shiftbuf(port));
    launch.dir[port] = teensy_model::peek(shiftbuf(port + 4));
  }
  launches.push_back(launch);
  teensy_model::poke(kTimstat, teensy_model::peek(kTimstat) | kMarkerFlag);
}

// The NVIC: runs the tick ISR if its flag is up, then the frame ISR if it is pending.
void run_pending() {
  if (teensy_model::peek(kTimstat) & kMarkerFlag) teensy_model::run_isr(kTickIrq);
  const uint32_t frame_bit = 1u << (kFrameIrq % 32);
  if (teensy_model::peek(kIspr4) & frame_bit) {
    teensy_model::poke(kIspr4, teensy_model::peek(kIspr4) & ~frame_bit);
    teensy_model::run_isr(kFrameIrq);
  }
}

void install_frame_hardware() {
  teensy_model::reset();
  launches.clear();
  teensy_model::write_one_to_clear(kTimstat);
  teensy_model::on_write(kIspr4, [](uint32_t stored, uint32_t written) { return stored | written; });
  teensy_model::on_write(kIcpr4, [](uint32_t, uint32_t written) {
    teensy_model::poke(kIspr4, teensy_model::peek(kIspr4) & ~written);
    return 0u;
  });
  // Enabling the frame clock (TIMOD != 0) makes its output rise at once: the first tick.
  teensy_model::on_write(timctl(4), [](uint32_t, uint32_t written) {
    if (written & 3u) {
      edge();
      teensy_model::run_isr(kTickIrq);
    }
    return written;
  });
}

constexpr stepdance::protocol::FrameWords kWordsA{0x0000000Cu, 0x0000000Eu};
constexpr stepdance::protocol::FrameWords kWordsB{0x000000C0u, 0x000000E0u};
void (*during_stages)() = nullptr;

void stage_both_ports() {
  stepdance::hal::port_out_frame(0, kWordsA);
  stepdance::hal::port_out_frame(1, kWordsB);
  if (during_stages != nullptr) during_stages();
}

// Claims ports A and B, starts 40 µs frames and runs the first frame ISR (the stages, the commit).
void start_and_run_first_frame() {
  ASSERT_EQ(stepdance::hal::port_out_begin(0), stepdance::Status::kOk);
  ASSERT_EQ(stepdance::hal::port_out_begin(1), stepdance::Status::kOk);
  ASSERT_EQ(stepdance::hal::frame_timer_start(40, &stage_both_ports), stepdance::Status::kOk);
  run_pending();
}

bool written_during_commit(uint32_t address, uint32_t value, Access& found) {
  for (const Access& access : teensy_model::log()) {
    if (access.kind == Access::kWrite && access.address == address && access.value == value) {
      found = access;
      return true;
    }
  }
  return false;
}

// ---- 1. SION on the capture pads ------------------------------------------------------------
void ignore_pulse(void*, const stepdance::protocol::CapturedPulse&) {}

TEST(TeensyHardening, CapturePadsSetSionWithTheirAlt) {
  teensy_model::reset();
  // SW_MUX_CTL_PAD_GPIO_<pad> (RM §11.7): EMC_06, EMC_08, B1_00, B0_11; MUX_MODE = ALT, SION = bit 4.
  const uint32_t mux[4] = {0x401F802Cu, 0x401F8034u, 0x401F817Cu, 0x401F8168u};
  const uint32_t alt[4] = {1, 1, 6, 2};
  for (uint8_t port = 0; port < 4; ++port) {
    ASSERT_EQ(stepdance::hal::port_in_begin(port, stepdance::protocol::DirSampleEdge::kFalling, &ignore_pulse, nullptr),
              stepdance::Status::kOk);
    EXPECT_EQ(teensy_model::peek(mux[port]), alt[port] | (1u << 4)) << "input port " << int{port};
  }
}

// ---- 2. BASEPRI, not PRIMASK, around the commit ----------------------------------------------
TEST(TeensyHardening, CommitMasksTheTickByBasepriAndLeavesCapturesRunning) {
  install_frame_hardware();
  start_and_run_first_frame();
  Access step_a{}, step_b{};
  ASSERT_TRUE(written_during_commit(shiftbuf(0), kWordsA.step_bits, step_a));
  ASSERT_TRUE(written_during_commit(shiftbuf(1), kWordsB.step_bits, step_b));
  for (const Access& write : {step_a, step_b}) {
    EXPECT_EQ(write.primask, 0u) << "PRIMASK would hold back the priority-0 capture ISRs";
    EXPECT_NE(write.basepri, 0u) << "the tick ISR must be masked while the commit writes";
    EXPECT_LE(write.basepri, kTickPriority) << "BASEPRI must mask the tick ISR (priority 16)";
  }
  EXPECT_EQ(teensy_model::basepri(), 0u) << "the mask is lifted after the commit";
  EXPECT_EQ(teensy_model::primask(), 0u);
}

// ---- 3. A late frame: every port or none, and counted ----------------------------------------
TEST(TeensyHardening, OnTimeFrameGoesOutOnEveryPort) {
  install_frame_hardware();
  start_and_run_first_frame();
  EXPECT_EQ(teensy_model::peek(shiftbuf(0)), kWordsA.step_bits);
  EXPECT_EQ(teensy_model::peek(shiftbuf(4)), kWordsA.dir_bits);
  EXPECT_EQ(teensy_model::peek(shiftbuf(1)), kWordsB.step_bits);
  EXPECT_EQ(teensy_model::peek(shiftbuf(5)), kWordsB.dir_bits);
  EXPECT_EQ(stepdance::platform::teensy::frame_diagnostics().late_frames, 0u);
}

TEST(TeensyHardening, FrameWhoseTickPassedIsSkippedOnEveryPortAndCounted) {
  install_frame_hardware();
  during_stages = [] { edge(); };  // the stages overran: tick k+1 came (its ISR is held back)
  start_and_run_first_frame();
  during_stages = nullptr;
  for (unsigned buffer : {0u, 1u, 4u, 5u}) EXPECT_EQ(teensy_model::peek(shiftbuf(buffer)), 0u) << buffer;
  EXPECT_EQ(stepdance::platform::teensy::frame_diagnostics().late_frames, 1u);
}

TEST(TeensyHardening, TickDuringTheWritesNeverSplitsAFrameAcrossPorts) {
  install_frame_hardware();
  // The stages end inside the last few µs before the next tick (the commit guard timer has fired),
  // and the tick lands right after port A's STEP buffer is written.
  during_stages = [] {
    teensy_model::poke(kTimstat, teensy_model::peek(kTimstat) | kGuardFlag);
    teensy_model::on_write(shiftbuf(0), [](uint32_t, uint32_t written) {
      teensy_model::poke(shiftbuf(0), written);
      edge();
      return written;
    });
  };
  start_and_run_first_frame();
  during_stages = nullptr;
  ASSERT_GE(launches.size(), 1u);
  for (const Launch& launch : launches) {
    const bool a_sent = launch.step[0] == kWordsA.step_bits;
    const bool b_sent = launch.step[1] == kWordsB.step_bits;
    EXPECT_EQ(a_sent, b_sent) << "a frame went out on one port and not the other";
  }
  // Nothing of this frame may wait in a buffer for the tick after (it would go out late).
  EXPECT_NE(teensy_model::peek(shiftbuf(0)), kWordsA.step_bits);
  EXPECT_NE(teensy_model::peek(shiftbuf(1)), kWordsB.step_bits);
  EXPECT_EQ(stepdance::platform::teensy::frame_diagnostics().late_frames, 1u);
}

// ---- 4. Exact restart ------------------------------------------------------------------------
void no_stages() {}

TEST(TeensyHardening, QuickRestartWaitsAFullPeriodAfterTheStop) {
  install_frame_hardware();
  ASSERT_EQ(stepdance::hal::port_out_begin(0), stepdance::Status::kOk);
  ASSERT_EQ(stepdance::hal::frame_timer_start(40, &no_stages), stepdance::Status::kOk);
  teensy_model::advance_cycles(5 * kCyclesPerUs);  // stop 5 µs after the first tick: port A still shifts
  stepdance::platform::teensy::frame_timer_stop();
  const uint64_t stopped = teensy_model::now_cycles();
  ASSERT_EQ(stepdance::hal::frame_timer_start(40, &no_stages), stepdance::Status::kOk);
  uint64_t enabled_at = 0;
  for (const Access& access : teensy_model::log()) {
    if (access.kind == Access::kWrite && access.address == timctl(4) && (access.value & 3u)) enabled_at = access.cycles;
  }
  // The last launch was at or before the stop; the first new one must be a full period (40 µs)
  // later, so the 32 µs transmission has ended and no two launches are closer than the period.
  EXPECT_GE(enabled_at, stopped + 40u * kCyclesPerUs);
  EXPECT_EQ(launches.size(), 2u);
}

// ---- 5. ADC calibration: once, and never on top of a running one ---------------------------
struct AdcWatch {
  int core_calibration_reads_left = 5;  // Teensyduino's boot calibration is still running
  int our_calibration_reads_left = 0;
  int calibrations_started = 0;
  int writes_during_core_calibration = 0;
  bool conversion_stopped_before_calibration = false;
};
AdcWatch adc1;

TEST(TeensyHardening, AdcCalibratesOnceAndOnlyAfterTheCoresCalibrationEnded) {
  teensy_model::reset();
  adc1 = AdcWatch{};
  constexpr uint32_t kAdc1 = 0x400C4000u;  // RM ADC chapter: ADC1 base
  constexpr uint32_t kHc0 = kAdc1 + 0x00u, kCfg = kAdc1 + 0x44u, kGc = kAdc1 + 0x48u, kGs = kAdc1 + 0x4Cu;
  constexpr uint32_t kCal = 1u << 7;      // ADC_GC CAL
  teensy_model::write_one_to_clear(kGs);  // ADC_GS CALF is write-1-to-clear
  teensy_model::poke(kGc, kCal);
  teensy_model::on_read(kGc, [](uint32_t stored) {
    int& left =
        adc1.core_calibration_reads_left > 0 ? adc1.core_calibration_reads_left : adc1.our_calibration_reads_left;
    if (left > 0 && --left == 0) stored &= ~kCal;  // the calibration finishes
    teensy_model::poke(kGc, stored);
    return stored;
  });
  teensy_model::on_write(kGc, [](uint32_t, uint32_t written) {
    if (adc1.core_calibration_reads_left > 0) ++adc1.writes_during_core_calibration;
    if (written & kCal) {
      ++adc1.calibrations_started;
      adc1.our_calibration_reads_left = 3;
    }
    return written;
  });
  teensy_model::on_write(kCfg, [](uint32_t, uint32_t written) {
    if (adc1.core_calibration_reads_left > 0) ++adc1.writes_during_core_calibration;
    return written;
  });
  teensy_model::on_write(kHc0, [](uint32_t, uint32_t written) {
    if ((written & 0x1Fu) == 0x1Fu && adc1.calibrations_started == 0) adc1.conversion_stopped_before_calibration = true;
    return written;
  });
  // Pins 16 and 17 are ADC1 channels 12 and 11 (Teensy 4.x schematic).
  ASSERT_EQ(stepdance::hal::adc_begin(16), stepdance::Status::kOk);
  ASSERT_EQ(stepdance::hal::adc_begin(17), stepdance::Status::kOk);
  EXPECT_EQ(adc1.writes_during_core_calibration, 0) << "CFG/GC changed while the core's calibration ran";
  EXPECT_TRUE(adc1.conversion_stopped_before_calibration) << "a conversion in progress must be stopped (ADCH = 31)";
  EXPECT_EQ(adc1.calibrations_started, 1);
}

// ---- 7. analogWrite on a pin sharing an input port's PWM submodule --------------------------
struct SharedPin {
  uint8_t port;
  uint32_t mux;             // SW_MUX_CTL_PAD of the shared pin (RM §11.7)
  uint32_t alt;             // its FlexPWM function (Teensy 4.x PWM pin list)
  uint32_t submodule_base;  // RM §55.8: PWMn base + 0x60 × submodule
};

TEST(TeensyHardening, InputPortRefusesWhenAnalogWriteOwnsItsSubmodule) {
  const SharedPin shared[] = {
      {0, 0x401F8030u, 1, 0x403E0000u + 0x60u * 0},  // pin 33 = EMC_07, FlexPWM2_0_B
      {2, 0x401F8180u, 6, 0x403DC000u + 0x60u * 3},  // pin 7 = B1_01, FlexPWM1_3_B
      {2, 0x401F80F0u, 4, 0x403DC000u + 0x60u * 3},  // pin 25 = AD_B0_13, FlexPWM1_3_X
      {3, 0x401F8164u, 2, 0x403E0000u + 0x60u * 2},  // pin 6 = B0_10, FlexPWM2_2_A
  };
  for (const SharedPin& pin : shared) {
    teensy_model::reset();
    stepdance::clear_fault();
    teensy_model::poke(pin.mux, pin.alt);  // what Teensyduino's analogWrite leaves in the pad
    EXPECT_EQ(
        stepdance::hal::port_in_begin(pin.port, stepdance::protocol::DirSampleEdge::kFalling, &ignore_pulse, nullptr),
        stepdance::Status::kBusy);
    for (const Access& access : teensy_model::log()) {
      const bool in_submodule = access.address >= pin.submodule_base && access.address < pin.submodule_base + 0x60u;
      EXPECT_FALSE(access.kind == Access::kWrite && in_submodule) << "the refused port touched its submodule";
    }
    stepdance::FaultReport report;
    ASSERT_TRUE(stepdance::recent_fault_report(0, report));
    EXPECT_EQ(report.reason, stepdance::FaultReason::kBadConfiguration);
    EXPECT_NE(std::strstr(report.detail, "analogWrite"), nullptr);
  }
  // The same pins as plain GPIO (pin 7 is input port B's DIR) do not block the port.
  teensy_model::reset();
  teensy_model::poke(0x401F8180u, 5u | (1u << 4));
  EXPECT_EQ(stepdance::hal::port_in_begin(2, stepdance::protocol::DirSampleEdge::kFalling, &ignore_pulse, nullptr),
            stepdance::Status::kOk);
}

}  // namespace
