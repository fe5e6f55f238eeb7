// A ByteStream over any Arduino-style port (Stream, usb_serial_class, HardwareSerial), without
// including a single Arduino header: the port's type is known only where a sketch names it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <type_traits>

#include "stepdance/core/byte_stream.hpp"

namespace stepdance {

/// Lets the core's interfaces (G-code, EBB, RPC) read and write a port given as the original
/// library's `begin(&Serial)` / `begin(&SerialUSB1)` / `begin(&Serial1, baud)` arguments.
///
/// attach() records the port and four functions instantiated for its type; the port must offer
/// available(), read(), availableForWrite() and write(const uint8_t*, size_t), as every Arduino
/// serial port does. A port that already is a ByteStream (the simulator's ports) is used
/// directly. Writes never block: only availableForWrite() bytes are handed over.
/// Context: loop only (as the ports themselves).
class ArduinoStreamAdapter final : public ByteStream {
 public:
  /// Points the adapter at `port` (not null). Returns the stream to use: the port itself when it
  /// is a ByteStream, else this adapter.
  template <class Port>
  ByteStream& attach(Port* port) {
    if constexpr (std::is_base_of_v<ByteStream, Port>) {
      return *port;
    } else {
      port_ = port;
      available_ = [](void* p) { return static_cast<Port*>(p)->available(); };
      read_ = [](void* p) { return static_cast<Port*>(p)->read(); };
      write_space_ = [](void* p) { return static_cast<int>(static_cast<Port*>(p)->availableForWrite()); };
      write_ = [](void* p, const uint8_t* data, size_t length) {
        return static_cast<size_t>(static_cast<Port*>(p)->write(data, length));
      };
      return *this;
    }
  }

  size_t bytes_available() override {
    const int count = port_ != nullptr ? available_(port_) : 0;
    return count > 0 ? static_cast<size_t>(count) : 0;
  }
  int read_byte() override { return port_ != nullptr ? read_(port_) : -1; }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    const size_t room = write_space();
    const size_t count = length < room ? length : room;
    return count == 0 ? 0 : write_(port_, data, count);
  }
  size_t write_space() override {
    const int space = port_ != nullptr ? write_space_(port_) : 0;
    return space > 0 ? static_cast<size_t>(space) : 0;
  }

 private:
  void* port_ = nullptr;
  int (*available_)(void*) = nullptr;
  int (*read_)(void*) = nullptr;
  int (*write_space_)(void*) = nullptr;
  size_t (*write_)(void*, const uint8_t*, size_t) = nullptr;
};

}  // namespace stepdance
