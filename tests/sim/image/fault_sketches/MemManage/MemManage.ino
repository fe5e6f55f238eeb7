// Fault fixture for image boards: a read through a null pointer, which the Teensy's MPU traps
// (a 32-byte no-access region at address 0, as Teensyduino sets it): a MemManage fault.
#include <stdint.h>

volatile uint32_t sink;
uint32_t* volatile nowhere = nullptr;

__attribute__((noinline)) void read_through_null() { sink = *nowhere; }

void setup() { read_through_null(); }
void loop() {}
