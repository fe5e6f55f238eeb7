// The ONLY door from the Teensy backend to the Teensyduino core (SdFat has its own,
// teensyduino_storage.hpp, so only sketches that use storage see it).
//
// Everything else in platform/teensy talks to the hardware through our own regs_*.hpp. Keep this
// list tiny: the CI stand-in (targets/teensy/stand-in/) declares exactly these, with these
// signatures, and nothing else.
//
//   <Arduino.h>
//     class usb_serial_class {
//       int available();                                  // bytes waiting to be read
//       int read();                                       // next byte, or -1
//       int availableForWrite();                          // room in the transmit buffer
//       size_t write(const uint8_t* buffer, size_t size); // queue bytes (never asked for more than
//     };                                                  //   availableForWrite(), so never waits)
//     extern usb_serial_class Serial;                     // the USB serial port
//     uint32_t micros(void);                              // µs since boot, wraps at 2^32
//     extern volatile uint32_t F_CPU_ACTUAL;              // core clock in Hz (DWT cycle rate)
//     extern volatile uint32_t F_BUS_ACTUAL;              // IPG/bus clock in Hz (FlexPWM, PERCLK)
//     enum IRQ_NUMBER_t { ... };                          // any enum able to hold 0..159
//     void attachInterruptVector(IRQ_NUMBER_t irq, void (*function)(void));
//                                                         // writes the RAM vector table entry
//   <Wire.h>
//     class TwoWire {
//       void begin();  void setClock(uint32_t frequency);
//       void beginTransmission(uint8_t address);
//       size_t write(const uint8_t* data, size_t quantity);
//       uint8_t endTransmission(uint8_t sendStop);        // 0 ok, 2 address NACK, 3 data NACK, …
//       uint8_t requestFrom(uint8_t address, uint8_t quantity, uint8_t sendStop);  // bytes received
//       int available();  int read();
//     };
//     extern TwoWire Wire, Wire1;                         // QWIIC0 (pins 18/19), QWIIC1 (17/16)
//   <avr/eeprom.h>                                      // EEPROM emulation in flash
//     #define E2END                                     // last byte address (0x437 on a 4.0,
//                                                       //   0x10BB on a 4.1)
//     void eeprom_read_block(void* buf, const void* addr, uint32_t len);
//     void eeprom_write_block(const void* buf, void* addr, uint32_t len);
//                                                       // skips bytes already equal; programs
//                                                       //   flash with interrupts off
//
// NVIC priorities/enables, clocks, pins and every peripheral are programmed through our own
// register definitions, not through Teensyduino macros.
#pragma once

#if defined(__IMXRT1062__)

#include <Arduino.h>
#include <Wire.h>
#include <avr/eeprom.h>
#include <stddef.h>
#include <stdint.h>

namespace stepdance::platform::teensy::services {

// ---- USB serial ---------------------------------------------------------------------------------
inline int serial_available() { return Serial.available(); }
inline int serial_read() { return Serial.read(); }
inline int serial_write_space() { return Serial.availableForWrite(); }
inline size_t serial_write(const uint8_t* data, size_t length) { return Serial.write(data, length); }

// ---- Time and clocks ----------------------------------------------------------------------------
inline uint32_t micros_since_boot() { return micros(); }
inline uint32_t core_clock_hz() { return F_CPU_ACTUAL; }
inline uint32_t bus_clock_hz() { return F_BUS_ACTUAL; }

// ---- Interrupt vectors --------------------------------------------------------------------------
/// Points interrupt `irq` at `handler` in the RAM vector table.
inline void set_vector(uint8_t irq, void (*handler)()) {
  attachInterruptVector(static_cast<IRQ_NUMBER_t>(irq), handler);
}

// ---- I2C (Wire = QWIIC0, Wire1 = QWIIC1); each call blocks until its bytes are on the wire -------
inline TwoWire& wire(uint8_t bus) { return bus == 0 ? Wire : Wire1; }
inline void wire_begin(uint8_t bus, uint32_t clock_hz) {
  wire(bus).begin();
  wire(bus).setClock(clock_hz);
}
/// Writes `length` bytes to `address`; a STOP follows unless `stop` is false (a read follows).
/// Returns Wire's endTransmission code.
inline uint8_t wire_write(uint8_t bus, uint8_t address, const uint8_t* data, size_t length, bool stop) {
  wire(bus).beginTransmission(address);
  if (length > 0) wire(bus).write(data, length);
  return wire(bus).endTransmission(stop ? 1 : 0);
}
/// Reads up to `length` bytes from `address` into `data`; returns how many arrived.
inline size_t wire_read(uint8_t bus, uint8_t address, uint8_t* data, size_t length) {
  const size_t received = wire(bus).requestFrom(address, static_cast<uint8_t>(length), static_cast<uint8_t>(1));
  size_t taken = 0;
  while (taken < received && wire(bus).available() > 0) data[taken++] = static_cast<uint8_t>(wire(bus).read());
  return taken;
}

// ---- EEPROM emulation ---------------------------------------------------------------------------
inline size_t eeprom_bytes() { return static_cast<size_t>(E2END) + 1; }
inline void eeprom_read(size_t offset, uint8_t* data, size_t length) {
  eeprom_read_block(data, reinterpret_cast<const void*>(offset), static_cast<uint32_t>(length));
}
inline void eeprom_write(size_t offset, const uint8_t* data, size_t length) {
  eeprom_write_block(data, reinterpret_cast<void*>(offset), static_cast<uint32_t>(length));
}

}  // namespace stepdance::platform::teensy::services

#endif  // __IMXRT1062__
