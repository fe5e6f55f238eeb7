// FLEXIO3 driven register by register as the Teensy backend's flexio3.cpp drives it. Expected
// values come from the reference manual (IMXRT1060RM rev 3, chapter 50: register layout, timer
// and shifter behaviour), the protocol's frame layout and the frame encoder, not from the model.
#include "image/rt1062/flexio3.hpp"

#include <gtest/gtest.h>

#include "motion_fakes.hpp"
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::sim::image {
namespace {

using testing::Rig;

// ---- RM §50.5.1: FLEXIO3 registers and fields ----
constexpr uint32_t kBase = 0x42020000u;
constexpr uint32_t kCtrl = kBase + 0x008u;
constexpr uint32_t kShiftstat = kBase + 0x010u;
constexpr uint32_t kShifterr = kBase + 0x014u;
constexpr uint32_t kTimstat = kBase + 0x018u;
constexpr uint32_t kTimien = kBase + 0x028u;
constexpr uint32_t shiftctl(unsigned n) { return kBase + 0x080u + 4u * n; }
constexpr uint32_t shiftcfg(unsigned n) { return kBase + 0x100u + 4u * n; }
constexpr uint32_t shiftbuf(unsigned n) { return kBase + 0x200u + 4u * n; }
constexpr uint32_t shiftbufbis(unsigned n) { return kBase + 0x280u + 4u * n; }
constexpr uint32_t timctl(unsigned n) { return kBase + 0x400u + 4u * n; }
constexpr uint32_t timcfg(unsigned n) { return kBase + 0x480u + 4u * n; }
constexpr uint32_t timcmp(unsigned n) { return kBase + 0x500u + 4u * n; }
constexpr unsigned kIrq = 156;  // RM table 4-2: FLEXIO3

// TIMCTL: TRGSEL 29:24 (timer n output = 4n + 3), TRGPOL 23, TRGSRC 22, TIMOD 1:0.
constexpr uint32_t kTriggerTimer4 = (4u * 4u + 3u) << 24;
constexpr uint32_t kTriggerLow = 1u << 23;
constexpr uint32_t kTriggerInternal = 1u << 22;
constexpr uint32_t kDualBaud = 1u, k16Bit = 3u;
// TIMCFG: TIMDIS 14:12 (2 = on compare), TIMENA 10:8 (6 = trigger rising edge).
constexpr uint32_t kOneShotCfg = (2u << 12) | (6u << 8);
// SHIFTCTL: TIMSEL 26:24, PINCFG 17:16 (3 = output), PINSEL 12:8, SMOD 2:0 (2 = transmit).
constexpr uint32_t transmitter(unsigned timer, unsigned pin) { return (timer << 24) | (3u << 16) | (pin << 8) | 2u; }

// The Driver Module's port A: STEP Teensy 23 = GPIO_AD_B1_09 → FLEXIO3_FLEXIO09 (ALT9, RM §11.7),
// DIR Teensy 22 = GPIO_AD_B1_08 → FLEXIO3_FLEXIO08.
constexpr unsigned kStepPinA = 9, kDirPinA = 8;
// 120 MHz FlexIO clock: a 40 µs frame is 4800 clocks, half of it 2400; a bit is 120 clocks.
constexpr uint32_t kHalfPeriodClocks = 2400;

struct Flexio3Test : ::testing::Test {
  Flexio3Test() : fio(rig.bus, rig.chip, rig.io, TeensyModel::kTeensy41) { rig.bus.add(fio); }

  // flexio3.cpp power_up(): SWRST, release, FLEXEN (at t = 1000 ns: the FlexIO clock's epoch).
  void power_up() {
    rig.run_until(1000);
    ASSERT_TRUE(rig.write(kCtrl, 2));
    ASSERT_TRUE(rig.write(kCtrl, 0));
    ASSERT_TRUE(rig.write(kCtrl, 1));
  }
  // flexio3.cpp configure_port(port A): shifters 0 (STEP) and 4 (DIR) on timer 0, 32 bits of 1 µs.
  void configure_port_a() {
    ASSERT_TRUE(rig.write(timctl(0), 0));
    ASSERT_TRUE(rig.write(shiftcfg(0), 0));
    ASSERT_TRUE(rig.write(shiftcfg(4), 0));
    ASSERT_TRUE(rig.write(shiftctl(0), transmitter(0, kStepPinA)));
    ASSERT_TRUE(rig.write(shiftctl(4), transmitter(0, kDirPinA)));
    ASSERT_TRUE(rig.write(shiftbuf(0), 0));
    ASSERT_TRUE(rig.write(shiftbuf(4), 0));
    // Baud mode: CMP[7:0] = 60 clocks per half bit - 1, CMP[15:8] = 2 × 32 bits - 1.
    ASSERT_TRUE(rig.write(timcmp(0), (63u << 8) | 59u));
    ASSERT_TRUE(rig.write(timcfg(0), kOneShotCfg));
    ASSERT_TRUE(rig.write(timctl(0), kTriggerTimer4 | kTriggerInternal | kDualBaud));
  }
  // flexio3.cpp start_frame_clock(40): marker (timer 5), guard (timer 6), frame clock (timer 4).
  void start_frame_clock() {
    ASSERT_TRUE(rig.write(timctl(5), 0));
    ASSERT_TRUE(rig.write(timcmp(5), 3));  // 4 clocks after the tick
    ASSERT_TRUE(rig.write(timcfg(5), kOneShotCfg));
    ASSERT_TRUE(rig.write(timctl(5), kTriggerTimer4 | kTriggerInternal | k16Bit));
    ASSERT_TRUE(rig.write(timctl(6), 0));
    ASSERT_TRUE(rig.write(timcmp(6), kHalfPeriodClocks - 360u - 1u));  // guard: 3 µs = 360 clocks
    ASSERT_TRUE(rig.write(timcfg(6), kOneShotCfg));
    ASSERT_TRUE(rig.write(timctl(6), kTriggerTimer4 | kTriggerInternal | kTriggerLow | k16Bit));
    ASSERT_TRUE(rig.write(kTimstat, (1u << 5) | (1u << 6)));
    ASSERT_TRUE(rig.write(kTimien, rig.read32(kTimien) | (1u << 5)));
    ASSERT_TRUE(rig.write(timcmp(4), kHalfPeriodClocks - 1u));
    ASSERT_TRUE(rig.write(timcfg(4), 0));  // TIMENA always, TIMDIS never
    ASSERT_TRUE(rig.write(timctl(4), k16Bit));
  }
  // The tick ISR's first act: clear the marker and guard flags (w1c).
  void acknowledge_tick() { ASSERT_TRUE(rig.write(kTimstat, (1u << 5) | (1u << 6))); }
  // Runs events until the FLEXIO3 line is high (or `limit_ns`); returns the time.
  SimTime run_to_interrupt(SimTime limit_ns) {
    while (!rig.chip.level(kIrq) && rig.chip.scheduler().step(limit_ns)) {
    }
    return rig.chip.now_ns();
  }

  Rig rig;
  Flexio3 fio;
};

TEST_F(Flexio3Test, ResetValuesAndReservedBitsFollowTheManual) {
  // All FLEXIO registers reset to 0 (RM §50.5.1); reserved CTRL bits 29:3 read 0.
  EXPECT_EQ(rig.read32(kCtrl), 0u);
  EXPECT_EQ(rig.read32(timctl(3)), 0u);
  ASSERT_TRUE(rig.write(timcmp(2), 0xABCD1234u));
  EXPECT_EQ(rig.read32(timcmp(2)), 0x1234u);   // CMP is bits 15:0
  ASSERT_TRUE(rig.write(kCtrl, 0x3FFFFFF8u));  // only reserved bits
  EXPECT_EQ(rig.read32(kCtrl), 0u);
  // SHIFTCTL: TIMSEL 26:24, TIMPOL 23, PINCFG 17:16, PINSEL 12:8, PINPOL 7, SMOD 2:0; the rest reserved.
  ASSERT_TRUE(rig.write(shiftctl(0), transmitter(0, kStepPinA) | 0xF87CE078u));
  EXPECT_EQ(rig.read32(shiftctl(0)), transmitter(0, kStepPinA));
}

TEST_F(Flexio3Test, ShifterPinSelectHasFiveBits) {
  // SHIFTCTL PINSEL is bits 12:8 (RM §50.5.1.19): FlexIO3 pin 19 (Teensy 4.1 pin 37, port C's
  // STEP on a Driver Module) reads back whole. A 4-bit mask once sent port C's STEP to pin 3.
  const uint32_t step_c = transmitter(2, 19);
  ASSERT_EQ((step_c >> 8) & 0x1Fu, 19u);
  ASSERT_TRUE(rig.write(shiftctl(2), step_c));
  EXPECT_EQ(rig.read32(shiftctl(2)), step_c);
}

TEST_F(Flexio3Test, SoftwareResetClearsEverythingButCtrl) {
  power_up();
  ASSERT_TRUE(rig.write(timcmp(1), 77));
  ASSERT_TRUE(rig.write(shiftbuf(2), 0x55));
  ASSERT_TRUE(rig.write(kCtrl, 1 | 2));  // FLEXEN | SWRST
  EXPECT_EQ(rig.read32(kCtrl), 3u);
  EXPECT_EQ(rig.read32(timcmp(1)), 0u);
  EXPECT_EQ(rig.read32(shiftbuf(2)), 0u);
  ASSERT_TRUE(rig.write(timcmp(1), 5));  // held in reset while SWRST is set
  EXPECT_EQ(rig.read32(timcmp(1)), 0u);
}

TEST_F(Flexio3Test, FrameInterruptEvery40MicrosecondsAt120MHz) {
  power_up();
  rig.run_until(2000);  // 1000 ns after the epoch: 120 FlexIO clocks
  start_frame_clock();
  std::vector<SimTime> ticks;
  for (int k = 0; k < 10; ++k) {
    ticks.push_back(run_to_interrupt(1000000));
    EXPECT_TRUE(rig.read32(kTimstat) & (1u << 5));
    acknowledge_tick();
    EXPECT_FALSE(rig.chip.level(kIrq));  // clearing the flag ends the request
  }
  // Enable = the first rising edge; the marker flag 4 clocks later (33.3 ns → the next ns).
  EXPECT_EQ(ticks[0], 2000 + 34);
  // Period = 2 × (TIMCMP + 1) / 120 MHz = 40 µs, exactly, every time.
  for (size_t k = 1; k < ticks.size(); ++k) EXPECT_EQ(ticks[k] - ticks[k - 1], 40000) << k;
  EXPECT_EQ(rig.chip.rises(kIrq).size(), 10u);
}

TEST_F(Flexio3Test, PeriodFollowsTheClockRoot) {
  // CS1CDR at its reset value 0x0EC102C1: PRED 1, PODF 7 → 480 MHz / 2 / 8 = 30 MHz, so the same
  // TIMCMP gives a 4 × longer period (RM §14.7.10 reset value).
  rig.ccm.registers[0x28] = 0x0EC102C1u;
  power_up();
  start_frame_clock();
  EXPECT_EQ(fio.clock_hz(), 30000000u);
  const SimTime first = run_to_interrupt(1000000);
  acknowledge_tick();
  const SimTime second = run_to_interrupt(1000000);
  EXPECT_EQ(second - first, 160000);
}

TEST_F(Flexio3Test, CommitGuardFlagRisesThreeMicrosecondsBeforeTheNextTick) {
  power_up();
  rig.run_until(2000);
  start_frame_clock();  // tick at 2000
  rig.run_until(2034);  // the marker's flag, 4 clocks later
  acknowledge_tick();
  rig.run_until(2000 + 36999);
  EXPECT_FALSE(rig.read32(kTimstat) & (1u << 6));
  rig.run_until(2000 + 37000);  // mid-period edge + (2040 clocks) = 40 µs - 3 µs
  EXPECT_TRUE(rig.read32(kTimstat) & (1u << 6));
  EXPECT_FALSE(rig.chip.level(kIrq)) << "the guard has no interrupt enabled";
}

TEST_F(Flexio3Test, AStepWithDirHighPlaysTheEncodersWords) {
  // One forward pulse on signal 0 (X): the encoder lays STEP at 2..3 µs and DIR 1..4 µs.
  const protocol::EncodedFrame frame = protocol::encode_frame(protocol::FrameRequest{1, 1, 0});
  ASSERT_EQ(frame.words.step_bits, 0x0000000Cu);  // bits 2, 3: a 2 µs pulse from 2 µs
  ASSERT_EQ(frame.words.dir_bits, 0x0000001Eu);   // bits 1..4: 1 µs margin either side
  power_up();
  configure_port_a();
  ASSERT_TRUE(rig.write(shiftbuf(4), frame.words.dir_bits));
  ASSERT_TRUE(rig.write(shiftbuf(0), frame.words.step_bits));
  rig.run_until(2000);
  start_frame_clock();
  ASSERT_EQ(rig.io.frames.size(), 1u);
  EXPECT_EQ(rig.io.frames[0].port, 0u);
  EXPECT_EQ(rig.io.frames[0].start_ns, 2000);
  EXPECT_EQ(rig.io.frames[0].frame_ns, 40000);
  EXPECT_EQ(rig.io.frames[0].words.step_bits, frame.words.step_bits);
  EXPECT_EQ(rig.io.frames[0].words.dir_bits, frame.words.dir_bits);
  // The buffers were not rewritten: the next tick sends the same words again (the reason the
  // backend's tick ISR zeroes them).
  rig.run_until(2000 + 40000);
  ASSERT_EQ(rig.io.frames.size(), 2u);
  EXPECT_EQ(rig.io.frames[1].start_ns, 42000);
  EXPECT_EQ(rig.io.frames[1].words.step_bits, frame.words.step_bits);
}

TEST_F(Flexio3Test, AWriteAfterTheTickGoesOutOneFrameLater) {
  power_up();
  configure_port_a();
  rig.run_until(2000);
  start_frame_clock();                               // launches zeros at 2000
  rig.run_until(42000);                              // the second tick has launched (zeros again)
  ASSERT_TRUE(rig.write(shiftbuf(0), 0x0000000Cu));  // too late for the tick at 42000
  rig.run_until(82000);
  ASSERT_EQ(rig.io.frames.size(), 3u);
  EXPECT_EQ(rig.io.frames[1].words.step_bits, 0u);
  EXPECT_EQ(rig.io.frames[2].start_ns, 82000);
  EXPECT_EQ(rig.io.frames[2].words.step_bits, 0x0000000Cu);
}

TEST_F(Flexio3Test, ShifterStatusAndUnderrun) {
  power_up();
  configure_port_a();
  // Written buffers: the load at the first tick is clean and leaves SSF set (buffer empty).
  EXPECT_EQ(rig.read32(kShiftstat) & 0x11u, 0u);
  rig.run_until(2000);
  start_frame_clock();
  EXPECT_EQ(rig.read32(kShiftstat) & 0x11u, 0x11u);
  EXPECT_EQ(rig.read32(kShifterr) & 0x11u, 0u);
  // Nothing written before the next load: both shifters underrun (SEF); w1c clears them.
  rig.run_until(42000);
  EXPECT_EQ(rig.read32(kShifterr) & 0x11u, 0x11u);
  ASSERT_TRUE(rig.write(kShifterr, 0x01));
  EXPECT_EQ(rig.read32(kShifterr) & 0x11u, 0x10u);
}

TEST_F(Flexio3Test, BitSwappedAliasShowsTheBufferReversed) {
  ASSERT_TRUE(rig.write(shiftbufbis(1), 0x00000001u));  // SHIFTBUFBIS: bit 31 ↔ bit 0
  EXPECT_EQ(rig.read32(shiftbuf(1)), 0x80000000u);
  EXPECT_EQ(rig.read32(shiftbufbis(1)), 0x00000001u);
}

TEST_F(Flexio3Test, UnexpectedUsesAreRefused) {
  uint32_t value = 0;
  EXPECT_FALSE(rig.read(kCtrl, value, 2)) << "16-bit access";
  EXPECT_FALSE(rig.read(kBase + 0x000u, value)) << "VERID is not modelled";
  EXPECT_FALSE(rig.write(shiftctl(0), 1u)) << "receive mode";
  EXPECT_FALSE(rig.write(shiftcfg(0), 1u)) << "start bit";
  EXPECT_FALSE(rig.write(shiftctl(1), transmitter(1, 0))) << "FlexIO3 pin 0 = Teensy 19: no port line";
  ASSERT_TRUE(rig.write(timcfg(2), 0));
  EXPECT_FALSE(rig.write(timctl(2), 2u)) << "dual 8-bit PWM mode";
  EXPECT_FALSE(rig.write(timcfg(2), 1u << 24)) << "TIMOUT = 1";
}

TEST(Flexio3Teensy40, PortsCAndDHaveNoFlexio3PadsOnTheTeensy40) {
  Rig rig;
  Flexio3 fio(rig.bus, rig.chip, rig.io, TeensyModel::kTeensy40);
  rig.bus.add(fio);
  // Port C STEP is Teensy 37 = GPIO_B1_03 → FLEXIO3 19 on the 4.1; the 4.0's pin 37 is an SD pad.
  EXPECT_FALSE(rig.write(shiftctl(2), transmitter(2, 19)));
  EXPECT_TRUE(rig.write(shiftctl(0), transmitter(0, kStepPinA)));
}

TEST_F(Flexio3Test, PortsCAndDAreOnB1PadsOfTheTeensy41) {
  // Port C STEP 37 = B1_03 → FLEXIO3 19, DIR 36 = B1_02 → 18; port D STEP 35 = B1_12 → 28,
  // DIR 34 = B1_13 → 29 (RM §11.7 ALT9).
  EXPECT_TRUE(rig.write(shiftctl(2), transmitter(2, 19)));
  EXPECT_TRUE(rig.write(shiftctl(6), transmitter(2, 18)));
  EXPECT_TRUE(rig.write(shiftctl(3), transmitter(3, 28)));
  EXPECT_TRUE(rig.write(shiftctl(7), transmitter(3, 29)));
}

}  // namespace
}  // namespace stepdance::sim::image
