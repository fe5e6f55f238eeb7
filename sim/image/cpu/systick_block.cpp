// SysTick (DDI 0403E B3.3.2 table B3-7): a 24-bit down counter that reloads from RVR on the tick
// after it reaches zero, sets COUNTFLAG and (TICKINT) pends exception 15 when it reaches zero.
//
// The counter is not stepped: it is computed from the tick count of its clock since an anchor
// (a tick at which it held a known value), and one scheduler event waits for the next zero.
#include "image/cpu/image_chip.hpp"
#include "image/cpu/system_blocks.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kCsr = 0x0, kRvr = 0x4, kCvr = 0x8;
constexpr uint32_t kCountMask = 0x00FFFFFF;
constexpr uint32_t kCountFlag = 1u << 16;

}  // namespace

SysTickBlock::SysTickBlock(ImageChip& chip) : chip_(chip) {}

SysTickBlock::~SysTickBlock() { chip_.scheduler().cancel(zero_event_); }

uint64_t SysTickBlock::tick_now() const {
  if (core_clocked()) return chip_.cycles();
  return static_cast<uint64_t>(chip_.now_ns() / kExternalTickNs);
}

SimTime SysTickBlock::tick_time(uint64_t tick) const {
  if (core_clocked()) return chip_.time_of_cycle(tick);
  return static_cast<SimTime>(tick) * kExternalTickNs;
}

// Counter value at `tick` ≥ anchor: counts down from the anchor's value, then cycles RVR..0.
uint32_t SysTickBlock::value_at(uint64_t tick) const {
  const uint64_t since = tick - anchor_tick_;
  if (since <= anchor_value_) return static_cast<uint32_t>(anchor_value_ - since);
  const uint64_t period = uint64_t{rvr_} + 1;
  return static_cast<uint32_t>(rvr_ - (since - anchor_value_ - 1) % period);
}

// Number of times the counter has reached zero (from one) in (anchor, tick].
uint64_t SysTickBlock::zeros_through(uint64_t tick) const {
  if (!enabled()) return 0;
  const uint64_t since = tick - anchor_tick_;
  uint64_t zeros = 0;
  if (anchor_value_ > 0 && since >= anchor_value_) zeros = 1;
  if (since > anchor_value_ && rvr_ > 0) zeros += (since - anchor_value_) / (uint64_t{rvr_} + 1);
  return zeros;
}

void SysTickBlock::anchor(uint32_t value) {
  anchor_tick_ = tick_now();
  anchor_value_ = value;
  flag_zeros_ = 0;
}

void SysTickBlock::schedule_next_zero() {
  Scheduler& scheduler = chip_.scheduler();
  scheduler.cancel(zero_event_);
  if (!enabled()) return;
  const uint64_t now = tick_now();
  const uint64_t since = now - anchor_tick_;
  uint64_t next;
  if (anchor_value_ > 0 && since < anchor_value_) {
    next = anchor_tick_ + anchor_value_;
  } else {
    if (rvr_ == 0) return;  // RVR 0: the counter stops at zero (B3.3.3)
    const uint64_t period = uint64_t{rvr_} + 1;
    const uint64_t first = anchor_tick_ + anchor_value_ + period;
    next = now < first ? first : first + ((now - first) / period + 1) * period;
  }
  scheduler.schedule(zero_event_, tick_time(next));
}

void SysTickBlock::ZeroEvent::fire(Event& event, Scheduler&) {
  SysTickBlock& block = *static_cast<ZeroEvent&>(event).block;
  if (block.ticking()) block.chip_.pend_exception(kSysTick);
  block.schedule_next_zero();
}

void SysTickBlock::clock_changed() {
  if (!enabled() || !core_clocked()) return;
  schedule_next_zero();
}

Access SysTickBlock::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  const uint64_t now = tick_now();
  switch (offset) {
    case kCsr: {
      const uint64_t zeros = zeros_through(now);
      value = csr_ | (zeros > flag_zeros_ ? kCountFlag : 0);
      flag_zeros_ = zeros;  // COUNTFLAG clears on read
      return Access::kOk;
    }
    case kRvr: value = rvr_; return Access::kOk;
    case kCvr: value = enabled() ? value_at(now) : frozen_value_; return Access::kOk;
    default: return Access::kUnmodelled;  // CALIB: the RT1062 manual gives no value
  }
}

Access SysTickBlock::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  switch (offset) {
    case kCsr: {
      const uint32_t current = enabled() ? value_at(tick_now()) : frozen_value_;
      csr_ = value & 0x7;
      if (enabled())
        anchor(current);
      else
        frozen_value_ = current;
      schedule_next_zero();
      return Access::kOk;
    }
    case kRvr:
      rvr_ = value & kCountMask;
      if (enabled()) schedule_next_zero();
      return Access::kOk;
    case kCvr:  // any write clears the counter and COUNTFLAG
      frozen_value_ = 0;
      if (enabled()) anchor(0);
      schedule_next_zero();
      return Access::kOk;
    default: return Access::kUnmodelled;
  }
}

}  // namespace stepdance::sim::image
