// GPT1/GPT2 (RM §52.7).
#include "image/rt1062/gpt.hpp"

#include <algorithm>

namespace stepdance::sim::image::rt1062 {
namespace {

// Register offsets (RM §52.7) and CR fields (§52.7.1).
constexpr uint32_t kCr = 0x00, kPr = 0x04, kSr = 0x08, kIr = 0x0C, kOcr1 = 0x10, kOcr3 = 0x18, kIcr1 = 0x1C,
                   kIcr2 = 0x20, kCnt = 0x24;
constexpr uint32_t kCrEnable = 1u << 0, kCrEnableResets = 1u << 1, kCrFreeRun = 1u << 9, kCrEn24M = 1u << 10,
                   kCrSoftwareReset = 1u << 15;
constexpr uint32_t kCrKeptBySoftwareReset = 0x1FFu;  // EN, ENMOD, DBGEN, WAITEN, DOZEEN, STOPEN, CLKSRC
constexpr uint32_t kCrUnmodelled = 0xFFFF0000u;      // IM1/IM2 capture, OM1..3 outputs, FO1..3 force
constexpr uint32_t kSrRollover = 1u << 5;            // ROV; OF1..3 are bits 0..2
constexpr unsigned kIrqGpt1 = 100;                   // RM table 4-2 (GPT2 = 101)
constexpr uint64_t kWrap = uint64_t{1} << 32;

// The smallest n > after with n mod `modulus` == value.
uint64_t next_match(uint64_t after, uint64_t modulus, uint64_t value) {
  uint64_t n = after - after % modulus + value;
  if (n <= after) n += modulus;
  return n;
}

}  // namespace

Gpt::Gpt(unsigned number, ChipContext& context, Ccm& ccm)
    : number_(number), context_(context), ccm_(ccm), event_([this] { fire(); }) {
  ccm_.add_rates_listener([this](const ClockRates& rates) {
    const bool changed = rates.perclk_hz != perclk_hz_;
    perclk_hz_ = rates.perclk_hz;
    if (changed && enabled() && ((cr_ >> 6) & 7u) == 1u) {
      restart_clock(count_origin_ + ticks_now());  // PERCLK changed: count on at the new rate
    }
  });
}

Gpt::~Gpt() { context_.scheduler().cancel(event_); }

uint64_t Gpt::period_ticks() const { return restart_mode() ? uint64_t{ocr_[0]} + 1u : kWrap; }

uint64_t Gpt::ticks_now() const { return clock_.ticks_at(context_.now_ns()); }

uint32_t Gpt::count_now() const {
  if (!enabled()) return stopped_count_;
  return static_cast<uint32_t>((count_origin_ + ticks_now()) % period_ticks());
}

// Restarts counting now from `count` (unwrapped), at the clock CLKSRC and PR select.
void Gpt::restart_clock(uint64_t count) {
  uint32_t source_hz = 0;
  switch ((cr_ >> 6) & 7u) {
    case 1: source_hz = ccm_.perclk_hz(); break;
    case 4: source_hz = 32768u; break;
    case 5: source_hz = (cr_ & kCrEn24M) ? kOscillatorHz / (((pr_ >> 12) & 0xFu) + 1u) : 0u; break;
    default: break;
  }
  count %= period_ticks();
  clock_ = TickClock(context_.now_ns(), source_hz, (pr_ & 0xFFFu) + 1u);
  count_origin_ = count;
  handled_tick_ = count;
  schedule_next();
}

void Gpt::schedule_next() {
  context_.scheduler().cancel(event_);
  if (!enabled() || !clock_.running()) return;
  const uint64_t period = period_ticks();
  uint64_t next = restart_mode() ? UINT64_MAX : next_match(handled_tick_, kWrap, 0);  // rollover
  for (uint32_t ocr : ocr_) {
    if (ocr < period) next = std::min(next, next_match(handled_tick_, period, ocr));
  }
  event_tick_ = next;
  context_.scheduler().schedule(event_, clock_.time_of(next - count_origin_));
}

void Gpt::fire() {
  const uint64_t period = period_ticks();
  for (size_t n = 0; n < 3; ++n) {
    if (ocr_[n] < period && next_match(handled_tick_, period, ocr_[n]) == event_tick_) sr_ |= 1u << n;
  }
  if (!restart_mode() && event_tick_ % kWrap == 0) sr_ |= kSrRollover;
  handled_tick_ = event_tick_;
  schedule_next();
  update_irq();
}

void Gpt::update_irq() {
  const bool high = (sr_ & ir_ & 0x3Fu) != 0;
  if (high == irq_high_) return;
  irq_high_ = high;
  context_.set_irq_level(kIrqGpt1 + (number_ - 1u), high);
}

Access Gpt::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  uint32_t word = 0;
  switch (offset & ~3u) {
    case kCr: word = cr_; break;
    case kPr: word = pr_; break;
    case kSr: word = sr_; break;
    case kIr: word = ir_; break;
    case kIcr1:
    case kIcr2: word = 0; break;  // no captures (IMn = 0)
    case kCnt: word = count_now(); break;
    default:
      if ((offset & ~3u) < kOcr1 || (offset & ~3u) > kOcr3) return Access::kUnmodelled;
      word = ocr_[((offset & ~3u) - kOcr1) / 4u];
  }
  value = lane_read(word, offset, bytes);
  return Access::kOk;
}

Access Gpt::write_cr(uint32_t value) {
  if (value & kCrUnmodelled) return Access::kUnmodelled;
  const uint32_t source = (value >> 6) & 7u;
  if ((value & kCrEnable) && (source == 2 || source == 3)) return Access::kUnmodelled;
  const bool was_enabled = enabled();
  const uint32_t count = count_now();
  if (value & kCrSoftwareReset) {  // completes at once; SWR reads 0 (RM §52.7.1)
    cr_ = value & kCrKeptBySoftwareReset;
    pr_ = sr_ = ir_ = 0;
    ocr_ = {0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu};
    stopped_count_ = 0;
  } else {
    cr_ = value;
  }
  if (enabled() && !was_enabled) {
    restart_clock((cr_ & kCrEnableResets) ? 0u : stopped_count_);  // ENMOD: start from 0
  } else if (!enabled()) {
    stopped_count_ = was_enabled ? count : stopped_count_;
    context_.scheduler().cancel(event_);
  } else {
    restart_clock(count_origin_ + ticks_now());  // a clock source or mode change, running
  }
  update_irq();
  return Access::kOk;
}

Access Gpt::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  switch (word) {
    case kCr: return write_cr(lane_merge(cr_, offset, bytes, value));
    case kPr:
      pr_ = lane_merge(pr_, offset, bytes, value) & 0xFFFFu;
      if (enabled()) restart_clock(count_origin_ + ticks_now());
      return Access::kOk;
    case kSr: sr_ &= ~lane_merge(0u, offset, bytes, value); break;  // write 1 to clear
    case kIr: ir_ = lane_merge(ir_, offset, bytes, value) & 0x3Fu; break;
    case kIcr1:
    case kIcr2:
    case kCnt: return Access::kOk;  // read only
    default: {
      if (word < kOcr1 || word > kOcr3) return Access::kUnmodelled;
      const size_t n = (word - kOcr1) / 4u;
      const uint64_t count = count_origin_ + ticks_now();
      ocr_[n] = lane_merge(ocr_[n], offset, bytes, value);
      if (enabled()) restart_clock(n == 0 && restart_mode() ? 0u : count);  // OCR1 restarts the count
      return Access::kOk;
    }
  }
  update_irq();
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
