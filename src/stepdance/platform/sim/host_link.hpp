// Inside a board's shared object: the simulator's callback table and context, set at attach time.
#pragma once

#include "board/abi/board_abi.h"

namespace stepdance::sim_runtime {

/// The simulator's callbacks. Before attach() this is a table of harmless stand-ins, so a
/// sketch's global constructors may touch the HAL (they see time 0 and idle pins).
const StepdanceHostV1& host();
/// The opaque context every callback takes.
void* host_context();
/// Installs the simulator's table; called once by stepdance_board_attach().
void attach_host(const StepdanceHostV1* table, void* context);

/// Simulated time (ns) as of the latest entry from the simulator (or return from delay).
int64_t now_ns();
/// Records the time an entry point or delay_ns() brought.
void set_now_ns(int64_t now);

}  // namespace stepdance::sim_runtime
