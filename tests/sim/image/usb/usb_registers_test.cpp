// USB1 and USBPHY1 registers against the reference manual: reset values, write-1-to-clear
// status, the interrupt line, the general-purpose timer, and unmodelled registers.
#include <gtest/gtest.h>

#include "usb_bench.hpp"

namespace stepdance::sim::image::usb::testing {
namespace {

TEST(UsbRegisters, ResetValuesAreTheManuals) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  EXPECT_EQ(s.reg(0x140), 0x00080000u);  // USBCMD: ITC = 8
  EXPECT_EQ(s.reg(0x144), 0u);           // USBSTS
  EXPECT_EQ(s.reg(0x148), 0u);           // USBINTR
  EXPECT_EQ(s.reg(0x1A8), 0u);           // USBMODE: idle (Teensyduino tests CM to see a used controller)
  EXPECT_EQ(s.reg(0x1C0), 0x00800080u);  // ENDPTCTRL0: control endpoint, both halves enabled
  EXPECT_EQ(s.reg(0x1C4), 0u);           // ENDPTCTRL1
  EXPECT_EQ(s.reg(0x160), 0x00000808u);  // BURSTSIZE
  uint32_t value = 0;
  EXPECT_EQ(bench.blocks->phy.read(0x00, 4, value), Access::kOk);
  EXPECT_EQ(value, 0x001E1C00u);  // USBPHY1_PWD
  EXPECT_EQ(bench.blocks->phy.read(0x30, 4, value), Access::kOk);
  EXPECT_EQ(value, 0xC0200000u);  // USBPHY1_CTRL: SFTRST and CLKGATE set
}

TEST(UsbRegisters, BlocksSitWhereTheMemoryMapPutsThem) {
  UsbBench bench;
  EXPECT_EQ(bench.bus.find(0x402E0140), &bench.usb());
  EXPECT_EQ(bench.bus.find(0x400D9030), &bench.blocks->phy);
  EXPECT_EQ(bench.bus.find(0x402E0200), nullptr);  // USB2 is not modelled
  EXPECT_EQ(bench.usb().gate().ccgr, 6);           // CCM_CCGR6 CG0 (usboh3)
  EXPECT_EQ(bench.usb().gate().field, 0);
}

TEST(UsbRegisters, UnmodelledRegistersSaySo) {
  UsbBench bench;
  uint32_t value = 0;
  EXPECT_EQ(bench.usb().read(0x000, 4, value), Access::kUnmodelled);       // ID
  EXPECT_EQ(bench.usb().read(0x178, 4, value), Access::kUnmodelled);       // ENDPTNAK
  EXPECT_EQ(bench.usb().read(0x1A4, 4, value), Access::kUnmodelled);       // OTGSC
  EXPECT_EQ(bench.blocks->phy.read(0x80, 4, value), Access::kUnmodelled);  // VERSION
}

TEST(UsbRegisters, PhySetClearAndToggleAliases) {
  UsbBench bench;
  UsbPhy& phy = bench.blocks->phy;
  uint32_t value = 0;
  ASSERT_EQ(phy.write(0x38, 4, 0xC0000000u), Access::kOk);  // CTRL_CLR SFTRST | CLKGATE
  ASSERT_EQ(phy.read(0x30, 4, value), Access::kOk);
  EXPECT_EQ(value, 0x00200000u);
  ASSERT_EQ(phy.write(0x3C, 4, 0x00000002u), Access::kOk);  // CTRL_TOG bit 1
  ASSERT_EQ(phy.read(0x30, 4, value), Access::kOk);
  EXPECT_EQ(value, 0x00200002u);
  EXPECT_FALSE(phy.ready());                                // PWD still powers the transceivers down
  ASSERT_EQ(phy.write(0x08, 4, 0xFFFFFFFFu), Access::kOk);  // PWD_CLR
  EXPECT_TRUE(phy.ready());
  ASSERT_EQ(phy.write(0x34, 4, 0x80000000u), Access::kOk);  // CTRL_SET SFTRST: PWD back to reset
  ASSERT_EQ(phy.read(0x00, 4, value), Access::kOk);
  EXPECT_EQ(value, 0x001E1C00u);
}

TEST(UsbRegisters, StatusBitsClearByWritingOneAndDriveIrq113) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.init();
  s.set(kUsbIntr, kStsUri);
  bench.chip.scheduler().run_until(105 * kMillisecond);  // debounce 100 ms, then 10 ms of reset
  EXPECT_TRUE(s.reg(kUsbSts) & kStsUri);
  EXPECT_TRUE(s.reg(kPortSc1) & kPortPr);
  EXPECT_TRUE(bench.chip.irq113);
  s.set(kUsbSts, kStsUi);  // another bit: URI stays
  EXPECT_TRUE(s.reg(kUsbSts) & kStsUri);
  EXPECT_TRUE(bench.chip.irq113);
  s.set(kUsbSts, kStsUri);
  EXPECT_FALSE(s.reg(kUsbSts) & kStsUri);
  EXPECT_FALSE(bench.chip.irq113);
}

