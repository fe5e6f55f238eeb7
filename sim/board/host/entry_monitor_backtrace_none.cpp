// EntryMonitor's backtraces where code has no addresses to walk (WebAssembly): none recorded.
#include "board/host/entry_monitor.hpp"

namespace stepdance::sim {

void EntryMonitor::prepare_backtrace() {}

void EntryMonitor::capture_backtrace(uintptr_t pc) {
  record_.pc = pc;
  record_.frame_count = 0;
}

}  // namespace stepdance::sim
