// The ONLY door from the Teensy backend to the Teensyduino core and its SD library.
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
//   <SD.h>
//     #define BUILTIN_SDCARD, FILE_READ, FILE_WRITE       // FILE_WRITE opens at the end, creating
//     class File {                                        //   the file if needed
//       File();  File& operator=(const File&);  ~File();
//       size_t read(void* buf, size_t nbyte);
//       size_t write(const void* buf, size_t size);
//       void close();
//       operator bool();                                  // true while open
//     };
//     class SDClass {
//       bool begin(uint8_t csPin);                        // called with BUILTIN_SDCARD
//       File open(const char* filepath, uint8_t mode);
//       bool remove(const char* filepath);
//     };
//     extern SDClass SD;
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
#include <SD.h>
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

// ---- SD card ------------------------------------------------------------------------------------
using SdFileHandle = ::File;
inline bool sd_begin_builtin() { return SD.begin(BUILTIN_SDCARD); }
inline SdFileHandle sd_open_read(const char* name) { return SD.open(name, FILE_READ); }
/// Opens for writing at the end of the file, creating it if needed.
inline SdFileHandle sd_open_append(const char* name) { return SD.open(name, FILE_WRITE); }
inline bool sd_remove(const char* name) { return SD.remove(name); }

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
