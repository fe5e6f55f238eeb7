// Delivers pulses that left a cable to the receiving board's input port at their capture time.
#pragma once

#include <cstdint>

#include "board/host/sim_board.hpp"
#include "board/host/wire.hpp"
#include "kernel/scheduler/one_shot_pool.hpp"

namespace stepdance::sim {

/// One pulse on its way to an input port.
struct PulseInFlight {
  SimBoard* board = nullptr;
  uint8_t port = 0;
  ArrivingPulse pulse;
};

/// Pooled events that call board->capture(port, pulse) at the pulse's falling edge, when the
/// receiving board's capture ISR would run. One pool serves every cable of a simulation.
class PulseDelivery {
 public:
  explicit PulseDelivery(Scheduler& scheduler) : pool_(scheduler, &deliver, nullptr) {}
  /// Schedules `pulse` for `board`'s input port `port` at pulse.fall_ns.
  void send(SimBoard& board, uint8_t port, const ArrivingPulse& pulse) {
    pool_.post(pulse.fall_ns, PulseInFlight{&board, port, pulse});
  }

 private:
  static void deliver(void*, SimTime, const PulseInFlight& flight) { flight.board->capture(flight.port, flight.pulse); }
  OneShotPool<PulseInFlight> pool_;
};

}  // namespace stepdance::sim
