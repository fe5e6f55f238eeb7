// A sketch that writes a file through Teensyduino's SD library. scripts/build-teensy.sh links it
// and requires the no-heap check to flag the image: proof that the check sees the allocations of
// the real core, which the stand-in (targets/teensy/stand-in/SD.cpp) models.
#include <Arduino.h>
#include <SD.h>

void setup() {
  SD.begin(BUILTIN_SDCARD);
  File file = SD.open("probe.txt", FILE_WRITE);
  if (file) file.write("probe", 5);
  file.close();
}

void loop() {}
