// The stand-in USB serial's descriptors: one CDC-ACM function (USB 2.0 §9.6, the interface
// association ECN, CDC 1.2 §5.2.3, PSTN 1.2 §5.3). Endpoint numbers follow a Teensy serial's:
// notification 0x82, bulk OUT 0x03, bulk IN 0x84.
#include "usb_serial_device.h"

namespace stand_in_usb {
namespace {

constexpr uint8_t lo(uint16_t v) { return static_cast<uint8_t>(v & 0xFF); }
constexpr uint8_t hi(uint16_t v) { return static_cast<uint8_t>(v >> 8); }

constexpr uint16_t kVendorId = 0x16C0;   // PJRC's vendor ID for Teensy
constexpr uint16_t kProductId = 0x0483;  // a Teensy in "Serial" USB type
constexpr uint16_t kReleaseBcd = 0x0100;
constexpr uint16_t kConfigLength = 75;

// The descriptors below are laid out one field group a line, as USB 2.0's tables list them, which
// clang-format would break into one byte a line.
// clang-format off
const uint8_t kDevice[18] = {
    18, 1, lo(0x0200), hi(0x0200),  // bcdUSB 2.00
    0xEF, 0x02, 0x01,               // miscellaneous class, IAD protocol
    kControlPacket,
    lo(kVendorId), hi(kVendorId), lo(kProductId), hi(kProductId), lo(kReleaseBcd), hi(kReleaseBcd),
    1, 2, 3,  // manufacturer, product, serial number strings
    1,        // one configuration
};
// clang-format on

// USB 2.0 §9.6.2: what the device would be at the other speed.
const uint8_t kQualifier[10] = {10, 6, lo(0x0200), hi(0x0200), 0xEF, 0x02, 0x01, kControlPacket, 1, 0};

/// The configuration with bulk packets of `bulk` bytes (512 at high speed, 64 at full speed;
/// USB 2.0 §5.8.3) and the notification interval for that speed.
struct Configuration {
  uint8_t bytes[kConfigLength];
};
constexpr Configuration make_configuration(uint16_t bulk, uint8_t interval) {
  // clang-format off
  return Configuration{{
      9, 2, lo(kConfigLength), hi(kConfigLength), 2, 1, 0, 0xC0, 50,  // 2 interfaces, self powered, 100 mA
      8, 11, 0, 2, 0x02, 0x02, 0x01, 0,                                // IAD: interfaces 0-1, CDC ACM
      9, 4, 0, 0, 1, 0x02, 0x02, 0x01, 0,                              // interface 0: communications, ACM
      5, 0x24, 0x00, lo(0x0110), hi(0x0110),                           // CDC header, bcdCDC 1.10
      5, 0x24, 0x01, 0x00, 1,                                          // call management: data interface 1
      4, 0x24, 0x02, 0x02,                                             // ACM: line coding and line state
      5, 0x24, 0x06, 0, 1,                                             // union: control 0, data 1
      7, 5, 0x80 | kNotifyEndpoint, 3, kNotifyPacket, 0, interval,     // notification, interrupt IN
      9, 4, 1, 0, 2, 0x0A, 0x00, 0x00, 0,                              // interface 1: CDC data
      7, 5, kRxEndpoint, 2, lo(bulk), hi(bulk), 0,                     // bulk OUT
      7, 5, 0x80 | kTxEndpoint, 2, lo(bulk), hi(bulk), 0,              // bulk IN
  }};
  // clang-format on
}
constexpr Configuration kHighSpeed = make_configuration(512, 8);  // 2^(8-1) microframes = 16 ms
constexpr Configuration kFullSpeed = make_configuration(64, 16);  // 16 frames = 16 ms

const uint8_t kLanguages[4] = {4, 3, lo(0x0409), hi(0x0409)};  // English (United States)
const uint8_t kManufacturer[20] = {20, 3, 'S', 0, 't', 0, 'e', 0, 'p', 0, 'd', 0, 'a', 0, 'n', 0, 'c', 0, 'e', 0};
const uint8_t kProduct[22] = {22, 3, 'U', 0, 'S', 0, 'B', 0, ' ', 0, 'S', 0, 'e', 0, 'r', 0, 'i', 0, 'a', 0, 'l', 0};
const uint8_t kSerialNumber[10] = {10, 3, '0', 0, '0', 0, '0', 0, '1', 0};

const uint8_t* sized(const uint8_t* bytes, uint16_t size, uint16_t& length) {
  length = size;
  return bytes;
}

}  // namespace

const uint8_t* descriptor(uint16_t value, uint16_t index, uint16_t& length) {
  (void)index;  // one language: every string index answers in English
  switch (value) {
    case 0x0100: return sized(kDevice, sizeof kDevice, length);
    case 0x0200: return sized(high_speed() ? kHighSpeed.bytes : kFullSpeed.bytes, kConfigLength, length);
    case 0x0600: return sized(kQualifier, sizeof kQualifier, length);
    case 0x0300: return sized(kLanguages, sizeof kLanguages, length);
    case 0x0301: return sized(kManufacturer, sizeof kManufacturer, length);
    case 0x0302: return sized(kProduct, sizeof kProduct, length);
    case 0x0303: return sized(kSerialNumber, sizeof kSerialNumber, length);
    default: return nullptr;
  }
}

}  // namespace stand_in_usb
