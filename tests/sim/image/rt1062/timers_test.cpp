// GPT2 as our backend's khz_timer.cpp starts it, and the PIT as Teensyduino's startup and
// IntervalTimer drive it; expiry times from the counter arithmetic of RM §52.5 and §53.5.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "fake_chip.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/gpt.hpp"
#include "image/rt1062/pit.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kCscmr1 = 0x400FC01Cu, kGpt2 = 0x401F0000u, kPit = 0x40084000u;

class TimerChip : public ::testing::Test {
 protected:
  TimerChip() : analog(chip), ccm(chip, analog), gpt2(2, chip, ccm), pit(chip, ccm) {
    window.add(analog);
    bus.add(ccm);
    bus.add(window);
    bus.add(gpt2);
    bus.add(pit);
    bus.set_gate_query([this](ClockGate gate) { return ccm.gate_on(gate); });
    wr(kCscmr1, (rd(kCscmr1) & ~0x3Fu) | (1u << 6));  // startup.c: PERCLK = 24 MHz oscillator
  }
  uint32_t rd(uint32_t address) {
    uint32_t value = 0;
    BusRefusal refusal;
    EXPECT_TRUE(bus.read(address, 4, value, refusal)) << refusal.describe();
    return value;
  }
  void wr(uint32_t address, uint32_t value) {
    BusRefusal refusal;
    EXPECT_TRUE(bus.write(address, 4, value, refusal)) << refusal.describe();
  }
  // Our backend's start_gpt2(period_ticks): restart mode on PERCLK, OF1 interrupt.
  void start_gpt2(uint32_t period_ticks) {
    wr(kGpt2 + 0x00, 0);
    wr(kGpt2 + 0x0C, 0);
    wr(kGpt2 + 0x00, 1u << 15);  // SWR
    EXPECT_EQ(rd(kGpt2 + 0x00) & (1u << 15), 0u);
    wr(kGpt2 + 0x04, 0);
    wr(kGpt2 + 0x10, period_ticks - 1u);
    wr(kGpt2 + 0x08, 0x3F);
    wr(kGpt2 + 0x00, (1u << 6) | (1u << 1));  // CLKSRC = PERCLK, ENMOD
    wr(kGpt2 + 0x0C, 1u);                     // OF1IE
    wr(kGpt2 + 0x00, rd(kGpt2 + 0x00) | 1u);  // EN
  }

  testing::FakeChip chip;
  CcmAnalog analog;
  Ccm ccm;
  AnalogWindow window;
  Gpt gpt2;
  Pit pit;
  PeripheralBus bus;
};

TEST_F(TimerChip, GptResetValues) {
  EXPECT_EQ(rd(kGpt2 + 0x00), 0u);           // CR (RM §52.7.1)
  EXPECT_EQ(rd(kGpt2 + 0x10), 0xFFFFFFFFu);  // OCR1 (RM §52.7.5)
  EXPECT_EQ(rd(kGpt2 + 0x24), 0u);           // CNT
  EXPECT_EQ(rd(kPit + 0x000), 0x2u);         // PIT_MCR: MDIS (RM §53.4.1)
}

TEST_F(TimerChip, Gpt2CompareFiresItsIrqAtTheComputedTime) {
  chip.advance_to(10 * kMicrosecond);
  const SimTime start = chip.now_ns();
  start_gpt2(24000);  // 1 kHz at 24 MHz
  // CNT reaches OCR1 = 23999 after 23999 ticks of 1/24 µs: 999958.33 ns → the 999959th ns.
  chip.advance_to(start + 999958);
  EXPECT_FALSE(chip.irq_levels[101]);
  chip.advance_to(start + 999959);
  EXPECT_TRUE(chip.irq_levels[101]);  // GPT2 = IRQ 101 (RM table 4-2)
  EXPECT_EQ(chip.irq_log.back().time, start + 999959);
  EXPECT_EQ(rd(kGpt2 + 0x08) & 1u, 1u);
  wr(kGpt2 + 0x08, 1u);  // the ISR clears OF1
  EXPECT_FALSE(chip.irq_levels[101]);
  // Restart mode: the counter restarts after OCR1, so the next compare is 24000 ticks later.
  chip.advance_to(start + 999959 + 999999);
  EXPECT_FALSE(chip.irq_levels[101]);
  chip.advance_to(start + 1999959);
  EXPECT_TRUE(chip.irq_levels[101]);
  // CNT 250 µs into the third period: 6000 ticks.
  chip.advance_to(start + 2 * kMillisecond + 250 * kMicrosecond);
  EXPECT_EQ(rd(kGpt2 + 0x24), 6000u);
}

TEST_F(TimerChip, GptRefusesInputCaptureItDoesNotModel) {
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.write(kGpt2, 4, 1u << 16, refusal));  // IM1 = rising-edge capture
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
  EXPECT_TRUE(bus.read(kGpt2, 4, value, refusal));
}

