// Fault fixture for image boards: a write into the program flash, which the Teensy's MPU maps
// read-only (as Teensyduino's startup does): a MemManage fault.
#include <stdint.h>

__attribute__((noinline)) void write_to_flash() { *reinterpret_cast<volatile uint32_t*>(0x60010000u) = 1; }

void setup() { write_to_flash(); }
void loop() {}
