// Stand-in declarations of the Teensyduino services Stepdance and its sketches use, for CI builds.
//
// Teensyduino's core cannot be installed in CI, so scripts/build-teensy.sh compiles the library
// and every example against this directory instead. Everything here is written from the public
// Arduino/Teensy interfaces (names, signatures, documented constant values); nothing is taken
// from Teensyduino's sources. The matching definitions in teensyduino_stand_in.cpp are stubs:
// an image linked against them is a link and size check only and cannot be flashed.
//
// The whole surface, in one list. The backend's part is what
// src/stepdance/platform/teensy/teensyduino_services.hpp calls; the sketches' part is what the
// examples call. Add to it only what one of them really uses.
//   For the backend
//     Arduino.h  usb_serial_class Serial: available(), read(), availableForWrite(), write(data, n)
//                micros()
//                F_CPU_ACTUAL, F_BUS_ACTUAL       running core and peripheral bus clocks, in Hz
//                IRQ_NUMBER_t, attachInterruptVector(irq, handler)   RAM vector table entry
//     SdFat.h    SdioCard: begin(SdioConfig(FIFO_SDIO)), errorCode; FsVolume: begin(device),
//                remove; FsFile: open(volume, path, flags), read, write, close; O_RDONLY,
//                O_WRONLY, O_CREAT, O_TRUNC, O_AT_END
//   Modelled, not used by the backend
//     SdFat.h    SdFs: begin(SdioConfig) — SdFat's card and volume in one object, whose card
//                objects' vtables name the global operator delete as the real ones do, so the
//                no-heap check sees a sketch (or a backend change) that uses it
//     SD.h       BUILTIN_SDCARD, FILE_READ, FILE_WRITE; File, SDClass SD: begin, open, remove —
//                allocating its file objects on the heap like the real library, so the build's
//                no-heap check sees a sketch (or a backend change) that uses it
//   For sketches
//     Arduino.h  setup(), loop()                  the sketch's entry points, called by main()
//                HIGH, LOW                        1, 0
//                PI, HALF_PI, TWO_PI, DEG_TO_RAD, RAD_TO_DEG   Arduino's constants (macros, as there)
//                INPUT, OUTPUT, INPUT_PULLUP, INPUT_PULLDOWN   0, 1, 2, 3 (Teensy 4 values)
//                pinMode, digitalRead, digitalWrite, analogRead
//                digitalReadFast, digitalWriteFast (inline, as in the core's core_pins.h)
//                millis, delay, delayMicroseconds, yield, elapsedMillis
//                Print, Stream: print, println, write; DEC, HEX
//                SerialUSB1                       only with USB_DUAL_SERIAL or USB_TRIPLE_SERIAL
//     arm_math.h float32_t, float64_t             (CMSIS, shipped with Teensyduino)
//     usb_names.h struct usb_string_descriptor_struct   what a sketch folder's name.c fills in
//   For the image (teensyduino_stand_in.cpp, startup.cpp; Teensyduino's core has the real ones)
//                main(), reset handler, boot headers, vector table in RAM
#pragma once

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

// ---- Entry points and constants ----------------------------------------------------------------

void setup();
void loop();

#define HIGH 1
#define LOW 0

#define INPUT 0
#define OUTPUT 1
#define INPUT_PULLUP 2
#define INPUT_PULLDOWN 3

#define DEC 10
#define HEX 16

#define PI 3.1415926535897932384626433832795
#define HALF_PI 1.5707963267948966192313216916398
#define TWO_PI 6.283185307179586476925286766559
#define DEG_TO_RAD 0.017453292519943295769236907684886
#define RAD_TO_DEG 57.295779513082320876798154814105

// ---- Pins and time -----------------------------------------------------------------------------

// C linkage, as in the core's core_pins.h: a sketch's .c file can call these, and the linker sees
// the same unmangled names as with the real core.
extern "C" {
void pinMode(uint8_t pin, uint8_t mode);
uint8_t digitalRead(uint8_t pin);
void digitalWrite(uint8_t pin, uint8_t value);
int analogRead(uint8_t pin);
uint32_t millis();
uint32_t micros();
void delay(uint32_t ms);
void delayMicroseconds(uint32_t us);
void yield();
}
inline uint8_t digitalReadFast(uint8_t pin) { return digitalRead(pin); }
inline void digitalWriteFast(uint8_t pin, uint8_t value) { digitalWrite(pin, value); }

/// Counts milliseconds up from the last assignment.
class elapsedMillis {
 public:
  elapsedMillis() : start_(millis()) {}
  explicit elapsedMillis(uint32_t ms) : start_(millis() - ms) {}
  operator uint32_t() const { return millis() - start_; }
  elapsedMillis& operator=(uint32_t ms) {
    start_ = millis() - ms;
    return *this;
  }

 private:
  uint32_t start_;
};

// ---- Clocks ------------------------------------------------------------------------------------

extern "C" volatile uint32_t F_CPU_ACTUAL;
extern "C" volatile uint32_t F_BUS_ACTUAL;

// ---- Byte streams ------------------------------------------------------------------------------

/// Byte output with Arduino's print/println formatting.
class Print {
 public:
  virtual size_t write(uint8_t byte) = 0;
  virtual size_t write(const uint8_t* data, size_t length);
  size_t write(const char* text) { return write(reinterpret_cast<const uint8_t*>(text), strlen(text)); }
  virtual int availableForWrite() { return 0; }
  virtual void flush() {}

  size_t print(const char* text) { return write(text); }
  size_t print(char c) { return write(static_cast<uint8_t>(c)); }
  size_t print(int value, int base = DEC) { return print(static_cast<long>(value), base); }
  size_t print(unsigned value, int base = DEC) { return print(static_cast<unsigned long>(value), base); }
  size_t print(long value, int base = DEC);
  size_t print(unsigned long value, int base = DEC);
  size_t print(double value, int digits = 2);

  size_t println() { return write("\r\n"); }
  template <typename T>
  size_t println(T value) {
    const size_t n = print(value);
    return n + println();
  }
  template <typename T>
  size_t println(T value, int format) {
    const size_t n = print(value, format);
    return n + println();
  }

 protected:
  ~Print() = default;
};

/// Byte input on top of Print.
class Stream : public Print {
 public:
  virtual int available() = 0;
  virtual int read() = 0;
  virtual int peek() = 0;

 protected:
  ~Stream() = default;
};

/// A USB CDC serial port of the Teensy.
class usb_serial_class : public Stream {
 public:
  void begin(long baud);
  void end() {}
  int available() override;
  int read() override;
  int peek() override;
  void flush() override {}
  size_t write(uint8_t byte) override;
  size_t write(const uint8_t* data, size_t length) override;
  using Print::write;
  int availableForWrite() override;
  explicit operator bool() const;
};

extern usb_serial_class Serial;
#if defined(USB_DUAL_SERIAL) || defined(USB_TRIPLE_SERIAL)
extern usb_serial_class SerialUSB1;
#endif

// ---- Interrupts --------------------------------------------------------------------------------

/// i.MX RT1062 interrupt numbers 0..159 (reference manual, chapter 4 "Interrupts"). The backend
/// casts its own numbers to this type, so no names are declared.
enum IRQ_NUMBER_t : int {};

/// Puts a handler in the vector table in RAM (exception number = IRQ number + 16).
void attachInterruptVector(IRQ_NUMBER_t irq, void (*handler)());
