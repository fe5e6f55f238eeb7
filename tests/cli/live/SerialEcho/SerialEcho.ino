// Echoes every byte the host sends on USB Serial straight back: the live simulator's
// pseudo-terminal test drives it from pyserial with all 256 byte values.
#define module_driver
#include "stepdance.hpp"

void setup() {
  Serial.begin(115200);
  dance_start();
}

void loop() {
  while (Serial.available() > 0) Serial.write(static_cast<uint8_t>(Serial.read()));
  dance_loop();
}
