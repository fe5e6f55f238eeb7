// The host's descriptor parsing (USB 2.0 §9.6, CDC 1.2 §5.2): what it finds, what it refuses.
#include <gtest/gtest.h>

#include "fake_device_stack.hpp"
#include "image/usb/usb_descriptors.hpp"

namespace stepdance::sim::image::usb::testing {
namespace {

TEST(UsbDescriptors, DeviceDescriptorFields) {
  DeviceDescriptor device;
  std::string error;
  ASSERT_TRUE(parse_device_descriptor(kDeviceDescriptor, device, error)) << error;
  EXPECT_EQ(device.usb_version, 0x0200);
  EXPECT_EQ(device.device_class, 0xEF);
  EXPECT_EQ(device.max_packet0, 64);
  EXPECT_EQ(device.vendor_id, 0x16C0);
  EXPECT_EQ(device.product_id, 0x0483);
  EXPECT_EQ(device.serial_index, 3);
  EXPECT_EQ(device.configurations, 1);
}

TEST(UsbDescriptors, AShortDeviceDescriptorIsRefused) {
  DeviceDescriptor device;
  std::string error;
  std::vector<uint8_t> bytes(kDeviceDescriptor.begin(), kDeviceDescriptor.begin() + 8);
  EXPECT_FALSE(parse_device_descriptor(bytes, device, error));
  EXPECT_NE(error.find("8 bytes"), std::string::npos) << error;
}

TEST(UsbDescriptors, AConfigurationWithoutTheDataInterfaceIsRefused) {
  // Drop interface 1 and its endpoints (the last 23 bytes) and fix wTotalLength.
  std::vector<uint8_t> bytes(kConfiguration.begin(), kConfiguration.end() - 23);
  bytes[2] = static_cast<uint8_t>(bytes.size());
  CdcFunction cdc;
  std::string error;
  EXPECT_FALSE(parse_cdc_configuration(bytes, cdc, error));
  EXPECT_EQ(error, "configuration has no CDC data interface");
}

TEST(UsbDescriptors, AWrongTotalLengthIsRefused) {
  std::vector<uint8_t> bytes = kConfiguration;
  bytes[2] = 80;
  CdcFunction cdc;
  std::string error;
  EXPECT_FALSE(parse_cdc_configuration(bytes, cdc, error));
  EXPECT_NE(error.find("wTotalLength"), std::string::npos);
}

TEST(UsbDescriptors, AVendorInterfaceBesideTheCdcPairIsIgnored) {
  // As Teensyduino 1.59's "Serial" configuration has: a third, vendor-specific interface.
  std::vector<uint8_t> bytes = kConfiguration;
  const std::vector<uint8_t> vendor = {9, 4, 2, 0, 0, 0xFF, 0x6A, 0xC7, 0};
  bytes.insert(bytes.end(), vendor.begin(), vendor.end());
  bytes[2] = static_cast<uint8_t>(bytes.size());
  bytes[4] = 3;
  CdcFunction cdc;
  std::string error;
  ASSERT_TRUE(parse_cdc_configuration(bytes, cdc, error)) << error;
  EXPECT_EQ(cdc.interfaces, 3);
  EXPECT_EQ(cdc.bulk_in, 0x84);
  EXPECT_EQ(cdc.bulk_out, 0x03);
}

TEST(UsbDescriptors, StringsDecodeFromUtf16) {
  EXPECT_EQ(decode_string_descriptor(kManufacturer), "Maker");
  EXPECT_EQ(decode_string_descriptor({6, 3, 0xE9, 0x00, 'x', 0}), "?x");  // é is not ASCII
  EXPECT_EQ(decode_string_descriptor({4, 2, 'x', 0}), "");                // not a string descriptor
}

}  // namespace
}  // namespace stepdance::sim::image::usb::testing
