// Serial ports on the host: Serial (the console), SerialUSB1/2 and Serial1..Serial8.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "Stream.h"
#include "arduino_backend.hpp"
#include "stepdance/core/byte_stream.hpp"

/// One serial port as a sketch sees it: an Arduino Stream, and also a stepdance::ByteStream, so
/// `&Serial` can be handed to any core interface that reads a ByteStream.
///
/// `Serial` is the board's console, hal::console() (USB serial on a Teensy). The other ports ask
/// arduino_backend::serial_stream() for their stream on every access; a port with no stream
/// discards what is written (counting it as written) and has nothing to read.
///
/// Writes never block for long: when the stream refuses bytes, the port waits in 1 ms steps of
/// board time (as USB serial waits for a slow host) and gives up after 100 ms without
/// progress, dropping the rest; the return value counts the bytes accepted. Baud rates and
/// formats are accepted and ignored (the host moves bytes, not bits). Context: loop.
class HardwareSerial : public Stream, public stepdance::ByteStream {
 public:
  /// Which stream backs the port.
  enum class Backing : uint8_t { kConsole, kBackendPort };

  /// The console port.
  constexpr HardwareSerial() = default;
  /// A port the backend provides.
  explicit constexpr HardwareSerial(stepdance::arduino_backend::SerialPortId port)
      : backing_(Backing::kBackendPort), port_(port) {}

  /// Opens the port; the host ignores the rate and the format.
  void begin(uint32_t baud) { (void)baud; }
  void begin(uint32_t baud, uint16_t format) { (void)baud, (void)format; }
  /// Closes the port (nothing to do on the host).
  void end() {}
  /// True: the port is always ready (`while (!Serial) {}` returns at once).
  explicit operator bool() const { return true; }
  /// USB "data terminal ready": the host monitor has the port open. Always true here.
  bool dtr() const { return true; }

  // Stream
  int available() override;
  int read() override;
  int peek() override;
  // Print
  size_t write(uint8_t byte) override;
  size_t write(const uint8_t* buffer, size_t size) override;
  using Print::write;
  int availableForWrite() override;
  void flush() override {}

  // stepdance::ByteStream, sharing the peeked byte with the Stream side.
  size_t bytes_available() override;
  int read_byte() override { return read(); }
  size_t write_bytes(const uint8_t* data, size_t length) override;
  size_t write_space() override;

  /// Drops a peeked byte and restores the default timeout (used by arduino::reset_state).
  void reset_port();

 private:
  // The stream behind the port, or nullptr when nothing is connected.
  stepdance::ByteStream* stream() const;

  Backing backing_ = Backing::kConsole;
  stepdance::arduino_backend::SerialPortId port_ = stepdance::arduino_backend::SerialPortId::kUsb1;
  int peeked_ = -1;  // a byte peek() took off the stream, or −1
};

/// The console (USB serial).
extern HardwareSerial Serial;
/// The extra USB serial ports of the "Dual Serial" / "Triple Serial" USB types.
extern HardwareSerial SerialUSB1;
extern HardwareSerial SerialUSB2;
/// The hardware UARTs of a Teensy 4.1.
extern HardwareSerial Serial1;
extern HardwareSerial Serial2;
extern HardwareSerial Serial3;
extern HardwareSerial Serial4;
extern HardwareSerial Serial5;
extern HardwareSerial Serial6;
extern HardwareSerial Serial7;
extern HardwareSerial Serial8;
