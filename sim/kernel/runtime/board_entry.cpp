// Inside a board's shared object: the one exported symbol, binding the sketch to the simulator.
#include <cstring>

#include "IntervalTimer.h"
#include "abi/board_abi.h"
#include "runtime/host_link.hpp"
#include "runtime/sim_hal.hpp"
#include "stepdance/boards/board.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/io/output_port.hpp"

// The sketch's two Arduino entry points.
void setup();
void loop();

namespace stepdance::sim_runtime {
namespace {

StepdanceBoardStatsV1* stats_being_filled = nullptr;

void record_output_port(OutputPort* port) {
  const uint8_t index = port->port_index();
  if (index >= 4 || stats_being_filled == nullptr) return;
  StepdanceBoardStatsV1& stats = *stats_being_filled;
  stats.output_begun[index] = 1;
  stats.carried[index] = port->signals_carried();
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    stats.sent[index][signal][0] = port->pulses_sent(signal, DIRECTION_FORWARD);
    stats.sent[index][signal][1] = port->pulses_sent(signal, DIRECTION_REVERSE);
  }
}

void read_stats(StepdanceBoardStatsV1* stats) {
  *stats = StepdanceBoardStatsV1{};
  stats->frames = engine().frame_count();
  stats->frame_overruns = engine().load().overruns();
  stats->fault_reason = static_cast<uint8_t>(fault_reason());
  stats->fault_name = to_string(fault_reason());
  stats->fault_count = fault_count();
  stats->fault_detail = fault_detail();
  stats_being_filled = stats;
  iterate_across_all_output_ports(&record_output_port);
  stats_being_filled = nullptr;
}

void run_setup(int64_t now) {
  set_now_ns(now);
  ::setup();
}
void run_frame_tick(int64_t now) {
  set_now_ns(now);
  run_frame_isr();
  arduino::run_interval_timers();
}
void run_khz_tick(int64_t now) {
  set_now_ns(now);
  run_khz_isr();
  arduino::run_interval_timers();
}
void run_loop(int64_t now) {
  set_now_ns(now);
  arduino::run_interval_timers();  // also before dance_start(), when no frame ticks run
  ::loop();
}
void deliver_pulse(int64_t now, uint8_t port, const StepdanceCapturedPulseV1* pulse) {
  set_now_ns(now);
  deliver_captured_pulse(port, *pulse);
}

StepdanceBoardV1 board_table = {
    STEPDANCE_BOARD_ABI_VERSION, 0, &run_setup, &run_frame_tick, &run_khz_tick, &run_loop, &deliver_pulse, &read_stats,
};

}  // namespace
}  // namespace stepdance::sim_runtime

/// Binds this board to the simulator. Returns nullptr if the host speaks another ABI version.
extern "C" __attribute__((visibility("default"))) const StepdanceBoardV1* stepdance_board_attach(
    const StepdanceHostV1* host, void* host_context) {
  if (host == nullptr || host->abi_version != STEPDANCE_BOARD_ABI_VERSION) return nullptr;
  stepdance::sim_runtime::attach_host(host, host_context);
  auto& table = stepdance::sim_runtime::board_table;
  // Board tables are constexpr (one copy per translation unit), so compare names, not addresses.
  table.module = std::strcmp(stepdance::active_board().name, stepdance::kBasicModuleV1.name) == 0 ? 1 : 0;
  return &table;
}
