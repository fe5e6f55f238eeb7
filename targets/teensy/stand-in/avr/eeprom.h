// Stand-in declarations of Teensyduino's EEPROM emulation, as far as the Teensy backend uses it
// (the list is in teensyduino_services.hpp). The definitions in teensyduino_stand_in.cpp behave
// as erased flash that forgets every write.
#pragma once

#include <stdint.h>

#if defined(ARDUINO_TEENSY40)
#define E2END 0x437
#else
#define E2END 0x10BB
#endif

#ifdef __cplusplus
extern "C" {
#endif
void eeprom_read_block(void* buf, const void* addr, uint32_t len);
void eeprom_write_block(const void* buf, void* addr, uint32_t len);
#ifdef __cplusplus
}
#endif
