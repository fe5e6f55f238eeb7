// The NVIC's bookkeeping: which exceptions are enabled, pending and active, their priorities,
// and which one the core takes next (ARMv7-M ARM DDI 0403E B1.5 "exception model").
#pragma once

#include <array>
#include <cstdint>

namespace stepdance::sim::image {

/// Exception numbers (DDI 0403E B1.5.2 table B1-4); IRQ n is 16 + n.
enum ExceptionNumber : unsigned {
  kReset = 1,
  kNmi = 2,
  kHardFault = 3,
  kMemManage = 4,
  kBusFault = 5,
  kUsageFault = 6,
  kSvCall = 11,
  kDebugMonitor = 12,
  kPendSv = 14,
  kSysTick = 15,
  kFirstIrq = 16,
};

/// The i.MX RT1062's NVIC: 160 interrupt lines (IMXRT1060RM rev 3, 4.3 table 4-2, "ARM Cortex
/// M7 interrupts", IRQ 0..159) with 4 priority bits (16 levels: the device header's
/// __NVIC_PRIO_BITS = 4; priority registers keep bits [7:4], bits [3:0] read as zero).
constexpr unsigned kIrqCount = 160;
constexpr unsigned kExceptionCount = kFirstIrq + kIrqCount;
constexpr unsigned kPriorityBits = 4;
constexpr uint8_t kPriorityMask = static_cast<uint8_t>(0xFF << (8 - kPriorityBits));
/// Execution priority of thread mode with nothing masked: lower than any exception.
constexpr int kThreadPriority = 256;

/// The core's masks, read from the CPU before a decision.
struct Masks {
  bool primask = false;    ///< PRIMASK.PM: only NMI and HardFault
  bool faultmask = false;  ///< FAULTMASK.FM: only NMI
  uint8_t basepri = 0;     ///< BASEPRI: 0 = no masking
};

/// Enabled/pending/active state and priorities of all exceptions. Context: the simulator's thread.
class ExceptionState {
 public:
  ExceptionState() { reset(); }
  /// Cold reset: everything disabled, inactive, priority 0; PRIGROUP 0.
  void reset();

  bool enabled(unsigned number) const { return enabled_[number]; }
  void set_enabled(unsigned number, bool on);
  bool pending(unsigned number) const { return pending_[number]; }
  /// Sets or clears the pending bit; clearing an IRQ whose line is high leaves it pending (the
  /// line re-asserts it at once, DDI 0403E B3.4.1 "level-sensitive interrupts").
  void set_pending(unsigned number, bool on);
  bool active(unsigned number) const { return active_[number]; }
  /// The level on IRQ line `irq`: a rising level pends it, a high level keeps it pending.
  void set_line(unsigned irq, bool high);
  bool line(unsigned irq) const { return line_[irq]; }

  /// The priority register value (8 bits, low bits zero) or the fixed -3/-2/-1 of Reset, NMI
  /// and HardFault.
  int priority(unsigned number) const;
  void set_priority(unsigned number, uint8_t value) { priority_[number] = value & kPriorityMask; }
  /// AIRCR.PRIGROUP (0..7): group priority is bits [7:PRIGROUP+1].
  void set_priority_group(unsigned group) { priority_group_ = group & 7; }
  unsigned priority_group() const { return priority_group_; }

  /// The core's execution priority (B1.5.4): the group priority of the highest-priority active
  /// exception, lowered by BASEPRI, PRIMASK (0) and FAULTMASK (-1); kThreadPriority if none.
  int execution_priority(const Masks& masks) const;
  /// The exception the core takes now (pending, enabled, group priority above the execution
  /// priority; ties by priority, then lowest number), or 0 for none.
  unsigned next_to_take(const Masks& masks) const;
  /// True if some exception is pending and enabled (taken or masked).
  bool any_pending() const { return pending_count_ > 0; }
  /// True if anything at all could ever interrupt: an enabled IRQ, or `systick_ticking`, that a
  /// mask-free core would take at `masks`' execution priority. Used to call a spin a stall.
  bool can_be_interrupted(const Masks& masks, bool systick_ticking) const;

  /// Entry: pending → active. Exit: active → inactive; an IRQ whose line is still high pends again.
  void activate(unsigned number);
  void deactivate(unsigned number);
  /// Number of active exceptions (nesting depth).
  unsigned active_count() const { return active_count_; }

 private:
  int group_priority(int priority) const;
  void recount();

  std::array<bool, kExceptionCount> enabled_{};
  std::array<bool, kExceptionCount> pending_{};
  std::array<bool, kExceptionCount> active_{};
  std::array<bool, kIrqCount> line_{};
  std::array<uint8_t, kExceptionCount> priority_{};
  unsigned priority_group_ = 0;
  unsigned pending_count_ = 0;
  unsigned active_count_ = 0;
};

}  // namespace stepdance::sim::image
