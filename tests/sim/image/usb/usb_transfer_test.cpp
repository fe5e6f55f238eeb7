// Bulk transfers through dQHs and dTDs laid out as the RM gives them: expected tokens are
// computed from the dTD layout (total bytes 30:16, IOC 15, Active 7) and the USB 2.0 rules.
#include <gtest/gtest.h>

#include <string>

#include "usb_bench.hpp"

namespace stepdance::sim::image::usb::testing {
namespace {

constexpr unsigned kBulkOut = 2 * 3;     // dQH of endpoint 3 OUT
constexpr unsigned kBulkIn = 2 * 4 + 1;  // dQH of endpoint 4 IN

std::string ram_text(FakeChip& chip, uint32_t address, size_t length) {
  const auto* start = chip.ram.data() + (address - FakeChip::kRamBase);
  return std::string(start, start + length);
}

void put_text(FakeChip& chip, uint32_t address, const std::string& text) {
  std::copy(text.begin(), text.end(), chip.ram.begin() + (address - FakeChip::kRamBase));
}

TEST(UsbTransfers, BulkOutBytesLandInThePrimedDtd) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  s.make_dtd(FakeDeviceStack::kDtdRx, FakeDeviceStack::kRxBuffer, 512, true);
  s.prime(kBulkOut, FakeDeviceStack::kDtdRx);
  for (char c : std::string("hello")) bench.world.to_device.push_back(static_cast<uint8_t>(c));
  s.completions = 0;
  bench.chip.levels.clear();
  s.run_until(bench.chip.now_ns() + 2 * kMillisecond);
  EXPECT_EQ(ram_text(bench.chip, FakeDeviceStack::kRxBuffer, 5), "hello");
  // A short packet (5 < 512) retires the dTD: 507 bytes left, IOC kept, Active cleared.
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdRx + 4), (507u << 16) | (1u << 15));
  EXPECT_EQ(s.completions & (1u << 3), 1u << 3);  // ENDPTCOMPLETE bit 3 (ERCE3)
  EXPECT_FALSE(s.reg(kEndptStat) & (1u << 3));    // no longer primed
  ASSERT_FALSE(bench.chip.levels.empty());
  EXPECT_EQ(bench.chip.levels.front().irq, 113u);
  EXPECT_TRUE(bench.chip.levels.front().high);
  EXPECT_EQ(bench.host().out_pending(), 0u);
}

TEST(UsbTransfers, AnUnprimedEndpointHoldsTheHostsBytesUntilPrimed) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  for (char c : std::string("abc")) bench.world.to_device.push_back(static_cast<uint8_t>(c));
  s.run_until(bench.chip.now_ns() + 5 * kMillisecond);
  EXPECT_EQ(bench.host().out_pending(), 3u);  // NAKed: waiting in the host, not lost
  EXPECT_TRUE(bench.world.to_device.empty());
  s.make_dtd(FakeDeviceStack::kDtdRx, FakeDeviceStack::kRxBuffer, 512, true);
  const SimTime primed_at = bench.chip.now_ns();
  s.prime(kBulkOut, FakeDeviceStack::kDtdRx);
  EXPECT_GE(bench.chip.stops, 1);               // the prime woke the host: the CPU's run must end
  s.run_until(primed_at + 125 * kMicrosecond);  // within one microframe of the prime
  EXPECT_EQ(ram_text(bench.chip, FakeDeviceStack::kRxBuffer, 3), "abc");
  EXPECT_EQ(bench.host().out_pending(), 0u);
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdRx + 4) >> 16, 509u);
}

