// The register sequences Teensyduino 1.59's teensy4/usb.c and usb_serial.c make (read from the
// public PaulStoffregen/cores at tag 1.59 for facts: which registers, in which order), played
// against the model so the real core's image finds what it expects: the controller reset on a
// PHY left powered down, receive dTDs chained while the endpoint runs (the ATDTW protocol), and
// the transmit flush from general-purpose timer 0, 75 µs after the last write.
#include <gtest/gtest.h>

#include <string>

#include "usb_bench.hpp"

namespace stepdance::sim::image::usb::testing {
namespace {

constexpr unsigned kRxQueue = 2 * 3;                             // endpoint 3 OUT (CDC_RX_ENDPOINT)
constexpr unsigned kTxQueue = 2 * 4 + 1;                         // endpoint 4 IN (CDC_TX_ENDPOINT)
constexpr uint32_t kRxDtds = FakeDeviceStack::kDtdData + 0x200;  // 8 dTDs, 32 bytes apart

/// Teensyduino's usb_init() up to RS, in its order.
void teensyduino_init(UsbBench& bench) {
  FakeDeviceStack& s = bench.stack;
  UsbPhy& phy = bench.blocks->phy;
  uint32_t pwd = 0;
  ASSERT_EQ(phy.read(0x00, 4, pwd), Access::kOk);
  // The reset-value PWD has the power-down bits usb_init() tests: it takes its reset path.
  ASSERT_NE(pwd & 0x001E1C00u, 0u);
  ASSERT_EQ(phy.write(0x34, 4, UsbPhy::kCtrlSoftReset), Access::kOk);  // USBPHY1_CTRL_SET = SFTRST
  s.set(kUsbCmd, s.reg(kUsbCmd) | kCmdReset);
  EXPECT_EQ(s.reg(kUsbCmd) & kCmdReset, 0u);  // while (USB1_USBCMD & USB_USBCMD_RST);
  ASSERT_EQ(phy.write(0x38, 4, UsbPhy::kCtrlSoftReset), Access::kOk);
  s.set(kBurstSize, 0x0404);
  ASSERT_EQ(phy.write(0x38, 4, UsbPhy::kCtrlClockGate), Access::kOk);
  ASSERT_EQ(phy.write(0x00, 4, 0), Access::kOk);
  s.set(kUsbMode, 2 | (1u << 3));
  bench.chip.set_word(s.head(0), (64u << 16) | (1u << 15));
  bench.chip.set_word(s.head(1), 64u << 16);
  s.set(kEndptListAddr, FakeDeviceStack::kQueueHeads);
  s.set(kUsbIntr, kStsUi | kStsUei | kStsUri | kStsSli);
  s.set(kUsbCmd, kCmdRunStop);
}

/// usb.c's schedule_transfer(): link behind the last dTD; re-prime only if the controller has
/// already left the endpoint (ENDPTSTAT read under the ATDTW tripwire).
void schedule_transfer(UsbBench& bench, unsigned queue, uint32_t dtd, uint32_t& last) {
  FakeDeviceStack& s = bench.stack;
  const uint32_t mask = queue_bit(queue);
  if (last != 0) {
    bench.chip.set_word(last, dtd);
    last = dtd;
    if (s.reg(kEndptPrime) & mask) return;
    uint32_t status = 0;
    do {
      s.set(kUsbCmd, s.reg(kUsbCmd) | kCmdAddDtdTripwire);
      status = s.reg(0x1B8);
    } while (!(s.reg(kUsbCmd) & kCmdAddDtdTripwire));
    if (status & mask) return;
  }
  last = dtd;
  s.prime(queue, dtd);
}

TEST(TeensyduinoSequence, InitOnAFreshChipEnumeratesAtHighSpeed) {
  UsbBench bench;
  teensyduino_init(bench);
  bench.stack.run_until(300 * kMillisecond);
  EXPECT_EQ(bench.host().failure(), "");
  EXPECT_TRUE(bench.host().enumerated());
  EXPECT_TRUE(bench.stack.high_speed);  // usb_high_speed = 1: 512-byte CDC packets
  EXPECT_EQ(bench.stack.reg(kBurstSize), 0x0404u);
}

TEST(TeensyduinoSequence, ChainedReceiveDtdsFillOneAfterAnother) {
  UsbBench bench;
  bench.enumerate();
  // usb_serial_configure(): rx dQH with 512-byte packets and ZLT off, then 8 dTDs queued.
  bench.chip.set_word(bench.stack.head(kRxQueue), (512u << 16) | kCapZltDisabled);
  uint32_t last = 0;
  for (uint32_t i = 0; i < 8; ++i) {
    bench.stack.make_dtd(kRxDtds + 32 * i, FakeDeviceStack::kRxBuffer + 512 * i, 512, true);
    schedule_transfer(bench, kRxQueue, kRxDtds + 32 * i, last);
  }
  // 3 full packets and a 10-byte one: four dTDs retire, the fifth waits, the endpoint stays primed.
  std::string text;
  for (int i = 0; i < 3 * 512 + 10; ++i) text += static_cast<char>('A' + i % 23);
  bench.world.to_device.assign(text.begin(), text.end());
  bench.stack.run_until(bench.chip.now_ns() + 2 * kMillisecond);
  const uint32_t retired_full = 1u << 15;  // 0 bytes left, IOC, not active
  EXPECT_EQ(bench.chip.word(kRxDtds + 4), retired_full);
  EXPECT_EQ(bench.chip.word(kRxDtds + 32 + 4), retired_full);
  EXPECT_EQ(bench.chip.word(kRxDtds + 64 + 4), retired_full);
  EXPECT_EQ(bench.chip.word(kRxDtds + 96 + 4), (502u << 16) | (1u << 15));
  EXPECT_EQ(bench.chip.word(kRxDtds + 128 + 4), (512u << 16) | (1u << 15) | kTokenActive);
  EXPECT_TRUE(bench.stack.reg(0x1B8) & (1u << 3));
  const auto* ram = bench.chip.ram.data() + (FakeDeviceStack::kRxBuffer - FakeChip::kRamBase);
  EXPECT_EQ(std::string(ram, ram + 3 * 512 + 10), text);
  // A dTD linked behind the active chain is found when the controller gets there: no re-prime.
  bench.stack.make_dtd(kRxDtds + 256, FakeDeviceStack::kRxBuffer + 0x1000 * 3, 512, true);
  schedule_transfer(bench, kRxQueue, kRxDtds + 256, last);
  // Not re-primed: a prime would have loaded the new dTD; the fifth is still the current one.
  EXPECT_EQ(bench.chip.word(bench.stack.head(kRxQueue) + 4), kRxDtds + 128);
  bench.world.to_device.assign(5 * 512, 'z');
  bench.stack.run_until(bench.chip.now_ns() + 2 * kMillisecond);
  EXPECT_EQ(bench.chip.word(kRxDtds + 224 + 4), retired_full);  // the eighth
  EXPECT_EQ(bench.chip.word(kRxDtds + 256 + 4), retired_full);  // the one linked late
  EXPECT_EQ(bench.host().out_pending(), 0u);
}

TEST(TeensyduinoSequence, TimerZeroFlushesAPartialTransmitBuffer) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  // usb_serial_configure(): timer_config(flush, 75): GPTIMER0LD = 74, TIE0 on.
  s.set(kGpTimer0Ctrl, 0);
  s.set(kGpTimer0Ld, 74);
  s.set(kUsbIntr, s.reg(kUsbIntr) | kStsTi0);
  // usb_serial_write() of 5 bytes: copied to the buffer, timer_start_oneshot().
  const std::string text = "G1 X5";
  std::copy(text.begin(), text.end(), bench.chip.ram.begin() + (FakeDeviceStack::kTxBuffer - FakeChip::kRamBase));
  const SimTime written = bench.chip.now_ns();
  s.set(kGpTimer0Ctrl, kGptRun | kGptReset);
  // The interrupt comes 75 µs later with TI0; the flush callback queues the 5 bytes.
  bench.chip.scheduler().run_until(written + 75 * kMicrosecond - 1);
  EXPECT_FALSE(bench.chip.irq113);
  bench.chip.scheduler().run_until(written + 75 * kMicrosecond);
  ASSERT_TRUE(bench.chip.irq113);
  const uint32_t status = s.reg(kUsbSts);
  s.set(kUsbSts, status);
  ASSERT_TRUE(status & kStsTi0);
  bench.chip.set_word(s.head(kTxQueue), 512u << 16);
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 5, false);
  uint32_t last = 0;
  schedule_transfer(bench, kTxQueue, FakeDeviceStack::kDtdTx, last);
  // The host polls bulk IN at the next microframe.
  bench.chip.scheduler().run_until(written + 75 * kMicrosecond + 125 * kMicrosecond);
  EXPECT_EQ(std::string(bench.world.received.begin(), bench.world.received.end()), text);
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing
