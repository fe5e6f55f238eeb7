// The emulated host enumerates the scripted device stack as a PC would.
#include <gtest/gtest.h>

#include "usb_bench.hpp"

namespace stepdance::sim::image::usb::testing {
namespace {

std::vector<uint8_t> setup_bytes(uint8_t type, uint8_t request, uint16_t value, uint16_t index, uint16_t length) {
  return {type,
          request,
          static_cast<uint8_t>(value),
          static_cast<uint8_t>(value >> 8),
          static_cast<uint8_t>(index),
          static_cast<uint8_t>(index >> 8),
          static_cast<uint8_t>(length),
          static_cast<uint8_t>(length >> 8)};
}

TEST(UsbEnumeration, ReadsTheDescriptorsByteForByte) {
  UsbBench bench;
  bench.enumerate();
  const HostRecord& r = bench.host().record();
  EXPECT_EQ(r.device_bytes, kDeviceDescriptor);
  EXPECT_EQ(r.configuration_bytes, kConfiguration);  // 75 bytes: two 64-byte packets' worth
  EXPECT_EQ(r.device.vendor_id, 0x16C0);
  EXPECT_EQ(r.device.product_id, 0x0483);
  EXPECT_EQ(r.manufacturer, "Maker");
  EXPECT_EQ(r.product, "Serial");
  EXPECT_EQ(r.serial_number, "42");
}

TEST(UsbEnumeration, FindsTheCdcFunction) {
  UsbBench bench;
  bench.enumerate();
  const CdcFunction& cdc = bench.host().record().cdc;
  EXPECT_EQ(cdc.comm_interface, 0);
  EXPECT_EQ(cdc.data_interface, 1);
  EXPECT_EQ(cdc.notify_endpoint, 0x82);
  EXPECT_EQ(cdc.bulk_out, 0x03);
  EXPECT_EQ(cdc.bulk_in, 0x84);
  EXPECT_EQ(cdc.bulk_in_max_packet, 512);
  EXPECT_TRUE(cdc.has_association);
  EXPECT_EQ(bench.host().record().speed, BusSpeed::kHigh);
  EXPECT_TRUE(bench.stack.high_speed);  // the stack saw PORTSC1.HSP after the reset
}

TEST(UsbEnumeration, SendsThePcRequestsInOrder) {
  UsbBench bench;
  bench.enumerate();
  const auto& s = bench.stack.setups;
  ASSERT_EQ(s.size(), 12u);
  EXPECT_EQ(s[0], setup_bytes(0x80, 6, 0x0100, 0, 64));  // device descriptor at address 0
  EXPECT_EQ(s[1], setup_bytes(0x00, 5, 1, 0, 0));        // SET_ADDRESS 1
  EXPECT_EQ(s[2], setup_bytes(0x80, 6, 0x0100, 0, 18));
  EXPECT_EQ(s[3], setup_bytes(0x80, 6, 0x0200, 0, 9));
  EXPECT_EQ(s[4], setup_bytes(0x80, 6, 0x0200, 0, 75));
  EXPECT_EQ(s[5], setup_bytes(0x80, 6, 0x0300, 0, 255));
  EXPECT_EQ(s[6], setup_bytes(0x80, 6, 0x0301, 0x0409, 255));
  EXPECT_EQ(s[9], setup_bytes(0x00, 9, 1, 0, 0));      // SET_CONFIGURATION 1
  EXPECT_EQ(s[10], setup_bytes(0x21, 0x20, 0, 0, 7));  // SET_LINE_CODING, interface 0
  EXPECT_EQ(s[11], setup_bytes(0x21, 0x22, 3, 0, 0));  // SET_CONTROL_LINE_STATE: DTR | RTS
}

TEST(UsbEnumeration, CdcRequestsReachTheDevice) {
  UsbBench bench;
  bench.enumerate();
  // PSTN 1.2 table 17: dwDTERate 115200 (0x0001C200, little-endian), 1 stop bit, no parity, 8 bits.
  EXPECT_EQ(bench.stack.line_coding, (std::vector<uint8_t>{0x00, 0xC2, 0x01, 0x00, 0, 0, 8}));
  EXPECT_EQ(bench.stack.line_state, 3);
  EXPECT_TRUE(bench.stack.configured);
}

TEST(UsbEnumeration, NewAddressTakesEffectAfterTheStatusStage) {
  UsbBench bench;
  bench.enumerate();
  ASSERT_EQ(bench.stack.address_writes.size(), 1u);
  EXPECT_EQ(bench.stack.address_writes[0], (1u << 25) | (1u << 24));  // USBADR 1, USBADRA
  EXPECT_EQ(bench.usb().address(), 1);
  EXPECT_EQ(bench.host().record().address, 1);
}

TEST(UsbEnumeration, TakesTheSpecsWaitsAndNoMore) {
  UsbBench bench;
  bench.enumerate();
  const HostRecord& r = bench.host().record();
  EXPECT_EQ(r.attached_ns, 0);
  // 100 ms debounce + 10 ms reset + 10 ms recovery + 2 ms after SET_ADDRESS, then microframes.
  EXPECT_GE(r.configured_ns, 122 * kMillisecond);
  EXPECT_LT(r.configured_ns, 125 * kMillisecond);
  EXPECT_EQ(bench.stack.bus_resets, 1);
  EXPECT_EQ(
      bench.host().describe(),
      "usb host: configured at 0.124750 s, high speed, 16C0:0483 \"Maker\" \"Serial\", CDC bulk IN 0x84 OUT 0x03");
}

TEST(UsbEnumeration, ADeviceThatNeverAnswersIsReportedInOneLine) {
  UsbBench bench;
  bench.stack.answer_device_descriptor = false;
  bench.stack.init();
  bench.stack.run_until(2 * kSecond);
  const std::string& failure = bench.host().failure();
  EXPECT_FALSE(bench.host().enumerated());
  EXPECT_NE(failure.find("GET_DESCRIPTOR(device) at address 0"), std::string::npos) << failure;
  EXPECT_NE(failure.find("data stage"), std::string::npos) << failure;
  EXPECT_NE(failure.find("9.2.6.4"), std::string::npos) << failure;
  EXPECT_EQ(failure.find('\n'), std::string::npos);
  // 120 ms to the first request, then the 500 ms data-stage limit.
  EXPECT_NE(failure.find("at 0.62"), std::string::npos) << failure;
}

TEST(UsbEnumeration, APoweredDownPhyKeepsTheDeviceOffTheBus) {
  UsbBench bench;
  bench.stack.init(/*power_phy=*/false);
  bench.stack.run_until(500 * kMillisecond);
  EXPECT_FALSE(bench.host().enumerated());
  EXPECT_EQ(bench.host().record().attached_ns, -1);
  EXPECT_NE(bench.usb().detached_reason().find("USBPHY1_CTRL.SFTRST"), std::string::npos)
      << bench.usb().detached_reason();
  EXPECT_EQ(bench.host().describe(),
            "usb host: no device attached (USBPHY1_CTRL.SFTRST is 1 (the PHY is held in reset))");
}

TEST(UsbEnumeration, AStalledRequiredRequestFails) {
  UsbBench bench;
  bench.stack.init();
  // Stall everything from the start: the device never answers GET_DESCRIPTOR.
  bench.stack.answer_device_descriptor = false;
  bench.stack.run_until(120 * kMillisecond + 500 * kMicrosecond);
  bench.stack.set(kEndptCtrl0, 0x00010001u);
  bench.stack.run_until(200 * kMillisecond);
  EXPECT_NE(bench.host().failure().find("STALL"), std::string::npos) << bench.host().failure();
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing

namespace stepdance::sim::image::usb::testing {
namespace {

TEST(UsbEnumeration, AtFullSpeedHighSpeedPacketSizesAreRefused) {
  UsbBench bench;
  bench.stack.init();
  bench.stack.set(kPortSc1, kPortPfsc);  // force full speed: the 512-byte bulk endpoints are wrong
  bench.stack.run_until(300 * kMillisecond);
  EXPECT_EQ(bench.host().record().speed, BusSpeed::kFull);
  EXPECT_NE(bench.host().failure().find("wMaxPacketSize 512/512 (USB 2.0 §5.8.3: at most 64 at full speed)"),
            std::string::npos)
      << bench.host().failure();
}

TEST(UsbEnumeration, FullSpeedWorksInOneMillisecondFrames) {
  UsbBench bench;
  bench.stack.init();
  bench.stack.set(kPortSc1, kPortPfsc);
  bench.stack.full_speed_configuration = true;
  bench.stack.run_until(300 * kMillisecond);
  ASSERT_EQ(bench.host().failure(), "");
  ASSERT_TRUE(bench.host().enumerated());
  // Each request needs at least one more 1 ms frame than at high speed: 12 requests after 122 ms.
  EXPECT_GE(bench.host().record().configured_ns, 134 * kMillisecond);
  EXPECT_EQ(bench.host().record().cdc.bulk_in_max_packet, 64);
  // Host activity sits on frame boundaries: 1 ms after the end of reset at 110 ms.
  EXPECT_EQ((bench.host().record().configured_ns - 110 * kMillisecond) % kMillisecond, 0);
}

TEST(UsbEnumeration, SofInterruptsComeEachMicroframeWhileEnabled) {
  UsbBench bench;
  bench.enumerate();
  FakeDeviceStack& s = bench.stack;
  s.set(kUsbSts, kStsSri);
  s.set(kUsbIntr, s.reg(kUsbIntr) | kStsSri);
  const SimTime start = bench.chip.now_ns();
  int sofs = 0;
  for (SimTime t = start + 5 * kMicrosecond; t <= start + 1 * kMillisecond; t += 5 * kMicrosecond) {
    bench.chip.scheduler().run_until(t);
    if (s.reg(kUsbSts) & kStsSri) {
      ++sofs;
      s.set(kUsbSts, kStsSri);
    }
  }
  EXPECT_EQ(sofs, 8);  // 1 ms of 125 µs microframes
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing

namespace stepdance::sim::image::usb::testing {
namespace {

TEST(UsbEnumeration, ATerminalClosingAndOpeningThePortTogglesDtr) {
  UsbBench bench;
  bench.enumerate();
  ASSERT_EQ(bench.stack.line_state, 3);
  bench.host().set_line_state(false, false);  // the port closed
  bench.stack.run_until(bench.chip.now_ns() + kMillisecond);
  EXPECT_EQ(bench.stack.line_state, 0);
  bench.host().set_line_state(true, false);  // opened again, DTR only
  bench.stack.run_until(bench.chip.now_ns() + kMillisecond);
  EXPECT_EQ(bench.stack.line_state, 1);
  EXPECT_EQ(bench.stack.setups.back(), (std::vector<uint8_t>{0x21, 0x22, 1, 0, 0, 0, 0, 0}));
  EXPECT_TRUE(bench.host().enumerated());
  EXPECT_EQ(bench.host().failure(), "");
}

TEST(UsbEnumeration, ALineStateSetBeforeEnumerationIsTheOneSent) {
  UsbBench bench;
  bench.host().set_line_state(false, true);  // a port opened with DTR off (RTS only)
  bench.enumerate();
  EXPECT_EQ(bench.stack.line_state, 2);
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing
