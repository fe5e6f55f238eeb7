// ADC1/ADC2 driven as Teensyduino's analog.c and our backend's adc.cpp drive them; times from the
// conversion-time formula (RM §66.5.4.5) worked by hand.
#include "image/rt1062/adc.hpp"

#include <gtest/gtest.h>

#include "fake_chip.hpp"
#include "image/chip/peripheral_bus.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kAdc1 = 0x400C4000u, kAdc2 = 0x400C8000u;
constexpr uint32_t kHc0 = 0x00, kHs = 0x20, kR0 = 0x24, kCfg = 0x44, kGc = 0x48, kGs = 0x4C;

class AdcChip : public ::testing::Test {
 protected:
  AdcChip()
      : analog(chip),
        ccm(chip, analog),
        adc1(0, chip, ccm, world, TeensyModel::kTeensy41),
        adc2(1, chip, ccm, world, TeensyModel::kTeensy41) {
    window.add(analog);
    bus.add(ccm);
    bus.add(window);
    bus.add(adc1);
    bus.add(adc2);
    bus.set_gate_query([this](ClockGate gate) { return ccm.gate_on(gate); });
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
  // Waits as a polling loop does (1 µs per pass); returns the time the condition held.
  template <typename Done>
  SimTime wait(Done done) {
    for (int pass = 0; pass < 100000 && !done(); ++pass) chip.advance_to(chip.now_ns() + kMicrosecond);
    return chip.now_ns();
  }

  testing::FakeChip chip;
  testing::FakeWorld world;
  CcmAnalog analog;
  Ccm ccm;
  AnalogWindow window;
  Adc adc1, adc2;
  PeripheralBus bus;
};

TEST_F(AdcChip, ResetValues) {
  EXPECT_EQ(rd(kAdc1 + kHc0), 0x1Fu);   // RM §66.8.1: ADCH = 31, conversion off
  EXPECT_EQ(rd(kAdc1 + kCfg), 0x200u);  // RM §66.8.4
  EXPECT_EQ(rd(kAdc1 + kGc), 0u);
  EXPECT_EQ(rd(kAdc1 + kHs), 0u);
}

TEST_F(AdcChip, TeensyduinoCalibrationAndAnalogReadTakeTheirConversionTimes) {
  // analog_init (10 bits, 4 averages): CFG = MODE 1 | ADSTS 2 | ADLSMP | ADIV 1 | ADICLK 3 | ADHSC.
  const uint32_t cfg = (1u << 2) | (2u << 8) | (1u << 4) | (1u << 5) | 3u | (1u << 10);
  wr(kAdc1 + kCfg, cfg);
  const SimTime cal_start = chip.now_ns();
  wr(kAdc1 + kGc, (1u << 5) | (1u << 7));  // AVGE | CAL
  const SimTime cal_end = wait([&] { return !(rd(kAdc1 + kGc) & (1u << 7)); });
  // ADCK = ADACK 20 MHz (ADHSC) ÷ 2 = 10 MHz; 6 + 32 × (21 + 21 + 2) = 1414 cycles = 141.4 µs.
  EXPECT_GE(cal_end - cal_start, 141400);
  EXPECT_LT(cal_end - cal_start, 141400 + kMicrosecond);
  EXPECT_EQ(rd(kAdc1 + kGs) & 2u, 0u);  // CALF clear
  // analogRead(14): A0 = AD_B1_02 = ADC1 channel 7 (analog.c pin_to_channel).
  world.analog[14] = 512;
  const SimTime start = chip.now_ns();
  wr(kAdc1 + kHc0, 7);
  EXPECT_EQ(rd(kAdc1 + kGs) & 1u, 1u);  // ADACT
  const SimTime done = wait([&] { return (rd(kAdc1 + kHs) & 1u) != 0; });
  // 6 + 4 × (21 + 21 + 2) = 182 cycles at 10 MHz = 18.2 µs.
  EXPECT_GE(done - start, 18200);
  EXPECT_LT(done - start, 18200 + kMicrosecond);
  EXPECT_EQ(rd(kAdc1 + kR0), 512u);
  EXPECT_EQ(rd(kAdc1 + kHs) & 1u, 0u);  // reading R0 cleared COCO0
  ASSERT_FALSE(world.analog_reads.empty());
  EXPECT_EQ(world.analog_reads.back().pin, 14);
  EXPECT_EQ(world.analog_reads.back().time, start + 18200);
}

TEST_F(AdcChip, OurBackendsRoundRobinGetsAnInterruptPerConversion) {
  // IPG = 24 MHz: PERIPH_CLK2 from the oscillator (CBCMR PERIPH_CLK2_SEL 1), IPG_PODF 0.
  wr(0x400FC018u, (rd(0x400FC018u) & ~(3u << 12)) | (1u << 12));
  wr(0x400FC014u, (rd(0x400FC014u) & ~(3u << 8) & ~(7u << 27)) | (1u << 25));
  ASSERT_EQ(ccm.ipg_clock_hz(), 24000000u);
  // adc.cpp calibrate(): ADICLK 1 (IPG/2) | ADIV 3 (÷8) | MODE 1 | ADLSMP | ADSTS 3 | AVGS 3 | OVWREN.
  wr(kAdc2 + kHc0, 0x1F);
  wr(kAdc2 + kCfg, 1u | (3u << 5) | (1u << 2) | (1u << 4) | (3u << 8) | (3u << 14) | (1u << 16));
  EXPECT_EQ(adc2.adck_hz(), 1500000u);
  wr(kAdc2 + kGs, 2);
  wr(kAdc2 + kGc, (1u << 5) | (1u << 7));
  wait([&] { return !(rd(kAdc2 + kGc) & (1u << 7)); });
  // start_conversion: HC0 = AIEN | channel 7 (pin 14 on ADC2).
  world.analog[14] = 1000;
  const SimTime start = chip.now_ns();
  wr(kAdc2 + kHc0, (1u << 7) | 7u);
  // 6 + 32 × (21 + 25) = 1478 cycles at 1.5 MHz = 985333.3 ns → the 985334th ns.
  chip.advance_to(start + 985333);
  EXPECT_FALSE(chip.irq_levels[68]);
  chip.advance_to(start + 985334);
  EXPECT_TRUE(chip.irq_levels[68]);  // ADC2 = IRQ 68 (RM table 4-2)
  EXPECT_EQ(rd(kAdc2 + kR0), 1000u);
  EXPECT_FALSE(chip.irq_levels[68]);
}

TEST_F(AdcChip, ResultsScaleToTheResolution) {
  world.analog[24] = 1023;           // pin 24 = AD_B0_12 = ADC1 channel 1
  wr(kAdc1 + kCfg, (2u << 2) | 1u);  // 12 bits
  wr(kAdc1 + kHc0, 1);
  wait([&] { return (rd(kAdc1 + kHs) & 1u) != 0; });
  EXPECT_EQ(rd(kAdc1 + kR0), 4095u);
  world.analog[24] = 512;
  wr(kAdc1 + kCfg, 1u);  // 8 bits: 512 of 1023 → 128 of 255
  wr(kAdc1 + kHc0, 1);
  wait([&] { return (rd(kAdc1 + kHs) & 1u) != 0; });
  EXPECT_EQ(rd(kAdc1 + kR0), 128u);
}

TEST_F(AdcChip, ContinuousConversionsFollowEachOtherWithoutTheFirstAdder) {
  world.analog[24] = 300;
  wr(kAdc1 + kCfg, 1u << 2);  // 10 bits, ADICLK = IPG (3 MHz at reset), short sample ADSTS 0
  wr(kAdc1 + kGc, 1u << 6);   // ADCO
  const SimTime start = chip.now_ns();
  wr(kAdc1 + kHc0, (1u << 7) | 1u);
  // First: 6 + (21 + 3) = 30 cycles = 10 µs; each next: 24 cycles = 8 µs. 100 conversions end at
  // 10 + 99 × 8 = 802 µs exactly.
  int conversions = 0;
  bool was_high = false;
  for (SimTime t = start; t <= start + 802 * kMicrosecond; t += 1000) {
    chip.advance_to(t);
    if (chip.irq_levels[67] && !was_high) ++conversions;
    was_high = chip.irq_levels[67];
    if (was_high) {
      EXPECT_EQ(rd(kAdc1 + kR0), 300u);
      was_high = false;
    }
  }
  EXPECT_EQ(conversions, 100);
  EXPECT_EQ(chip.irq_log.back().time, start + 802 * kMicrosecond);
}

TEST_F(AdcChip, RefusesChannelsWithoutATeensyPinAndHardwareTriggers) {
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.write(kAdc1 + kHc0, 4, 3, refusal));  // ADC1 IN3 = AD_B0_14: no Teensy pin
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
  EXPECT_FALSE(bus.write(kAdc1 + kCfg, 4, 1u << 13, refusal));  // ADTRG
  EXPECT_TRUE(bus.read(kAdc1 + kHc0, 4, value, refusal));
  EXPECT_EQ(value, 0x1Fu);
  wr(0x400FC06Cu, rd(0x400FC06Cu) & ~(3u << 16));  // CCGR1 CG8 (ADC1) off
  EXPECT_FALSE(bus.read(kAdc1 + kHc0, 4, value, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kGateOff);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
