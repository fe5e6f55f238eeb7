// Fault and diagnostic lines on the USB serial console, never blocking.
//
// Teensyduino's USB serial code must not be entered from an ISR that may have interrupted it in
// the loop, so a fault raised in an ISR is only recorded (two pointers to static strings); the
// next console call in the loop prints it. A fault line that does not fit yet stays pending.
#if defined(__IMXRT1062__)

#include <string.h>

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/console.hpp"
#include "stepdance/platform/teensy/irq.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy {
namespace {

const char* volatile pending_reason = nullptr;
const char* volatile pending_detail = nullptr;
volatile bool fault_pending = false;

}  // namespace

bool write_line(const char* const* pieces, size_t count) {
  size_t total = 2;  // CRLF
  for (size_t i = 0; i < count; ++i) total += strlen(pieces[i]);
  const int space = services::serial_write_space();
  if (space < 0 || static_cast<size_t>(space) < total) return false;
  for (size_t i = 0; i < count; ++i) {
    services::serial_write(reinterpret_cast<const uint8_t*>(pieces[i]), strlen(pieces[i]));
  }
  services::serial_write(reinterpret_cast<const uint8_t*>("\r\n"), 2);
  return true;
}

void flush_pending_fault() {
  if (!fault_pending || !irq::in_thread_mode()) return;
  const char* const line[] = {"stepdance fault: ", pending_reason, ": ", pending_detail};
  if (write_line(line, 4)) fault_pending = false;
}

}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

void log_fault(const char* reason, const char* detail) {
  {
    CriticalSection guard;
    if (teensy::fault_pending) return;  // the first report is the one that matters
    teensy::pending_reason = reason != nullptr ? reason : "";
    teensy::pending_detail = detail != nullptr ? detail : "";
    teensy::fault_pending = true;
  }
  teensy::flush_pending_fault();
}

void log_message(const char* text) {
  if (!teensy::irq::in_thread_mode()) return;  // loop only: USB code must not run inside an ISR
  teensy::flush_pending_fault();
  const char* const line[] = {text != nullptr ? text : ""};
  teensy::write_line(line, 1);  // dropped whole if the console cannot take it now
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
