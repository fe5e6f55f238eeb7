// Every block's named counters and every kind of warning tallied, handed out one at a time: what a
// simulated board reports for the run's summary, and what a debugger (or the simulator's image
// board) asks a firmware image for through the entry points in platform/teensy/debug_entries.cpp.
#pragma once

#include <stdint.h>

namespace stepdance {

/// One counter: of the `instance`-th block (from 0, in the engine's order) of class `block`.
/// The strings are static.
using CounterEmit = void (*)(void* context, const char* block, uint32_t instance, const char* name, uint64_t value);
/// One kind of warning: where it came from, its reason's name, its first detail, how often.
using WarningEmit = void (*)(void* context, const char* source, const char* reason, const char* detail, uint32_t count);

/// Calls `emit` once per counter of every block the engine knows. Context: loop.
void report_block_counters(CounterEmit emit, void* context);
/// Calls `emit` once per kind of warning tallied, in the order first seen. Context: loop.
void report_warnings(WarningEmit emit, void* context);

}  // namespace stepdance
