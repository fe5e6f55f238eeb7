// USB serial console shared by console(), log_message() and log_fault() (backend-internal).
#pragma once

#if defined(__IMXRT1062__)

#include <stddef.h>

namespace stepdance::platform::teensy {

/// Writes the pieces as one line ending in CRLF if all of it fits in the USB transmit buffer now;
/// writes nothing otherwise. Never blocks. Context: loop only.
bool write_line(const char* const* pieces, size_t count);
/// Sends a fault report that was recorded in an ISR or did not fit yet. Context: loop only.
void flush_pending_fault();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
