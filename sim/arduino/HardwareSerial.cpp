// Serial ports on the host over hal::console() and the backend's serial streams.
#include "HardwareSerial.h"

#include <initializer_list>

#include "arduino_state.hpp"
#include "stepdance/hal/console.hpp"

using stepdance::arduino_backend::SerialPortId;

HardwareSerial Serial;
HardwareSerial SerialUSB1(SerialPortId::kUsb1);
HardwareSerial SerialUSB2(SerialPortId::kUsb2);
HardwareSerial Serial1(SerialPortId::kUart1);
HardwareSerial Serial2(SerialPortId::kUart2);
HardwareSerial Serial3(SerialPortId::kUart3);
HardwareSerial Serial4(SerialPortId::kUart4);
HardwareSerial Serial5(SerialPortId::kUart5);
HardwareSerial Serial6(SerialPortId::kUart6);
HardwareSerial Serial7(SerialPortId::kUart7);
HardwareSerial Serial8(SerialPortId::kUart8);

namespace {

// A refused write waits in steps this long, giving up after this much time without progress.
constexpr uint32_t kWriteWaitStepUs = 1000;
constexpr uint32_t kWriteGiveUpUs = 100000;

// available() reports at most this many bytes (it returns an int).
constexpr size_t kMaxReportedBytes = 0x7FFFFFFF;

int clamp_to_int(size_t count) { return static_cast<int>(count < kMaxReportedBytes ? count : kMaxReportedBytes); }

}  // namespace

namespace stepdance::arduino::internal {
void reset_serial_state() {
  for (HardwareSerial* port : {&Serial, &SerialUSB1, &SerialUSB2, &Serial1, &Serial2, &Serial3, &Serial4, &Serial5,
                               &Serial6, &Serial7, &Serial8}) {
    port->reset_port();
  }
}
}  // namespace stepdance::arduino::internal

stepdance::ByteStream* HardwareSerial::stream() const {
  if (backing_ == Backing::kConsole) return &stepdance::hal::console();
  return stepdance::arduino_backend::serial_stream(port_);
}

void HardwareSerial::reset_port() {
  peeked_ = -1;
  reset_stream_settings();
}

size_t HardwareSerial::bytes_available() {
  stepdance::ByteStream* source = stream();
  const size_t waiting = source != nullptr ? source->bytes_available() : 0;
  return waiting + (peeked_ >= 0 ? 1 : 0);
}

int HardwareSerial::available() { return clamp_to_int(bytes_available()); }

int HardwareSerial::read() {
  if (peeked_ >= 0) {
    const int byte = peeked_;
    peeked_ = -1;
    return byte;
  }
  stepdance::ByteStream* source = stream();
  return source != nullptr ? source->read_byte() : -1;
}

int HardwareSerial::peek() {
  if (peeked_ < 0) {
    stepdance::ByteStream* source = stream();
    if (source != nullptr) peeked_ = source->read_byte();
  }
  return peeked_;
}

size_t HardwareSerial::write(uint8_t byte) { return write(&byte, 1); }

size_t HardwareSerial::write(const uint8_t* buffer, size_t size) {
  stepdance::ByteStream* sink = stream();
  if (sink == nullptr) return size;  // nothing connected: discarded
  size_t written = 0;
  uint32_t waited_us = 0;
  while (written < size) {
    const size_t accepted = sink->write_bytes(buffer + written, size - written);
    written += accepted;
    if (written == size) break;
    if (accepted > 0) {
      waited_us = 0;
      continue;
    }
    if (waited_us >= kWriteGiveUpUs) break;
    stepdance::arduino_backend::delay_us(kWriteWaitStepUs);
    waited_us += kWriteWaitStepUs;
    sink = stream();
    if (sink == nullptr) return size;
  }
  return written;
}

size_t HardwareSerial::write_bytes(const uint8_t* data, size_t length) {
  // The ByteStream side never waits: it hands over what fits now.
  stepdance::ByteStream* sink = stream();
  if (sink == nullptr) return length;
  return sink->write_bytes(data, length);
}

size_t HardwareSerial::write_space() {
  stepdance::ByteStream* sink = stream();
  return sink != nullptr ? sink->write_space() : static_cast<size_t>(kMaxReportedBytes);
}

int HardwareSerial::availableForWrite() { return clamp_to_int(write_space()); }
