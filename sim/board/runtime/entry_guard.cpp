// Inside a board's shared object: the escape points of the running entries.
#include "board/runtime/entry_guard.hpp"

namespace stepdance::sim_runtime {

sigjmp_buf EntryGuard::points_[kMaxEntryNesting];
volatile int EntryGuard::depth_ = 0;

void EntryGuard::escape(int code) {
  if (depth_ == 0) return;
  siglongjmp(points_[depth_ - 1], code == 0 ? 1 : code);
}

}  // namespace stepdance::sim_runtime
