// The NVIC's bookkeeping (DDI 0403E B1.5.4 "execution priority and priority boosting").
#include "image/cpu/exception_state.hpp"

namespace stepdance::sim::image {

void ExceptionState::reset() {
  enabled_.fill(false);
  pending_.fill(false);
  active_.fill(false);
  line_.fill(false);
  priority_.fill(0);
  priority_group_ = 0;
  // Always enabled: NMI, HardFault, SVCall, DebugMonitor, PendSV, SysTick (B3.2.13: only
  // MemManage, BusFault and UsageFault have enable bits, in SHCSR).
  for (unsigned n : {kNmi, kHardFault, kSvCall, kDebugMonitor, kPendSv, kSysTick}) enabled_[n] = true;
  recount();
}

void ExceptionState::recount() {
  pending_count_ = 0;
  active_count_ = 0;
  for (unsigned n = 1; n < kExceptionCount; ++n) {
    pending_count_ += pending_[n] && enabled_[n];
    active_count_ += active_[n];
  }
}

void ExceptionState::set_enabled(unsigned number, bool on) {
  enabled_[number] = on;
  recount();
}

void ExceptionState::set_pending(unsigned number, bool on) {
  if (!on && number >= kFirstIrq && line_[number - kFirstIrq]) on = true;
  pending_[number] = on;
  recount();
}

void ExceptionState::set_line(unsigned irq, bool high) {
  const bool rising = high && !line_[irq];
  line_[irq] = high;
  if (rising) set_pending(kFirstIrq + irq, true);
}

int ExceptionState::priority(unsigned number) const {
  if (number == kReset) return -3;
  if (number == kNmi) return -2;
  if (number == kHardFault) return -1;
  return priority_[number];
}

int ExceptionState::group_priority(int priority) const {
  if (priority < 0) return priority;
  const int subgroup_bits = static_cast<int>(priority_group_) + 1;
  return (priority >> subgroup_bits) << subgroup_bits;
}

int ExceptionState::execution_priority(const Masks& masks) const {
  int highest = kThreadPriority;
  for (unsigned n = 1; n < kExceptionCount && active_count_ > 0; ++n) {
    if (active_[n] && group_priority(priority(n)) < highest) highest = group_priority(priority(n));
  }
  if (masks.basepri != 0 && group_priority(masks.basepri & kPriorityMask) < highest) {
    highest = group_priority(masks.basepri & kPriorityMask);
  }
  if (masks.primask && highest > 0) highest = 0;
  if (masks.faultmask && highest > -1) highest = -1;
  return highest;
}

unsigned ExceptionState::next_to_take(const Masks& masks) const {
  if (pending_count_ == 0) return 0;
  const int running = execution_priority(masks);
  unsigned best = 0;
  for (unsigned n = 1; n < kExceptionCount; ++n) {
    if (!pending_[n] || !enabled_[n]) continue;
    if (group_priority(priority(n)) >= running) continue;
    if (best == 0 || priority(n) < priority(best)) best = n;
  }
  return best;
}

bool ExceptionState::can_be_interrupted(const Masks& masks, bool systick_ticking) const {
  const int running = execution_priority(masks);
  if (systick_ticking && group_priority(priority(kSysTick)) < running) return true;
  for (unsigned n = kFirstIrq; n < kExceptionCount; ++n) {
    if (enabled_[n] && group_priority(priority(n)) < running) return true;
  }
  return false;
}

void ExceptionState::activate(unsigned number) {
  pending_[number] = false;
  active_[number] = true;
  recount();
}

void ExceptionState::deactivate(unsigned number) {
  active_[number] = false;
  if (number >= kFirstIrq && line_[number - kFirstIrq]) pending_[number] = true;
  recount();
}

}  // namespace stepdance::sim::image
