// ENC1/ENC2 and XBAR1 driven as the backend's quadrature.cpp drives them. Expected values: RM
// §56.8 / §61.4 layouts and reset values, XBAR1 numbers from RM chapter 4 (ENC1 PHASEA/B =
// outputs 66/67, ENC2 = 71/72; IOMUX_XBAR_INOUT17/16/06/07 = inputs 17/16/6/7), and the knob's
// counts the fake world reports.
#include <gtest/gtest.h>

#include "image/rt1062/enc.hpp"
#include "image/rt1062/xbar1.hpp"
#include "motion_fakes.hpp"

namespace stepdance::sim::image {
namespace {

using testing::FakeClockBlock;
using testing::Rig;

constexpr uint32_t kXbar = 0x403BC000u;
constexpr uint32_t sel(unsigned output) { return kXbar + 2u * (output / 2u); }
constexpr uint32_t enc(unsigned index, uint32_t offset) { return 0x403C8000u + 0x4000u * index + offset; }
constexpr uint32_t kCtrl = 0x00, kFilt = 0x02, kPosd = 0x06, kUpos = 0x0E, kLpos = 0x10, kLposh = 0x14;
constexpr uint32_t kUinit = 0x16, kLinit = 0x18, kImr = 0x1A, kCtrl2 = 0x1E, kUmod = 0x20, kLmod = 0x22;
constexpr uint32_t kUcomp = 0x24;
constexpr uint16_t kSwip = 1u << 11, kHie = 1u << 14;

struct EncTest : ::testing::Test {
  EncTest() {
    rig.bus.add(xbar);
    rig.bus.add(enc1);
    rig.bus.add(enc2);
    xbar.add_listener([this] {
      enc1.routing_changed();
      enc2.routing_changed();
    });
  }
  bool w16(uint32_t address, uint32_t value) { return rig.write(address, value, 2); }
  uint32_t r16(uint32_t address) {
    uint32_t value = 0;
    EXPECT_TRUE(rig.read(address, value, 2)) << std::hex << address;
    return value;
  }
  // regs_xbar.hpp connect(): read-modify-write of the output's byte in SELn.
  void connect(unsigned input, unsigned output) {
    const unsigned shift = (output & 1u) ? 8u : 0u;
    ASSERT_TRUE(w16(sel(output), (r16(sel(output)) & ~(0x7Fu << shift)) | (input << shift)));
  }
  // quadrature_begin(index) after the pads: XBAR routes, then the ENC setup and SWIP.
  void begin(unsigned index) {
    if (index == 0) {
      connect(17, 66);
      connect(16, 67);
    } else {
      connect(6, 71);
      connect(7, 72);
    }
    ASSERT_TRUE(w16(enc(index, kCtrl), 0));
    ASSERT_TRUE(w16(enc(index, kCtrl2), 0));
    ASSERT_TRUE(w16(enc(index, kUmod), 0));
    ASSERT_TRUE(w16(enc(index, kLmod), 0));
    ASSERT_TRUE(w16(enc(index, kFilt), (2u << 8) | 15u));
    ASSERT_TRUE(w16(enc(index, kUinit), 0));
    ASSERT_TRUE(w16(enc(index, kLinit), 0));
    ASSERT_TRUE(w16(enc(index, kCtrl), kSwip));
  }
  // quadrature_read(): UPOS (latches LPOSH), then LPOSH.
  int32_t read_position(unsigned index) {
    const uint32_t upper = r16(enc(index, kUpos));
    return static_cast<int32_t>((upper << 16) | r16(enc(index, kLposh)));
  }