TEST(UsbRegisters, ResetEndsWithPortChangeAndHighSpeed) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.init();
  // Attach at 0, 100 ms debounce, 10 ms reset (USB 2.0 §7.1.7.3, §7.1.7.5).
  bench.chip.scheduler().run_until(109 * kMillisecond);
  EXPECT_TRUE(s.reg(kPortSc1) & kPortPr);
  EXPECT_FALSE(s.reg(kUsbSts) & kStsPci);
  bench.chip.scheduler().run_until(111 * kMillisecond);
  const uint32_t port = s.reg(kPortSc1);
  EXPECT_FALSE(port & kPortPr);
  EXPECT_TRUE(port & kPortHsp);
  EXPECT_EQ((port >> 26) & 3u, 2u);  // PSPD: high speed
  EXPECT_TRUE(s.reg(kUsbSts) & kStsPci);
}

TEST(UsbRegisters, ForcedFullSpeedComesUpAtFullSpeed) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.init();
  s.set(kPortSc1, kPortPfsc);
  bench.chip.scheduler().run_until(111 * kMillisecond);
  EXPECT_FALSE(s.reg(kPortSc1) & kPortHsp);
  EXPECT_EQ((s.reg(kPortSc1) >> 26) & 3u, 0u);
}

TEST(UsbRegisters, GeneralPurposeTimerExpiresAfterLoadPlusOneMicroseconds) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.set(kUsbIntr, kStsTi0);
  s.set(kGpTimer0Ld, 74);  // 75 µs, as Teensyduino's serial flush uses it
  bench.chip.scheduler().run_until(10 * kMicrosecond);
  s.set(kGpTimer0Ctrl, kGptRun | kGptReset);
  bench.chip.scheduler().run_until(40 * kMicrosecond);
  EXPECT_EQ(s.reg(kGpTimer0Ctrl) & kGptCountMask, 74u - 30u);
  bench.chip.scheduler().run_until(84 * kMicrosecond + 999);
  EXPECT_FALSE(s.reg(kUsbSts) & kStsTi0);
  bench.chip.scheduler().run_until(85 * kMicrosecond);
  EXPECT_TRUE(s.reg(kUsbSts) & kStsTi0);
  EXPECT_TRUE(bench.chip.irq113);
  EXPECT_EQ(s.reg(kGpTimer0Ctrl) & kGptCountMask, 0u);  // one-shot: stays at 0
}

TEST(UsbRegisters, RestartingTheTimerPostponesItsExpiry) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.set(kGpTimer0Ld, 74);
  s.set(kGpTimer0Ctrl, kGptRun | kGptReset);
  bench.chip.scheduler().run_until(50 * kMicrosecond);
  s.set(kGpTimer0Ctrl, kGptRun | kGptReset);  // another write() before the flush
  bench.chip.scheduler().run_until(100 * kMicrosecond);
  EXPECT_FALSE(s.reg(kUsbSts) & kStsTi0);
  bench.chip.scheduler().run_until(125 * kMicrosecond);
  EXPECT_TRUE(s.reg(kUsbSts) & kStsTi0);
}

TEST(UsbRegisters, ControllerResetReturnsRegistersAndDetaches) {
  UsbBench bench;
  FakeDeviceStack& s = bench.stack;
  s.init();
  EXPECT_TRUE(bench.usb().attached());
  s.set(kUsbCmd, kCmdReset);
  EXPECT_EQ(s.reg(kUsbCmd), 0x00080000u);  // RST done at once, RS gone
  EXPECT_EQ(s.reg(kUsbMode), 0u);
  EXPECT_EQ(s.reg(kEndptListAddr), 0u);
  EXPECT_FALSE(bench.usb().attached());
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing
