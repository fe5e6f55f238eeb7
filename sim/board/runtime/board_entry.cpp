// Inside a board's shared object: the one exported symbol, binding the sketch to the simulator.
#include "IntervalTimer.h"
#include "board/abi/board_abi.h"
#include "board/runtime/entry_guard.hpp"
#include "stepdance/boards/board.hpp"
#include "stepdance/core/counter_report.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/sim/host_link.hpp"
#include "stepdance/platform/sim/sim_hal.hpp"

// The sketch's two Arduino entry points.
void setup();
void loop();

namespace stepdance::sim_runtime {
namespace {

void read_stats(StepdanceBoardStatsV1* stats) {
  *stats = StepdanceBoardStatsV1{};
  stats->frames = engine().frame_count();
  stats->frame_overruns = engine().load().overruns();
  stats->fault_reason = static_cast<uint8_t>(fault_reason());
  stats->fault_name = to_string(fault_reason());
  stats->fault_count = fault_count();
  stats->fault_detail = fault_detail();
  const LoadMetrics& load = engine().load();
  stats->load_peak_cycles = load.peak_cycles();
  stats->load_budget_cycles = hal::cycles_per_second() / frame_rate_hz();
  stats->load_total_cycles = load.total_cycles();
  stats->load_frames = load.frames();
}

void read_counters(StepdanceCounterFnV1 emit, void* context) { report_block_counters(emit, context); }

void read_warnings(StepdanceWarningFnV1 emit, void* context) { report_warnings(emit, context); }

// Each entry runs guarded, so the simulator can leave it early (see EntryGuard; the frequent
// ones as kGuardFrequentEntries says).
int run_setup(int64_t now) {
  set_now_ns(now);
  return EntryGuard::run([] { ::setup(); });
}
int run_frame_tick(int64_t now) {
  set_now_ns(now);
  return EntryGuard::run_frequent([] {
    run_frame_isr();
    arduino::run_interval_timers();
  });
}
int run_khz_tick(int64_t now) {
  set_now_ns(now);
  return EntryGuard::run_frequent([] {
    run_khz_isr();
    arduino::run_interval_timers();
  });
}
int run_loop(int64_t now) {
  set_now_ns(now);
  return EntryGuard::run([] {
    arduino::run_interval_timers();  // also before dance_start(), when no frame ticks run
    ::loop();
  });
}
int deliver_pulse(int64_t now, uint8_t port, const StepdanceCapturedPulseV1* pulse) {
  set_now_ns(now);
  return EntryGuard::run_frequent([port, pulse] { deliver_captured_pulse(port, *pulse); });
}

StepdanceBoardV1 board_table = {
    STEPDANCE_BOARD_ABI_VERSION,
    nullptr,
    &run_setup,
    &run_frame_tick,
    &run_khz_tick,
    &run_loop,
    &deliver_pulse,
    &read_stats,
    &read_counters,
    &read_warnings,
    &EntryGuard::escape,
};

}  // namespace
}  // namespace stepdance::sim_runtime

/// Binds this board to the simulator. Returns nullptr if the host speaks another ABI version.
extern "C" __attribute__((visibility("default"))) const StepdanceBoardV1* stepdance_board_attach(
    const StepdanceHostV1* host, void* host_context) {
  if (host == nullptr || host->abi_version != STEPDANCE_BOARD_ABI_VERSION) return nullptr;
  stepdance::sim_runtime::attach_host(host, host_context);
  auto& table = stepdance::sim_runtime::board_table;
  table.board_name = stepdance::active_board().name;
  return &table;
}
