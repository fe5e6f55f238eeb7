// Stand-in declarations of Teensyduino's Wire library, as far as the Teensy backend uses it (the
// list is in teensyduino_services.hpp). The definitions (wire.cpp) drive the i.MX RT1062's LPI2C1
// (Wire) and LPI2C3 (Wire1) as a bus master, with blocking transfers.
#pragma once

#include <stddef.h>
#include <stdint.h>

/// One LPI2C controller as Teensyduino presents it.
class TwoWire {
 public:
  /// Bytes one transfer can carry, as Teensyduino's Wire for the Teensy 4 (BUFFER_LENGTH).
  static constexpr size_t kBufferBytes = 136;

  explicit constexpr TwoWire(uint8_t controller) : controller_(controller) {}
  void begin();
  void setClock(uint32_t frequency);
  void beginTransmission(uint8_t address);
  size_t write(const uint8_t* data, size_t quantity);
  /// 0 ok, 1 too long, 2 address NACK, 3 data NACK, 4 other error, 5 timeout.
  uint8_t endTransmission(uint8_t sendStop);
  /// Bytes received (0 if the address went unanswered).
  uint8_t requestFrom(uint8_t address, uint8_t quantity, uint8_t sendStop);
  int available();
  int read();

 private:
  uint8_t controller_;  // 0 = LPI2C1 (Wire), 1 = LPI2C3 (Wire1)
  uint8_t address_ = 0;
  bool transmitting_ = false;
  bool too_long_ = false;
  uint8_t tx_length_ = 0;
  uint8_t rx_length_ = 0;
  uint8_t rx_index_ = 0;
  uint8_t tx_[kBufferBytes] = {};
  uint8_t rx_[kBufferBytes] = {};
};

extern TwoWire Wire;   // pins 18 (SDA) / 19 (SCL)
extern TwoWire Wire1;  // pins 17 (SDA1) / 16 (SCL1)
