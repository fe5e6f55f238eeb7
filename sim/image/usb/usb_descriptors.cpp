// Descriptor parsing (USB 2.0 §9.6, CDC 1.2 §5.2, PSTN 1.2 §5.3).
#include "image/usb/usb_descriptors.hpp"

#include <cstdio>

namespace stepdance::sim::image::usb {
namespace {

constexpr uint8_t kTypeDevice = 1, kTypeConfiguration = 2, kTypeInterface = 4, kTypeEndpoint = 5;
constexpr uint8_t kTypeInterfaceAssociation = 11;
constexpr uint8_t kClassComm = 0x02, kSubclassAcm = 0x02, kClassData = 0x0A;
constexpr uint8_t kAttributesBulk = 2, kAttributesInterrupt = 3;

uint16_t le16(const std::vector<uint8_t>& bytes, size_t at) {
  return static_cast<uint16_t>(bytes[at] | (bytes[at + 1] << 8));
}

bool fail(std::string& error, const std::string& why) {
  error = why;
  return false;
}

/// Files one endpoint descriptor under the interface it follows.
void note_endpoint(const std::vector<uint8_t>& bytes, size_t at, int interface_class, CdcFunction& cdc) {
  const uint8_t address = bytes[at + 2];
  const uint8_t type = bytes[at + 3] & 3u;
  const uint16_t max_packet = le16(bytes, at + 4) & 0x7FFu;
  const bool in = (address & 0x80u) != 0;
  if (interface_class == kClassComm && type == kAttributesInterrupt && in) {
    cdc.notify_endpoint = address;
    cdc.notify_max_packet = max_packet;
  } else if (interface_class == kClassData && type == kAttributesBulk) {
    (in ? cdc.bulk_in : cdc.bulk_out) = address;
    (in ? cdc.bulk_in_max_packet : cdc.bulk_out_max_packet) = max_packet;
  }
}

/// Files one interface descriptor; returns its class while it belongs to the CDC function.
int note_interface(const std::vector<uint8_t>& bytes, size_t at, CdcFunction& cdc) {
  const uint8_t number = bytes[at + 2], cls = bytes[at + 5], subclass = bytes[at + 6];
  if (cls == kClassComm && subclass == kSubclassAcm && cdc.comm_interface == 0xFF) {
    cdc.comm_interface = number;
    return kClassComm;
  }
  if (cls == kClassData && cdc.data_interface == 0xFF) {
    cdc.data_interface = number;
    return kClassData;
  }
  return -1;
}

}  // namespace

bool parse_device_descriptor(const std::vector<uint8_t>& bytes, DeviceDescriptor& device, std::string& error) {
  if (bytes.size() < 18 || bytes[0] != 18 || bytes[1] != kTypeDevice) {
    char text[120];
    std::snprintf(text, sizeof text, "device descriptor malformed (%zu bytes, bLength %d, bDescriptorType %d)",
                  bytes.size(), bytes.empty() ? -1 : bytes[0], bytes.size() < 2 ? -1 : bytes[1]);
    return fail(error, text);
  }
  device.usb_version = le16(bytes, 2);
  device.device_class = bytes[4];
  device.max_packet0 = bytes[7];
  device.vendor_id = le16(bytes, 8);
  device.product_id = le16(bytes, 10);
  device.device_version = le16(bytes, 12);
  device.manufacturer_index = bytes[14];
  device.product_index = bytes[15];
  device.serial_index = bytes[16];
  device.configurations = bytes[17];
  return true;
}

bool parse_cdc_configuration(const std::vector<uint8_t>& bytes, CdcFunction& cdc, std::string& error) {
  if (bytes.size() < 9 || bytes[0] != 9 || bytes[1] != kTypeConfiguration) {
    return fail(error, "configuration descriptor malformed");
  }
  cdc.total_length = le16(bytes, 2);
  cdc.interfaces = bytes[4];
  cdc.configuration_value = bytes[5];
  if (cdc.total_length != bytes.size()) return fail(error, "configuration wTotalLength disagrees with the bytes sent");
  int interface_class = -1;
  for (size_t at = bytes[0]; at < bytes.size();) {
    const uint8_t length = bytes[at];
    if (length < 2 || at + length > bytes.size()) return fail(error, "configuration has a descriptor that overruns it");
    const uint8_t type = bytes[at + 1];
    if (type == kTypeInterface && length >= 9) interface_class = note_interface(bytes, at, cdc);
    if (type == kTypeEndpoint && length >= 7) note_endpoint(bytes, at, interface_class, cdc);
    if (type == kTypeInterfaceAssociation && length >= 8 && bytes[at + 4] == kClassComm) cdc.has_association = true;
    at += length;
  }
  if (cdc.comm_interface == 0xFF) return fail(error, "configuration has no CDC-ACM communications interface");
  if (cdc.data_interface == 0xFF) return fail(error, "configuration has no CDC data interface");
  if (cdc.bulk_in == 0 || cdc.bulk_out == 0)
    return fail(error, "CDC data interface lacks a bulk IN or bulk OUT endpoint");
  return true;
}

std::string decode_string_descriptor(const std::vector<uint8_t>& bytes) {
  std::string text;
  if (bytes.size() < 2 || bytes[1] != 3) return text;
  const size_t end = bytes[0] < bytes.size() ? bytes[0] : bytes.size();
  for (size_t at = 2; at + 1 < end; at += 2) {
    const uint16_t unit = le16(bytes, at);
    text += unit < 0x80 ? static_cast<char>(unit) : '?';
  }
  return text;
}

}  // namespace stepdance::sim::image::usb
