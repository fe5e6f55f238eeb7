// Firmware for stand_in_boot_test.cpp: a sketch on the CI stand-in core that records what its
// start-up left running (clock, time, pins) in variables the test reads from the chip's memory.
// No double-precision arithmetic: it runs on any ImageChip.
#include <Arduino.h>

volatile uint32_t boot_stage = 0;                  // 1 once setup() has run, 2 once loop() has
volatile uint32_t boot_millis_at_setup = 0;        // millis() when setup() began
volatile uint32_t boot_delay_us = 0;               // micros() across delay(5)
volatile uint32_t boot_delay_microseconds_us = 0;  // micros() across delayMicroseconds(250)
volatile uint32_t boot_cpu_hz = 0;                 // F_CPU_ACTUAL as setup() saw it
volatile uint32_t boot_bus_hz = 0;                 // F_BUS_ACTUAL

void setup() {
  boot_millis_at_setup = millis();
  boot_cpu_hz = F_CPU_ACTUAL;
  boot_bus_hz = F_BUS_ACTUAL;
  uint32_t start = micros();
  delay(5);
  boot_delay_us = micros() - start;
  start = micros();
  delayMicroseconds(250);
  boot_delay_microseconds_us = micros() - start;
  pinMode(13, OUTPUT);
  digitalWrite(13, HIGH);
  boot_stage = 1;
}

void loop() { boot_stage = 2; }