  Rig rig;
  Xbar1 xbar;
  Enc enc1{0, rig.bus, rig.chip, rig.io, xbar};
  Enc enc2{1, rig.bus, rig.chip, rig.io, xbar};
};

TEST_F(EncTest, ResetValuesFollowTheManual) {
  EXPECT_EQ(r16(sel(66)), 0u);  // XBARA1_SEL33: every output selects input 0
  EXPECT_EQ(r16(enc(0, kCtrl)), 0u);
  EXPECT_EQ(r16(enc(0, kUcomp)), 0xFFFFu);  // UCOMP/LCOMP reset 0xFFFF
  ASSERT_TRUE(w16(sel(0), 0xFFFF));
  EXPECT_EQ(r16(sel(0)), 0x7F7Fu) << "SELn bits 15 and 7 are reserved";
}

TEST_F(EncTest, CountsOnlyOnceTheXbarRoutesThePhases) {
  rig.io.encoders[0] = 40;
  EXPECT_EQ(read_position(0), 0) << "after reset the counter is 0 and no phase reaches it";
  rig.io.encoders[0] = 55;
  EXPECT_EQ(read_position(0), 0);
  begin(0);
  rig.io.encoders[0] = 100;
  EXPECT_EQ(read_position(0), 45);
  rig.io.encoders[0] = 10;  // turned back past the start
  EXPECT_EQ(read_position(0), -45);
  EXPECT_EQ(r16(enc(0, kLposh)), 0xFFD3u);
  EXPECT_EQ(read_position(1), 0) << "ENC2 is not routed";
}

TEST_F(EncTest, SoftwareInitLoadsUinitLinit) {
  begin(1);
  rig.io.encoders[1] = 7;
  // quadrature_write(1, 70000): UINIT:LINIT = 0x0001:0x1170, then SWIP.
  ASSERT_TRUE(w16(enc(1, kUinit), 0x0001));
  ASSERT_TRUE(w16(enc(1, kLinit), 0x1170));
  ASSERT_TRUE(w16(enc(1, kCtrl), kSwip));
  EXPECT_EQ(r16(enc(1, kCtrl)) & kSwip, 0u) << "SWIP clears itself";
  rig.io.encoders[1] = 9;
  EXPECT_EQ(read_position(1), 70002);
}

TEST_F(EncTest, PosdIsTheChangeSinceTheLastCounterRead) {
  begin(0);
  rig.io.encoders[0] = 5;
  EXPECT_EQ(r16(enc(0, kPosd)), 5u);
  rig.io.encoders[0] = 3;
  EXPECT_EQ(r16(enc(0, kPosd)), 0xFFFEu);  // −2
  EXPECT_EQ(r16(enc(0, kLpos)), 3u);
}

TEST_F(EncTest, PadsOutOfTheirXbarFunctionDoNotCount) {
  FakeClockBlock iomuxc{"IOMUXC", 0x401F8000u};
  rig.bus.add(iomuxc);
  begin(0);  // the fake IOMUXC holds 0: the pads are in ALT0, not XBAR: no counting
  rig.io.encoders[0] = 30;
  EXPECT_EQ(read_position(0), 0);
  iomuxc.registers[0x0C8] = 1;  // AD_B0_03 ALT1 = XBAR1_INOUT17
  iomuxc.registers[0x0C4] = 1;  // AD_B0_02 ALT1 = XBAR1_INOUT16
  iomuxc.registers[0x62C] = 1;  // XBAR1_IN17_SELECT_INPUT: AD_B0_03
  connect(16, 67);              // any SEL write makes the ENC look again
  rig.io.encoders[0] = 32;
  EXPECT_EQ(read_position(0), 2);
}

// RM §56.8 ENC_CTRL2 UPDHLD (bit 0): a TRIGGER rising edge updates the hold registers. The
// trigger comes through XBAR1 (ENC1 TRIGGER = output 70, ENC2 = 75; PIT_TRIGGER3 = input 59).
TEST_F(EncTest, ATriggerThroughTheXbarLatchesTheHoldsOnlyWithUpdhld) {
  xbar.on_output_edge(70, [this] { enc1.trigger(); });
  xbar.on_output_edge(75, [this] { enc2.trigger(); });
  begin(0);
  begin(1);
  constexpr uint32_t kUposh = 0x12;
  rig.io.encoders[0] = 300;
  rig.io.encoders[1] = 70000;  // past 16 bits: UPOSH 1, LPOSH 4464
  connect(59, 70);
  connect(59, 75);
  xbar.pulse(59);
  EXPECT_EQ(r16(enc(0, kLposh)), 0u) << "UPDHLD clear: the trigger does nothing";
  ASSERT_TRUE(w16(enc(0, kCtrl2), 1));
  ASSERT_TRUE(w16(enc(1, kCtrl2), 1));
  EXPECT_EQ(r16(enc(0, kCtrl2)), 1u);
  xbar.pulse(58);  // another input: not routed to either TRIGGER
  EXPECT_EQ(r16(enc(0, kLposh)), 0u);
  EXPECT_EQ(enc1.first_trigger_ns(), -1);
  rig.run_until(1234);
  xbar.pulse(59);
  rig.io.encoders[0] = 310;  // after the sample
  EXPECT_EQ(r16(enc(0, kUposh)), 0u);
  EXPECT_EQ(r16(enc(0, kLposh)), 300u);
  EXPECT_EQ(r16(enc(1, kUposh)), 1u);
  EXPECT_EQ(r16(enc(1, kLposh)), 70000u - 65536u);
  EXPECT_EQ(enc1.first_trigger_ns(), 1234);
  EXPECT_TRUE(w16(enc(0, kCtrl2), 1u << 1) == false) << "UPDPOS (clear on trigger) is not modelled";
}

TEST_F(EncTest, UnexpectedUsesAreRefused) {
  EXPECT_FALSE(w16(enc(0, kCtrl), kHie)) << "home interrupt";
  EXPECT_FALSE(w16(enc(0, kCtrl2), 1u << 2)) << "modulus counting";
  uint32_t value = 0;
  EXPECT_FALSE(rig.read(enc(0, kImr), value, 2)) << "input monitor";
  EXPECT_FALSE(rig.read(enc(0, kCtrl), value, 4)) << "32-bit access";
  EXPECT_FALSE(w16(kXbar + 0x84, 1u << 1)) << "XBAR edge interrupt";
}

}  // namespace
}  // namespace stepdance::sim::image
