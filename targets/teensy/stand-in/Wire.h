// Stand-in declarations of Teensyduino's Wire library, as far as the Teensy backend uses it (the
// list is in teensyduino_services.hpp). The definitions in teensyduino_stand_in.cpp behave as a
// bus with nothing attached: every address goes unanswered.
#pragma once

#include <stddef.h>
#include <stdint.h>

/// One LPI2C controller as Teensyduino presents it.
class TwoWire {
 public:
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
};

extern TwoWire Wire;   // pins 18 (SDA) / 19 (SCL)
extern TwoWire Wire1;  // pins 17 (SDA1) / 16 (SCL1)
