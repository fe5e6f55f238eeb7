// Inside a board's shared object: the host Arduino API's backend hooks (delay, extra serial ports).
#include "IntervalTimer.h"
#include "arduino_backend.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance::arduino_backend {

// The simulator runs the rest of the world (this board's interrupts included) for the delay.
void delay_us(uint32_t us) {
  if (us == 0) return;
  sim_runtime::set_now_ns(sim_runtime::host().delay_ns(sim_runtime::host_context(), int64_t{us} * 1000));
  arduino::run_interval_timers();  // frame ticks during the delay ran the others
}

// Only the USB console (Serial) is simulated; other ports are unconnected.
ByteStream* serial_stream(SerialPortId) { return nullptr; }

}  // namespace stepdance::arduino_backend
