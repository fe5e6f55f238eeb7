// EntryMonitor's backtraces on a host with glibc's unwinder (execinfo.h).
#include <execinfo.h>

#include "board/host/entry_monitor.hpp"

namespace stepdance::sim {

void EntryMonitor::prepare_backtrace() {
  void* frame[1];
  backtrace(frame, 1);  // the first call loads the unwinder; later ones allocate nothing
}

void EntryMonitor::capture_backtrace(uintptr_t pc) {
  record_.pc = pc;
  record_.frame_count = backtrace(record_.frames, EscapeRecord::kMaxFrames);
}

}  // namespace stepdance::sim
