// eFlexPWM input capture driven register by register as the backend's input_capture.cpp and
// Teensyduino's pwm_init() drive it. Expected values: RM §55.8 layouts and reset values, the
// IPG clock (600 MHz / 4 = 150 MHz: 150 ticks per µs, StepdanceCapturedPulseV1), the counter
// period 65536 / 150 MHz.
#include <gtest/gtest.h>

#include "image/rt1062/flexpwm.hpp"
#include "image/rt1062/input_capture.hpp"
#include "motion_fakes.hpp"

namespace stepdance::sim::image {
namespace {

using testing::FakeClockBlock;
using testing::Rig;

constexpr uint32_t kPwm1 = 0x403DC000u, kPwm2 = 0x403E0000u;  // RM §2.3
constexpr uint32_t sm(uint32_t base, unsigned n, uint32_t offset) { return base + 0x60u * n + offset; }
// SMn registers (RM §55.8).
constexpr uint32_t kCnt = 0x00, kInit = 0x02, kCtrl2 = 0x04, kCtrl = 0x06, kVal0 = 0x0A, kVal1 = 0x0E;
constexpr uint32_t kSts = 0x24, kInten = 0x26, kCaptctrlA = 0x34, kCaptctrlB = 0x38;
constexpr uint32_t kCval2 = 0x48, kCval2Cyc = 0x4A, kCval3 = 0x4C, kCval4 = 0x50, kCval5 = 0x54;
constexpr uint32_t kOuten = 0x180, kMctrl = 0x188;
// STS / INTEN bits: CFB0 8, CFB1 9, CFA0 10, CFA1 11, RF 12.
constexpr uint16_t kCfb0 = 1u << 8, kCfb1 = 1u << 9, kCfa0 = 1u << 10, kCfa1 = 1u << 11, kRf = 1u << 12;
// CAPTCTRLx: ARM bit 0, EDGx0 (3:2) = 2 rising, EDGx1 (5:4) = 1 falling.
constexpr uint16_t kArmRiseFall = (2u << 2) | (1u << 4) | 1u;
constexpr unsigned kIrqPwm2Sm0 = 137, kIrqPwm2Sm2 = 139;  // RM table 4-2

struct CaptureTest : ::testing::Test {
  CaptureTest() {
    rig.bus.add(pwm1);
    rig.bus.add(pwm2);
  }
  bool w16(uint32_t address, uint32_t value) { return rig.write(address, value, 2); }
  uint32_t r16(uint32_t address) {
    uint32_t value = 0;
    EXPECT_TRUE(rig.read(address, value, 2)) << std::hex << address;
    return value;
  }
  // input_capture.cpp start_capture() for submodule n, channel A or B, of `base`.
  void start_capture(uint32_t base, unsigned n, bool channel_b) {
    ASSERT_TRUE(w16(base + kMctrl, r16(base + kMctrl) & ~(1u << (8 + n))));
    ASSERT_TRUE(w16(sm(base, n, kInten), 0));
    ASSERT_TRUE(w16(sm(base, n, kCaptctrlA), 0));
    ASSERT_TRUE(w16(sm(base, n, kCaptctrlB), 0));
    ASSERT_TRUE(w16(base + kMctrl, r16(base + kMctrl) | (1u << (4 + n))));
    ASSERT_TRUE(w16(sm(base, n, kCtrl2), 1u << 13));
    ASSERT_TRUE(w16(sm(base, n, kCtrl), 1u << 10));
    ASSERT_TRUE(w16(sm(base, n, kInit), 0));
    ASSERT_TRUE(w16(sm(base, n, kVal0), 0));
    ASSERT_TRUE(w16(sm(base, n, kVal1), 0xFFFF));
    ASSERT_TRUE(w16(base + kOuten, 0));
    ASSERT_TRUE(w16(base + kMctrl, r16(base + kMctrl) | (1u << n)));
    ASSERT_TRUE(w16(sm(base, n, kSts), 0xFFFF));
    ASSERT_TRUE(w16(sm(base, n, channel_b ? kCaptctrlB : kCaptctrlA), kArmRiseFall));
    ASSERT_TRUE(w16(base + kMctrl, r16(base + kMctrl) | (1u << (8 + n))));
    const uint16_t flags = channel_b ? (kCfb0 | kCfb1) : (kCfa0 | kCfa1);
    ASSERT_TRUE(w16(sm(base, n, kInten), flags | kRf));
  }

