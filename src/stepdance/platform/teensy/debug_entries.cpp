// Entry points the firmware never calls: a debugger, or the simulator's image board at the end of
// a run, calls them to read what a host-compiled board reports in the run's summary (every block's
// named counters, every kind of warning tallied). They run in thread mode as the loop would, with
// the caller's stack; `emit` is the caller's code. docs/simulator.md, "Image boards".
#if defined(__IMXRT1062__)

#include "stepdance/core/counter_report.hpp"

extern "C" {

__attribute__((used, noinline)) void stepdance_debug_counters(stepdance::CounterEmit emit, void* context) {
  stepdance::report_block_counters(emit, context);
}

__attribute__((used, noinline)) void stepdance_debug_warnings(stepdance::WarningEmit emit, void* context) {
  stepdance::report_warnings(emit, context);
}

}  // extern "C"

namespace {

// Nothing in the image calls the entries, and images link with --gc-sections, which drops what
// nothing refers to (this toolchain has no `retain` attribute). Every linker script keeps
// .init_array, so a constructor that takes their addresses keeps them: one store at start-up.
const void* volatile kept_debug_entries[2];

__attribute__((constructor)) void keep_debug_entries() {
  kept_debug_entries[0] = reinterpret_cast<const void*>(&stepdance_debug_counters);
  kept_debug_entries[1] = reinterpret_cast<const void*>(&stepdance_debug_warnings);
}

}  // namespace

#endif  // __IMXRT1062__
