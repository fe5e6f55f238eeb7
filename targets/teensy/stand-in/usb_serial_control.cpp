// The stand-in USB serial's control endpoint: standard requests (USB 2.0 §9.4) and the CDC-ACM
// requests (PSTN 1.2 §6.3.10–6.3.12), on endpoint 0's two queue heads.
#include <string.h>

#include "usb_serial_device.h"

namespace stand_in_usb {
namespace {

TransferDescriptor data_td;
TransferDescriptor status_td;
alignas(32) uint8_t reply[128];  // descriptors are copied to RAM before the controller sends them
alignas(32) uint8_t line_coding[7] = {0x00, 0xC2, 0x01, 0x00, 0, 0, 8};  // 115200 8N1 until set
alignas(32) uint8_t received[8];
bool line_coding_pending = false;
uint8_t configuration = 0;

// wRequestAndType values: bRequest << 8 | bmRequestType.
constexpr uint16_t kGetStatus = 0x0080, kClearFeatureEndpoint = 0x0102, kSetAddress = 0x0500;
constexpr uint16_t kGetDescriptor = 0x0680, kGetConfiguration = 0x0880, kSetConfiguration = 0x0900;
constexpr uint16_t kSetLineCoding = 0x2021, kGetLineCoding = 0x21A1, kSetLineState = 0x2221;
constexpr uint16_t kSendBreak = 0x2321;

void clear_control_completions() { usb(kEndptComplete) = queue_bit(0) | queue_bit(1); }

/// Data stage IN of `length` bytes (≤ asked), then the host's zero-length OUT as status.
void send(const uint8_t* bytes, uint16_t length, uint16_t asked) {
  if (length > asked) length = asked;
  if (length > sizeof reply) length = sizeof reply;
  memcpy(reply, bytes, length);
  clear_control_completions();
  prime(queue(0, true), data_td, reply, length, false);
  prime(queue(0, false), status_td, nullptr, 0, false);
}

/// Status stage only: a zero-length IN.
void acknowledge(bool interrupt = false) {
  clear_control_completions();
  prime(queue(0, true), status_td, nullptr, 0, interrupt);
}

void stall() { usb(kEndptCtrl0) = 0x00810081u; }  // RXS and TXS; the enables are fixed

void get_descriptor(uint16_t value, uint16_t index, uint16_t asked) {
  uint16_t length = 0;
  const uint8_t* bytes = descriptor(value, index, length);
  if (bytes == nullptr) return stall();
  send(bytes, length, asked);
}

void standard_request(uint16_t request, uint16_t value, uint16_t index, uint16_t length) {
  switch (request) {
    case kGetDescriptor: return get_descriptor(value, index, length);
    case kSetAddress:
      acknowledge();
      // USBADRA: the controller takes the address after the status stage (RM USB_nDEVICEADDR).
      usb(kDeviceAddr) = (static_cast<uint32_t>(value) << 25) | kDeviceAddrAdvance;
      return;
    case kSetConfiguration:
      configuration = static_cast<uint8_t>(value);
      if (configuration != 0) configure_serial();
      return acknowledge();
    case kGetConfiguration: return send(&configuration, 1, length);
    case kGetStatus: {
      static const uint8_t kZero[2] = {0, 0};
      return send(kZero, 2, length);
    }
    case kClearFeatureEndpoint: return acknowledge();
    default: return stall();
  }
}

}  // namespace

void control_setup(const uint8_t s[8]) {
  const uint16_t request = static_cast<uint16_t>(s[0] | (s[1] << 8));
  const uint16_t value = static_cast<uint16_t>(s[2] | (s[3] << 8));
  const uint16_t index = static_cast<uint16_t>(s[4] | (s[5] << 8));
  const uint16_t length = static_cast<uint16_t>(s[6] | (s[7] << 8));
  line_coding_pending = false;
  switch (request) {
    case kSetLineCoding:
      if (length != sizeof line_coding) return stall();
      clear_control_completions();
      prime(queue(0, false), data_td, received, sizeof line_coding, false);
      prime(queue(0, true), status_td, nullptr, 0, true);
      line_coding_pending = true;
      return;
    case kGetLineCoding: return send(line_coding, sizeof line_coding, length);
    case kSetLineState: set_line_state(value); return acknowledge();
    case kSendBreak: return acknowledge();
    default: return standard_request(request, value, index, length);
  }
}

void control_complete(uint32_t complete) {
  if (line_coding_pending && (complete & queue_bit(queue(0, true)))) {
    memcpy(line_coding, received, sizeof line_coding);
    line_coding_pending = false;
  }
}

}  // namespace stand_in_usb
