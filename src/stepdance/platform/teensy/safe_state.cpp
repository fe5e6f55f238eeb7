// The safe state: no more frames, STEP/DIR held low, every driver of the board disabled.
#if defined(__IMXRT1062__)

#include "stepdance/boards/board.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/output_ports.hpp"
#include "stepdance/platform/teensy/pins.hpp"

namespace stepdance::hal {

namespace teensy = platform::teensy;

void enter_safe_state() {
  timers_stop();
  // The frame in flight (if any) is cut: its pins become GPIO outputs driven low at once.
  teensy::output_ports_park_pins();
  const BoardDefinition& board = active_board();
  for (uint8_t port = 0; port < board.output_port_count && port < 4; ++port) {
    const uint8_t enable = board.output_ports[port].enable;
    const teensy::PinInfo* info = teensy::pin_info(enable);
    if (info == nullptr) continue;
    teensy::pin_drive(*info, true);  // ENABLE is active low: high disables the driver
    teensy::pad_configure(*info, teensy::kPadOutput);
    teensy::pin_make_gpio(*info, true);
  }
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