TEST(UsbTransfers, InCompletionSetsEndptCompleteAndRaisesIrq113) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  put_text(bench.chip, FakeDeviceStack::kTxBuffer, "0123456789");
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 10, true);
  s.set(kEndptComplete, 0xFFFFFFFFu);
  bench.chip.irq113 = false;
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  bench.chip.scheduler().run_until(bench.chip.now_ns() + 125 * kMicrosecond);  // no ISR taken
  EXPECT_EQ(std::string(bench.world.received.begin(), bench.world.received.end()), "0123456789");
  EXPECT_EQ(s.reg(kEndptComplete), 1u << 20);  // ETCE4: transmit endpoint 4
  EXPECT_TRUE(s.reg(kUsbSts) & kStsUi);
  EXPECT_TRUE(bench.chip.irq113);
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdTx + 4), 1u << 15);         // 0 left, IOC, not active
  EXPECT_EQ(bench.chip.word(s.head(kBulkIn) + 4), FakeDeviceStack::kDtdTx);  // current dTD pointer
}

TEST(UsbTransfers, AFullPacketTransferEndsWithAZeroLengthPacket) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  put_text(bench.chip, FakeDeviceStack::kTxBuffer, std::string(512, 'x'));
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 512, true);
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  // The host's transactions, one by one: the 512-byte packet leaves the dTD active (ZLT is
  // enabled in the dQH: a transfer ending on a full packet owes a zero-length packet).
  uint8_t packet[512];
  size_t length = 0;
  ASSERT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kAck);
  EXPECT_EQ(length, 512u);
  EXPECT_TRUE(bench.chip.word(FakeDeviceStack::kDtdTx + 4) & kTokenActive);
  ASSERT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kAck);
  EXPECT_EQ(length, 0u);
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdTx + 4), 1u << 15);
  EXPECT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kNak);
}

TEST(UsbTransfers, WithZltDisabledAFullPacketEndsTheTransfer) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  bench.chip.set_word(s.head(kBulkIn), (512u << 16) | kCapZltDisabled);
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 512, true);
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  uint8_t packet[512];
  size_t length = 0;
  ASSERT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kAck);
  EXPECT_EQ(length, 512u);
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdTx + 4), 1u << 15);
}

TEST(UsbTransfers, TokensToAnotherAddressOrADisabledEndpointGetNoAnswer) {
  UsbBench bench;
  bench.enumerate();
  uint8_t packet[64];
  size_t length = 0;
  EXPECT_EQ(bench.usb().in(0, 4, packet, sizeof packet, length), Handshake::kNoResponse);  // old address
  EXPECT_EQ(bench.usb().in(1, 5, packet, sizeof packet, length), Handshake::kNoResponse);  // not enabled
  EXPECT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kNak);         // nothing primed
  bench.stack.set(kEndptCtrl0 + 16, 0x00C80000u | kCtrlTxStall);
  EXPECT_EQ(bench.usb().in(1, 4, packet, sizeof packet, length), Handshake::kStall);
}

TEST(UsbTransfers, ATransferFollowsItsBufferAcrossPages) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  // 700 bytes starting 0x100 before a page end: page 0 holds 256 bytes, page 1 the rest.
  const uint32_t start = FakeDeviceStack::kTxBuffer + 0x1000 - 0x100;
  std::string text;
  for (int i = 0; i < 700; ++i) text += static_cast<char>('a' + i % 26);
  put_text(bench.chip, start, text);
  s.make_dtd(FakeDeviceStack::kDtdTx, start, 700, false);
  bench.chip.set_word(FakeDeviceStack::kDtdTx + 12, FakeDeviceStack::kTxBuffer + 0x1000);  // page 1
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  s.run_until(bench.chip.now_ns() + kMillisecond);
  EXPECT_EQ(std::string(bench.world.received.begin(), bench.world.received.end()), text);
  EXPECT_EQ(bench.chip.word(FakeDeviceStack::kDtdTx + 4), 0u);  // retired, no IOC
}

