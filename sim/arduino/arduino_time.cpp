// Arduino time functions over hal::micros_now() and the backend's delay hook.
#include "arduino_time.h"

#include "arduino_backend.hpp"
#include "arduino_state.hpp"
#include "stepdance/hal/hal.hpp"

namespace {

// Extends the 32-bit microsecond counter to 64 bits: a reading below the previous one means
// the counter wrapped once in between.
uint32_t last_micros = 0;
uint64_t wrapped_micros = 0;  // 2^32 × wraps seen
bool tracking = false;

uint64_t micros_since_start() {
  const uint32_t now = stepdance::hal::micros_now();
  if (!tracking) {
    tracking = true;
  } else if (now < last_micros) {
    wrapped_micros += uint64_t{1} << 32;
  }
  last_micros = now;
  return wrapped_micros + now;
}

// delay(ms) hands the backend at most this much per call, so ms × 1000 never overflows.
constexpr uint32_t kDelayChunkMs = 1000000;

}  // namespace

namespace stepdance::arduino::internal {
void reset_time_state() {
  last_micros = 0;
  wrapped_micros = 0;
  tracking = false;
}
}  // namespace stepdance::arduino::internal

uint32_t micros() { return static_cast<uint32_t>(micros_since_start()); }

uint32_t millis() { return static_cast<uint32_t>(micros_since_start() / 1000u); }

void delay(uint32_t ms) {
  while (ms > 0) {
    const uint32_t chunk = ms < kDelayChunkMs ? ms : kDelayChunkMs;
    stepdance::arduino_backend::delay_us(chunk * 1000u);
    ms -= chunk;
  }
}

void delayMicroseconds(uint32_t us) { stepdance::arduino_backend::delay_us(us); }

void yield() {}
