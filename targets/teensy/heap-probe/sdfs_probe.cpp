// A sketch that mounts the card through SdFat's SdFs, as our backend once did. SdFs holds SdFat's
// own card objects, whose vtables name the global operator delete (their base class has a virtual
// destructor). scripts/build-teensy.sh links it and requires the no-heap check to flag the image:
// proof that the check sees what the backend's own card type (SdCardBuiltin) avoids.
#include <Arduino.h>
#include <SdFat.h>

SdFs sd;

void setup() { sd.begin(SdioConfig(FIFO_SDIO)); }

void loop() {}
