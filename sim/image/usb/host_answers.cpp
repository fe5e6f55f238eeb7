// What the emulated host takes from each enumeration answer, and the checks a PC's USB stack
// makes of it (USB 2.0 §5.5.3 control packet sizes, §5.8.3 bulk packet sizes).
#include <cstdio>

#include "image/usb/usb_host.hpp"

namespace stepdance::sim::image::usb {
namespace {

enum Step : int { kDevice8, kAddress, kDevice, kConfigHead, kConfigAll, kLanguages, kManufacturer, kProduct, kSerial };

}  // namespace

bool UsbHost::handle_answer(const ControlTransfer& t) {
  const std::vector<uint8_t>& bytes = t.data;
  std::string error;
  char text[160];
  switch (step_) {
    case kDevice8:
      if (bytes.size() < 8 || bytes[1] != 1) {
        fail(t.name + ": the answer is not a device descriptor");
        return false;
      }
      max_packet0_ = bytes[7];
      if (max_packet0_ != 64 &&
          (record_.speed == BusSpeed::kHigh || (max_packet0_ != 8 && max_packet0_ != 16 && max_packet0_ != 32))) {
        std::snprintf(text, sizeof text,
                      "bMaxPacketSize0 is %u (USB 2.0 §5.5.3: 64 at high speed; 8, 16, 32 or 64 at full speed)",
                      max_packet0_);
        fail(text);
        return false;
      }
      return true;
    case kAddress:
      current_address_ = options_.address;
      record_.address = options_.address;
      phase_until_ns_ = chip_.now_ns() + options_.set_address_recovery_ns;
      return true;
    case kDevice:
      record_.device_bytes = bytes;
      if (!parse_device_descriptor(bytes, record_.device, error)) {
        fail(t.name + ": " + error);
        return false;
      }
      return true;
    case kConfigHead:
      if (bytes.size() < 9 || bytes[1] != 2) {
        fail(t.name + ": the answer is not a configuration descriptor");
        return false;
      }
      record_.cdc.total_length = static_cast<uint16_t>(bytes[2] | (bytes[3] << 8));
      return true;
    default: break;
  }
  return handle_late_answer(t);
}

bool UsbHost::handle_late_answer(const ControlTransfer& t) {
  const std::vector<uint8_t>& bytes = t.data;
  std::string error;
  char text[200];
  switch (step_) {
    case kConfigAll: {
      record_.configuration_bytes = bytes;
      if (!parse_cdc_configuration(bytes, record_.cdc, error)) {
        fail(t.name + ": " + error);
        return false;
      }
      const CdcFunction& c = record_.cdc;
      const bool high = record_.speed == BusSpeed::kHigh;
      const bool sizes_ok = high ? c.bulk_in_max_packet == 512 && c.bulk_out_max_packet == 512
                                 : c.bulk_in_max_packet <= 64 && c.bulk_out_max_packet <= 64;
      if (!sizes_ok) {
        std::snprintf(text, sizeof text, "bulk endpoints 0x%02X/0x%02X have wMaxPacketSize %u/%u (USB 2.0 §5.8.3: %s)",
                      c.bulk_in, c.bulk_out, c.bulk_in_max_packet, c.bulk_out_max_packet,
                      high ? "512 at high speed" : "at most 64 at full speed");
        fail(text);
        return false;
      }
      return true;
    }
    case kLanguages:
      if (!t.stalled && bytes.size() >= 4) language_ = static_cast<uint16_t>(bytes[2] | (bytes[3] << 8));
      return true;
    case kManufacturer: record_.manufacturer = decode_string_descriptor(bytes); return true;
    case kProduct: record_.product = decode_string_descriptor(bytes); return true;
    case kSerial: record_.serial_number = decode_string_descriptor(bytes); return true;
    default: return true;
  }
}

}  // namespace stepdance::sim::image::usb
