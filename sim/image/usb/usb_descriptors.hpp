// Reading a device's descriptors as a host does: the device descriptor, the configuration with
// its CDC-ACM function, and string descriptors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stepdance::sim::image::usb {

/// The fields of a device descriptor the host uses (USB 2.0 §9.6.1, table 9-8).
struct DeviceDescriptor {
  uint16_t usb_version = 0;  ///< bcdUSB
  uint8_t device_class = 0;
  uint8_t max_packet0 = 0;  ///< bMaxPacketSize0
  uint16_t vendor_id = 0;
  uint16_t product_id = 0;
  uint16_t device_version = 0;  ///< bcdDevice
  uint8_t manufacturer_index = 0, product_index = 0, serial_index = 0;
  uint8_t configurations = 0;
};

/// A CDC-ACM function found in a configuration (CDC 1.2 §3.4 / PSTN 1.2 §5.3: a communications
/// interface, class 2 subclass 2, with an interrupt IN notification endpoint; a data interface,
/// class 0x0A, with a bulk IN and a bulk OUT endpoint).
struct CdcFunction {
  uint8_t configuration_value = 0;  ///< bConfigurationValue
  uint16_t total_length = 0;        ///< wTotalLength
  uint8_t interfaces = 0;           ///< bNumInterfaces
  uint8_t comm_interface = 0xFF;
  uint8_t data_interface = 0xFF;
  uint8_t notify_endpoint = 0;  ///< endpoint address (0x80 | n), 0 if none
  uint16_t notify_max_packet = 0;
  uint8_t bulk_in = 0;  ///< endpoint address (0x80 | n)
  uint16_t bulk_in_max_packet = 0;
  uint8_t bulk_out = 0;
  uint16_t bulk_out_max_packet = 0;
  bool has_association = false;  ///< an interface association descriptor covers the pair
};

/// Parses an 18-byte device descriptor; false (and `error` set) if it is not one.
bool parse_device_descriptor(const std::vector<uint8_t>& bytes, DeviceDescriptor& device, std::string& error);
/// Parses a whole configuration descriptor set and finds its CDC-ACM function; false (and
/// `error` set, naming what is missing or malformed) if there is none.
bool parse_cdc_configuration(const std::vector<uint8_t>& bytes, CdcFunction& cdc, std::string& error);
/// A string descriptor's text (UTF-16LE code units below 0x80 as ASCII, others as '?').
std::string decode_string_descriptor(const std::vector<uint8_t>& bytes);

}  // namespace stepdance::sim::image::usb