  Rig rig;
  FlexPwm pwm1{1, rig.bus, rig.chip};
  FlexPwm pwm2{2, rig.bus, rig.chip};
  InputCapture capture{rig.bus, rig.chip, pwm1, pwm2};
};

TEST_F(CaptureTest, ResetValuesFollowTheManual) {
  EXPECT_EQ(r16(sm(kPwm2, 0, kCtrl)), 0x0400u);  // SMnCTRL: FULL
  EXPECT_EQ(r16(sm(kPwm2, 0, 0x2C)), 0xFFFFu);   // SMnDISMAP0
  EXPECT_EQ(r16(sm(kPwm2, 0, 0x30)), 0x07FFu);   // SMnDTCNT0
  EXPECT_EQ(r16(sm(kPwm2, 0, kCnt)), 0u);
  uint32_t value = 0;
  EXPECT_FALSE(rig.read(sm(kPwm2, 0, kCtrl), value, 4)) << "32-bit access";
  EXPECT_FALSE(rig.read(sm(kPwm2, 0, 0x08), value, 2)) << "reserved offset";
}

TEST_F(CaptureTest, ACapturedPulseOfWMicrosecondsSpans150WTicks) {
  rig.run_until(1000);
  start_capture(kPwm2, 0, false);  // port A: PWM2 SM0 A
  for (int width_us : {2, 5, 100}) {
    const SimTime rise = rig.chip.now_ns() + 7001;
    const SimTime fall = rise + width_us * 1000;
    rig.run_until(fall);
    capture.pulse_arrived(0, ArrivingPulse{rise, fall, true, true});
    EXPECT_TRUE(rig.chip.level(kIrqPwm2Sm0));
    const uint32_t sts = r16(sm(kPwm2, 0, kSts));
    ASSERT_EQ(sts & (kCfa0 | kCfa1), kCfa0 | kCfa1);
    const uint16_t rise_ticks = static_cast<uint16_t>(r16(sm(kPwm2, 0, kCval2)));
    const uint16_t fall_ticks = static_cast<uint16_t>(r16(sm(kPwm2, 0, kCval3)));
    EXPECT_EQ(static_cast<uint16_t>(fall_ticks - rise_ticks), 150 * width_us) << width_us;
    // The counter started at RUN (t = 1000 + the accesses at that time) and counts at 150 MHz.
    EXPECT_EQ(rise_ticks, static_cast<uint16_t>((rise - 1000) * 150 / 1000)) << width_us;
    ASSERT_TRUE(w16(sm(kPwm2, 0, kSts), kCfa0 | kCfa1));
    EXPECT_FALSE(rig.chip.level(kIrqPwm2Sm0)) << "flags cleared: the line falls";
  }
}

TEST_F(CaptureTest, ChannelBOfSubmodule2IsPortD) {
  start_capture(kPwm2, 2, true);
  rig.run_until(50000);
  capture.pulse_arrived(3, ArrivingPulse{48000, 50000, false, false});
  EXPECT_EQ(r16(sm(kPwm2, 2, kSts)) & (kCfb0 | kCfb1), kCfb0 | kCfb1);
  EXPECT_TRUE(rig.chip.level(kIrqPwm2Sm2));
  EXPECT_EQ(static_cast<uint16_t>(r16(sm(kPwm2, 2, kCval5)) - r16(sm(kPwm2, 2, kCval4))), 300u);
}

TEST_F(CaptureTest, TheCounterWrapsEvery65536TicksAndRaisesTheReloadFlag) {
  start_capture(kPwm2, 0, false);  // at t = 0
  ASSERT_TRUE(w16(sm(kPwm2, 0, kSts), kRf));
  // 65536 ticks at 150 MHz = 436906.7 ns: the reload interrupt comes at the next whole ns.
  rig.run_until(436906);
  EXPECT_FALSE(rig.chip.level(kIrqPwm2Sm0));
  EXPECT_EQ(r16(sm(kPwm2, 0, kCnt)), 65535u);
  rig.run_until(436907);
  EXPECT_TRUE(rig.chip.level(kIrqPwm2Sm0));
  EXPECT_TRUE(r16(sm(kPwm2, 0, kSts)) & kRf);
  EXPECT_EQ(r16(sm(kPwm2, 0, kCnt)), 0u);
  ASSERT_TRUE(w16(sm(kPwm2, 0, kSts), kRf));
  EXPECT_FALSE(rig.chip.level(kIrqPwm2Sm0));
}

TEST_F(CaptureTest, ReadingCvalPopsTheFifoCount) {
  start_capture(kPwm2, 1, false);
  rig.run_until(10000);
  capture.pulse_arrived(1, ArrivingPulse{8000, 10000, true, true});
  // CA0CNT (12:10) and CA1CNT (15:13) count one word each.
  EXPECT_EQ(r16(sm(kPwm2, 1, kCaptctrlA)) & 0xFC00u, (1u << 10) | (1u << 13));
  r16(sm(kPwm2, 1, kCval2));
  EXPECT_EQ(r16(sm(kPwm2, 1, kCaptctrlA)) & 0xFC00u, 1u << 13);
  EXPECT_EQ(r16(sm(kPwm2, 1, kCval2Cyc)), 0u);
}

TEST_F(CaptureTest, APulseThatHasNotFallenYetIsCapturedEdgeByEdge) {
  start_capture(kPwm2, 0, false);
  rig.run_until(1000);
  capture.pulse_arrived(0, ArrivingPulse{2000, 500000, true, true});  // a 498 µs pulse
  rig.run_until(2000);
  EXPECT_EQ(r16(sm(kPwm2, 0, kSts)) & (kCfa0 | kCfa1), kCfa0) << "the rise interrupts on its own";
  rig.run_until(500000);
  EXPECT_EQ(r16(sm(kPwm2, 0, kSts)) & (kCfa0 | kCfa1), kCfa0 | kCfa1);
  // 498 µs = 74700 ticks: one wrap, 74700 - 65536 = 9164 left in the wrapped difference.
  EXPECT_EQ(static_cast<uint16_t>(r16(sm(kPwm2, 0, kCval3)) - r16(sm(kPwm2, 0, kCval2))), 9164u);
  EXPECT_EQ(r16(sm(kPwm2, 0, 0x4E)), 1u) << "CVAL3CYC: one reload since the start";
}

TEST_F(CaptureTest, AnEdgeOnAPadNotInItsPwmFunctionIsNotCaptured) {
  FakeClockBlock iomuxc{"IOMUXC", 0x401F8000u};
  rig.bus.add(iomuxc);
  start_capture(kPwm2, 0, false);
  rig.run_until(10000);
  capture.pulse_arrived(0, ArrivingPulse{8000, 10000, true, true});  // EMC_06 still ALT0
  EXPECT_EQ(r16(sm(kPwm2, 0, kSts)) & (kCfa0 | kCfa1), 0u);
  EXPECT_EQ(capture.unrouted_edges(), 2u);
  iomuxc.registers[0x02C] = 0x11;  // SW_MUX_CTL_PAD_GPIO_EMC_06: SION | ALT1
  rig.run_until(20000);
  capture.pulse_arrived(0, ArrivingPulse{18000, 20000, true, true});
  EXPECT_EQ(r16(sm(kPwm2, 0, kSts)) & (kCfa0 | kCfa1), kCfa0 | kCfa1);
}

TEST_F(CaptureTest, TeensyduinoPwmInitIsAccepted) {
  // pwm.c flexpwm_init() at startup: fault registers, every submodule's PWM setup, LDOK, RUN.
  ASSERT_TRUE(w16(kPwm1 + 0x18C, 15u << 0));  // FCTRL0: FLVL
  ASSERT_TRUE(w16(kPwm1 + 0x18E, 0x000F));    // FSTS0
  ASSERT_TRUE(w16(kPwm1 + 0x190, 0));         // FFILT0
  ASSERT_TRUE(w16(kPwm1 + kMctrl, r16(kPwm1 + kMctrl) | 0x00F0u));
  for (unsigned n = 0; n < 4; ++n) {
    ASSERT_TRUE(w16(sm(kPwm1, n, kCtrl2), (1u << 13) | (1u << 14) | (1u << 15)));
    ASSERT_TRUE(w16(sm(kPwm1, n, kCtrl), 1u << 10));
    ASSERT_TRUE(w16(sm(kPwm1, n, 0x22), 0));  // OCTRL
    ASSERT_TRUE(w16(sm(kPwm1, n, 0x30), 0));  // DTCNT0
    ASSERT_TRUE(w16(sm(kPwm1, n, kInit), 0));
    for (uint32_t val = 0; val < 6; ++val) ASSERT_TRUE(w16(sm(kPwm1, n, kVal0 + 4 * val), val == 1 ? 33464 : 0));
  }
  ASSERT_TRUE(w16(kPwm1 + kMctrl, r16(kPwm1 + kMctrl) | 0x000F));
  ASSERT_TRUE(w16(kPwm1 + kMctrl, r16(kPwm1 + kMctrl) | 0x0F00));
  EXPECT_EQ(r16(kPwm1 + kMctrl), 0x0F00u) << "RUN set, LDOK cleared by the load";
  // 33465 ticks per period at 150 MHz: 223.1 µs; the counter is at 100 µs × 150 = 15000.
  rig.run_until(100000);
  EXPECT_EQ(r16(sm(kPwm1, 2, kCnt)), 15000u);
  EXPECT_TRUE(r16(sm(kPwm1, 2, kSts)) & 1u) << "CMPF0: the counter passed VAL0 = 0";
}

}  // namespace
}  // namespace stepdance::sim::image