TEST(UsbTransfers, LinkedDtdsRunBackToBack) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  put_text(bench.chip, FakeDeviceStack::kTxBuffer, "first");
  put_text(bench.chip, FakeDeviceStack::kTxBuffer + 0x100, "second");
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 5, false);
  s.make_dtd(FakeDeviceStack::kDtdTx2, FakeDeviceStack::kTxBuffer + 0x100, 6, true);
  bench.chip.set_word(FakeDeviceStack::kDtdTx, FakeDeviceStack::kDtdTx2);  // next pointer
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  s.run_until(bench.chip.now_ns() + kMillisecond);
  EXPECT_EQ(std::string(bench.world.received.begin(), bench.world.received.end()), "firstsecond");
  EXPECT_EQ(s.completions & (1u << 20), 1u << 20);
  EXPECT_FALSE(s.reg(kEndptStat) & (1u << 20));
}

TEST(UsbTransfers, BytesTheWorldCannotTakeWaitInTheHost) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  bench.world.accept_limit = 4;
  put_text(bench.chip, FakeDeviceStack::kTxBuffer, "0123456789");
  s.make_dtd(FakeDeviceStack::kDtdTx, FakeDeviceStack::kTxBuffer, 10, true);
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  s.run_until(bench.chip.now_ns() + 125 * kMicrosecond);
  EXPECT_EQ(bench.world.received.size(), 4u);
  s.run_until(bench.chip.now_ns() + 3 * kMillisecond);
  EXPECT_EQ(std::string(bench.world.received.begin(), bench.world.received.end()), "0123456789");
}

TEST(UsbTransfers, ATransferIntoUnmappedMemoryIsASystemError) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  s.make_dtd(FakeDeviceStack::kDtdTx, 0x10000000u, 10, true);  // no RAM there
  s.prime(kBulkIn, FakeDeviceStack::kDtdTx);
  bench.chip.scheduler().run_until(bench.chip.now_ns() + kMillisecond);
  EXPECT_NE(bench.usb().dma_error().find("0x10000000"), std::string::npos) << bench.usb().dma_error();
  EXPECT_TRUE(s.reg(kUsbSts) & kStsSei);
  EXPECT_NE(bench.host().failure(), "");
}

TEST(UsbTransfers, TheHostTakesOnlyWhatItCanHoldAndLosesNothing) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  std::string text;
  for (int i = 0; i < 10000; ++i) text += static_cast<char>('0' + i % 75);
  bench.world.to_device.assign(text.begin(), text.end());
  s.run_until(bench.chip.now_ns() + 5 * kMillisecond);
  EXPECT_EQ(bench.host().out_pending(), 4096u);  // HostOptions::out_buffer_bytes
  EXPECT_EQ(bench.world.to_device.size(), 10000u - 4096u);
  // The device takes 512 bytes at a time; everything arrives, in order.
  std::string arrived;
  for (int round = 0; round < 40 && arrived.size() < text.size(); ++round) {
    s.make_dtd(FakeDeviceStack::kDtdRx, FakeDeviceStack::kRxBuffer, 512, true);
    s.prime(kBulkOut, FakeDeviceStack::kDtdRx);
    s.run_until(bench.chip.now_ns() + 250 * kMicrosecond);
    const uint32_t left = bench.chip.word(FakeDeviceStack::kDtdRx + 4) >> 16;
    arrived += ram_text(bench.chip, FakeDeviceStack::kRxBuffer, 512 - left);
  }
  EXPECT_EQ(arrived, text);
}

TEST(UsbTransfers, AControllerResetMakesTheHostEnumerateAgain) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  s.set(kUsbCmd, kCmdReset);
  s.run_until(bench.chip.now_ns() + 20 * kMillisecond);
  EXPECT_FALSE(bench.host().enumerated());
  EXPECT_NE(bench.host().describe().find("USB1_USBMODE.CM is not 2"), std::string::npos) << bench.host().describe();
  s.init();
  const SimTime attached = bench.chip.now_ns();
  s.run_until(attached + 300 * kMillisecond);
  EXPECT_TRUE(bench.host().enumerated());
  EXPECT_EQ(s.bus_resets, 2);
  EXPECT_GE(bench.host().record().attached_ns, attached);
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing
