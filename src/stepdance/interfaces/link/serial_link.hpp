// The serial link under every host protocol: which port a protocol reads and answers on.
#pragma once

#include <stdint.h>

#include "stepdance/core/arduino_stream_adapter.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/status.hpp"

namespace stepdance::link {

namespace detail {
// Opens a hardware UART (a port type with begin(baud, format)); other ports need no opening.
template <class Port>
auto open_port(Port* port, uint32_t baud, uint16_t format, int) -> decltype(port->begin(baud, format), void()) {
  port->begin(baud, format);
}
template <class Port>
void open_port(Port*, uint32_t, uint16_t, long) {}
}  // namespace detail

/// Holds the byte stream a protocol talks through: the board's console, or a port given as the
/// original library's `begin(&Serial)` / `begin(&SerialUSB1)` / `begin(&Serial1, baud)`
/// arguments. Context: loop.
class SerialLink {
 public:
  /// The board's console (USB Serial). Never null.
  ByteStream* attach_console();
  /// Any Arduino-style port, or one of the simulator's streams; null when `port` is null.
  template <class Port>
  ByteStream* attach(Port* port) {
    stream_ = port == nullptr ? nullptr : &adapter_.attach(port);
    return stream_;
  }
  /// As attach(port), first opening a hardware UART at `baud` bit/s in `format` (Arduino's
  /// SERIAL_8N1 … values; 0 is the port's default).
  template <class Port>
  ByteStream* attach(Port* port, uint32_t baud, uint16_t format = 0) {
    if (port != nullptr) detail::open_port(port, baud, format, 0);
    return attach(port);
  }
  /// The stream attached last, or null before any attach.
  ByteStream* stream() const { return stream_; }

 private:
  ArduinoStreamAdapter adapter_;
  ByteStream* stream_ = nullptr;
};

/// Gives a protocol block the original library's three begin() overloads, written once.
/// `Protocol` derives from this and declares `Status begin_stream(ByteStream&)`, which starts it
/// on the attached stream (friend LinkedProtocol<Protocol> if it is private). A null port is
/// refused with kBadArgument before anything starts. Context: loop (setup).
template <class Protocol>
class LinkedProtocol {
 public:
  /// Starts on the board's console (USB Serial).
  Status begin() { return start(link_.attach_console()); }
  /// Starts on a port: `&Serial`, `&SerialUSB1`, any Arduino Stream.
  template <class Port>
  Status begin(Port* port) {
    return start(link_.attach(port));
  }
  /// Opens a hardware UART at `baud` (format as Arduino's SERIAL_8N1 …) and starts on it.
  template <class Port>
  Status begin(Port* port, uint32_t baud, uint16_t format = 0) {
    return start(link_.attach(port, baud, format));
  }

 protected:
  LinkedProtocol() = default;
  ~LinkedProtocol() = default;
  /// The stream the protocol talks through (null before begin).
  ByteStream* link_stream() const { return link_.stream(); }

 private:
  Status start(ByteStream* stream) {
    return stream == nullptr ? Status::kBadArgument : static_cast<Protocol*>(this)->begin_stream(*stream);
  }

  SerialLink link_;
};

}  // namespace stepdance::link
