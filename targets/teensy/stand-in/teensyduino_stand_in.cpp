// The rest of the stand-in Teensyduino core: the USB serial objects, the RAM vector table and
// main(). The start-up, clocks, time, pins, analog input, Wire, EEPROM and Print live in their own
// files (startup.cpp lists the sequence). The stand-in headers are included as system headers
// (<...>), as the real core's are.
#include <Arduino.h>

usb_serial_class Serial;
#if defined(USB_DUAL_SERIAL) || defined(USB_TRIPLE_SERIAL)
usb_serial_class SerialUSB1;
#endif

// usb_serial_class's methods: usb_serial.cpp (a CDC-ACM device on USB1).

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