TEST_F(TimerChip, PitChannelExpiresEveryLdvalPlusOneTicks) {
  // startup.c: PIT_MCR = 0, TCTRL0..3 = 0; IntervalTimer.begin(f, 1000 µs): LDVAL = 24000 - 1, TIE | TEN.
  wr(kPit + 0x000, 0);
  for (uint32_t ch = 0; ch < 4; ++ch) wr(kPit + 0x108 + 0x10 * ch, 0);
  chip.advance_to(5 * kMicrosecond);
  const SimTime start = chip.now_ns();
  wr(kPit + 0x120, 23999);  // channel 2
  wr(kPit + 0x128, 3);
  chip.advance_to(start + 250 * kMicrosecond);
  EXPECT_EQ(rd(kPit + 0x124), 23999u - 6000u);  // CVAL counts down at 24 MHz
  chip.advance_to(start + kMillisecond - 1);
  EXPECT_FALSE(chip.irq_levels[122]);
  chip.advance_to(start + kMillisecond);
  EXPECT_TRUE(chip.irq_levels[122]);  // PIT = IRQ 122 (RM table 4-2)
  EXPECT_EQ(rd(kPit + 0x12C), 1u);
  wr(kPit + 0x12C, 1);
  EXPECT_FALSE(chip.irq_levels[122]);
  wr(kPit + 0x120, 11999);  // a new LDVAL waits for the reload after the second expiry
  chip.advance_to(start + 2 * kMillisecond);
  EXPECT_TRUE(chip.irq_levels[122]);
  wr(kPit + 0x12C, 1);
  chip.advance_to(start + 2 * kMillisecond + 500 * kMicrosecond);
  EXPECT_TRUE(chip.irq_levels[122]);
  EXPECT_EQ(chip.irq_log.back().time, start + 2 * kMillisecond + 500 * kMicrosecond);
}

TEST_F(TimerChip, PitPeriodsOfFractionalNanosecondsDoNotDrift) {
  wr(kPit + 0x000, 0);
  const SimTime start = chip.now_ns();
  wr(kPit + 0x100, 6);  // 7 ticks of 1/24 µs = 291.67 ns per period
  wr(kPit + 0x108, 1);  // TEN, no interrupt
  // 24000 periods = 168000 ticks = exactly 7 ms: the 24000th reload happens then, CVAL = LDVAL.
  chip.advance_to(start + 7 * kMillisecond);
  EXPECT_EQ(rd(kPit + 0x104), 6u);
  chip.advance_to(start + 7 * kMillisecond + 42);  // 42 ns = 1.008 ticks later
  EXPECT_EQ(rd(kPit + 0x104), 5u);
}

// The backend's sample clock (sample_clock.cpp) at PERCLK 24 MHz: LDVAL 911 then TEN (912 ticks =
// 38 µs), then LDVAL 959 (960 ticks = 40 µs) for every later period. Each expiry pulses
// PIT_TRIGGER3, interrupt or not (RM chapter 4 and §53.3).
TEST_F(TimerChip, PitTriggersComeAtEachExpiryAndANewLdvalWaitsForTheFirst) {
  std::vector<std::pair<unsigned, SimTime>> pulses;
  pit.set_trigger_sink([&](unsigned channel) { pulses.emplace_back(channel, chip.now_ns()); });
  wr(kPit + 0x000, 0);
  chip.advance_to(3 * kMicrosecond);
  const SimTime start = chip.now_ns();
  wr(kPit + 0x130, 911);
  wr(kPit + 0x138, 1);
  wr(kPit + 0x130, 959);
  chip.advance_to(start + 38 * kMicrosecond + 3 * 40 * kMicrosecond);
  const std::vector<std::pair<unsigned, SimTime>> expected = {{3u, start + 38 * kMicrosecond},
                                                              {3u, start + 78 * kMicrosecond},
                                                              {3u, start + 118 * kMicrosecond},
                                                              {3u, start + 158 * kMicrosecond}};
  EXPECT_EQ(pulses, expected);
  EXPECT_FALSE(chip.irq_levels[122]) << "TIE clear: no interrupt";
  EXPECT_EQ(rd(kPit + 0x13C), 1u) << "TIF set all the same";
}

TEST_F(TimerChip, PitStaysStillWhileTheModuleIsDisabled) {
  wr(kPit + 0x100, 99);
  wr(kPit + 0x108, 3);  // MDIS is still set from reset
  chip.advance_to(10 * kMillisecond);
  EXPECT_FALSE(chip.irq_levels[122]);
  EXPECT_EQ(rd(kPit + 0x104), 99u);
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.read(kPit + 0x0E0, 4, value, refusal));  // LTMR64H: not modelled
  EXPECT_FALSE(bus.write(kPit + 0x108, 4, 4u, refusal));    // CHN: not modelled
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
