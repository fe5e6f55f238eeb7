// Do-nothing definitions of the stand-in Teensyduino services, so a CI firmware image links.
// They only make the link and the size report possible: an image built with them is not flashable.
// The stand-in headers are included as system headers (<...>), as the real core's are.
#include <Arduino.h>
#include <Wire.h>
#include <avr/eeprom.h>

volatile uint32_t F_CPU_ACTUAL = 600000000;
volatile uint32_t F_BUS_ACTUAL = 150000000;

usb_serial_class Serial;
#if defined(USB_DUAL_SERIAL) || defined(USB_TRIPLE_SERIAL)
usb_serial_class SerialUSB1;
#endif

void pinMode(uint8_t, uint8_t) {}
uint8_t digitalRead(uint8_t) { return LOW; }
void digitalWrite(uint8_t, uint8_t) {}
int analogRead(uint8_t) { return 0; }

uint32_t millis() { return 0; }
uint32_t micros() { return 0; }
void delay(uint32_t) {}
void delayMicroseconds(uint32_t) {}
void yield() {}

size_t Print::write(const uint8_t* data, size_t length) {
  size_t written = 0;
  while (written < length && write(data[written]) == 1) ++written;
  return written;
}
size_t Print::print(long, int) { return 0; }
size_t Print::print(unsigned long, int) { return 0; }
size_t Print::print(double, int) { return 0; }

// usb_serial_class's methods: usb_serial.cpp (a CDC-ACM device on USB1).

TwoWire Wire;
TwoWire Wire1;

void TwoWire::begin() {}
void TwoWire::setClock(uint32_t) {}
void TwoWire::beginTransmission(uint8_t) {}
size_t TwoWire::write(const uint8_t*, size_t quantity) { return quantity; }
uint8_t TwoWire::endTransmission(uint8_t) { return 2; }
uint8_t TwoWire::requestFrom(uint8_t, uint8_t, uint8_t) { return 0; }
int TwoWire::available() { return 0; }
int TwoWire::read() { return -1; }

namespace {
// Cortex-M7 exceptions (16) plus the i.MX RT1062's 160 interrupts.
constexpr int kVectorCount = 176;
}  // namespace

// The vector table the core runs from, kept in RAM so handlers can be installed at run time.
// VTOR needs the table aligned to a power of two at least its size (704 bytes).
alignas(1024) void (*volatile stand_in_vectors_ram[kVectorCount])();

void attachInterruptVector(IRQ_NUMBER_t irq, void (*handler)()) {
  stand_in_vectors_ram[static_cast<int>(irq) + 16] = handler;
}

int main() {
  setup();
  for (;;) {
    loop();
    yield();
  }
}

void eeprom_read_block(void* buf, const void*, uint32_t len) {
  for (uint32_t i = 0; i < len; ++i) static_cast<uint8_t*>(buf)[i] = 0xFF;
}
void eeprom_write_block(const void*, void*, uint32_t) {}
