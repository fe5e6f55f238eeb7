// EEPROM emulation of the CI firmware image: kept in RAM, so it forgets everything at reset.
// Teensyduino's real one programs the top of the QSPI flash (E2END + 1 bytes emulated in its last
// sectors); the stand-in does not drive the FlexSPI controller, so a write lasts until the next
// reset. Fresh, every byte reads 0xFF, as erased flash does.
#include <avr/eeprom.h>
#include <stdint.h>

namespace {
// Stored inverted, so that the zeroed .bss reads as erased (0xFF) without an initialiser in flash.
uint8_t inverted_bytes[E2END + 1];
}  // namespace

extern "C" {

// Context: any. Bytes past E2END read as 0xFF.
void eeprom_read_block(void* buf, const void* addr, uint32_t len) {
  const uintptr_t start = reinterpret_cast<uintptr_t>(addr);
  uint8_t* out = static_cast<uint8_t*>(buf);
  for (uint32_t i = 0; i < len; ++i) {
    const uintptr_t at = start + i;
    out[i] = at <= E2END ? static_cast<uint8_t>(~inverted_bytes[at]) : 0xFF;
  }
}

// Context: any. Bytes past E2END are dropped.
void eeprom_write_block(const void* buf, void* addr, uint32_t len) {
  const uintptr_t start = reinterpret_cast<uintptr_t>(addr);
  const uint8_t* in = static_cast<const uint8_t*>(buf);
  for (uint32_t i = 0; i < len && start + i <= E2END; ++i) inverted_bytes[start + i] = static_cast<uint8_t>(~in[i]);
}

}  // extern "C"
