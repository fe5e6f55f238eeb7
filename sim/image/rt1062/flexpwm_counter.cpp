// eFlexPWM submodule counters, reloads, compare and capture flags, and the interrupt lines, all
// evaluated from simulated time (RM §55.4 functional description, §55.8 registers).
#include <algorithm>

#include "image/rt1062/clock_roots.hpp"
#include "image/rt1062/flexpwm.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kInit = 0x02u, kCtrl2 = 0x04u, kCtrl = 0x06u, kVal1 = 0x0Eu, kInten = 0x26u;
constexpr uint32_t kValOffsets[6] = {0x0Au, 0x0Eu, 0x12u, 0x16u, 0x1Au, 0x1Eu};  // VAL0..VAL5
constexpr uint16_t kRf = 1u << 12;                                               // STS RF / INTEN RIE
constexpr uint16_t kMctrlIndex = (0x188u - 0x180u) / 2;
// STS capture flags of circuits 0/1 per channel A, B, X (RM §55.8 SMnSTS).
constexpr uint16_t kCaptureFlag[3][2] = {{1u << 10, 1u << 11}, {1u << 8, 1u << 9}, {1u << 6, 1u << 7}};

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

FlexPwm::Timebase FlexPwm::load(unsigned sm, SimTime start_ns, uint64_t reloads_before) const {
  const Submodule& s = sm_[sm];
  uint32_t ipg_hz = 0;
  ipg_root_hz(bus_, chip_.core_clock_hz(), ipg_hz);
  Timebase base;
  const unsigned prescale = (s.regs[kCtrl / 2] >> 4) & 7u;  // PRSC: ÷2^PRSC
  base.clock = ClockDomain{start_ns, ipg_hz >> prescale};
  base.init = s.regs[kInit / 2];
  // The counter runs INIT, INIT+1, … (16-bit) until it equals VAL1, then reloads INIT.
  base.period = ((static_cast<uint32_t>(s.regs[kVal1 / 2]) - base.init) & 0xFFFFu) + 1u;
  base.reloads_before = reloads_before;
  return base;
}

bool FlexPwm::start(unsigned sm, SimTime now_ns) {
  Submodule& s = sm_[sm];
  uint32_t ipg_hz = 0;
  if ((s.regs[kCtrl2 / 2] & 3u) != 0 || !ipg_root_hz(bus_, chip_.core_clock_hz(), ipg_hz)) return false;
  s.base = load(sm, now_ns, reloads(s, now_ns));
  s.running = true;
  s.load_pending = false;
  std::fill(std::begin(s.cmp_cleared_tick), std::end(s.cmp_cleared_tick), -1);
  module_regs_[kMctrlIndex] = static_cast<uint16_t>(module_regs_[kMctrlIndex] & ~(1u << sm));  // loaded
  return true;
}

void FlexPwm::stop(unsigned sm, SimTime now_ns) {
  Submodule& s = sm_[sm];
  s.sts = status(sm, now_ns);  // flags raised so far stay
  s.rf_cleared_at = reloads(s, now_ns);
  s.held_count = counter(s, now_ns);
  s.running = false;
}

void FlexPwm::refresh(unsigned sm, SimTime now_ns) {
  Submodule& s = sm_[sm];
  if (!s.running || !s.load_pending || now_ns < s.load_at_ns) return;
  // The buffered INIT/VAL1/PRSC take effect at the reload after LDOK; flags so far stay.
  s.sts = static_cast<uint16_t>(s.sts | compare_flags(s, s.load_at_ns));
  s.base = load(sm, s.load_at_ns, reloads(s, s.load_at_ns));
  std::fill(std::begin(s.cmp_cleared_tick), std::end(s.cmp_cleared_tick), -1);
  s.load_pending = false;
  module_regs_[kMctrlIndex] = static_cast<uint16_t>(module_regs_[kMctrlIndex] & ~(1u << sm));
}

int64_t FlexPwm::ticks(const Submodule& s, SimTime t) const { return s.base.clock.cycles_at(t); }

uint16_t FlexPwm::counter(const Submodule& s, SimTime t) const {
  return static_cast<uint16_t>(s.base.init + static_cast<uint32_t>(ticks(s, t) % s.base.period));
}

uint64_t FlexPwm::reloads(const Submodule& s, SimTime t) const {
  if (!s.running) return s.rf_cleared_at;
  return s.base.reloads_before + static_cast<uint64_t>(ticks(s, t) / s.base.period);
}

SimTime FlexPwm::next_reload_ns(const Submodule& s, SimTime t) const {
  const int64_t next = (ticks(s, t) / s.base.period + 1) * static_cast<int64_t>(s.base.period);
  return s.base.clock.time_of(next);
}

uint16_t FlexPwm::compare_flags(const Submodule& s, SimTime t) const {
  if (!s.running) return 0;
  const int64_t now_tick = ticks(s, t);
  const int64_t period = s.base.period;
  uint16_t flags = 0;
  for (unsigned n = 0; n < 6; ++n) {
    // CMPFn: the counter equalled VALn at some tick after the last clear.
    const int64_t at = (static_cast<uint32_t>(s.regs[kValOffsets[n] / 2]) - s.base.init) & 0xFFFFu;
    if (at >= period) continue;
    const int64_t seen = floor_div(now_tick - at, period) - floor_div(s.cmp_cleared_tick[n] - at, period);
    if (seen > 0) flags = static_cast<uint16_t>(flags | (1u << n));
  }
  return flags;
}

uint16_t FlexPwm::status(unsigned sm, SimTime now_ns) {
  Submodule& s = sm_[sm];
  uint16_t value = static_cast<uint16_t>(s.sts | compare_flags(s, now_ns));
  if (s.running && (s.regs[kCtrl / 2] & 0x0400u) && reloads(s, now_ns) > s.rf_cleared_at) value |= kRf;
  return value;
}

void FlexPwm::clear_status(unsigned sm, uint16_t bits, SimTime now_ns) {
  Submodule& s = sm_[sm];
  s.sts = static_cast<uint16_t>(s.sts & ~bits);
  if (bits & kRf) s.rf_cleared_at = reloads(s, now_ns);
  for (unsigned n = 0; n < 6; ++n) {
    if (s.running && (bits & (1u << n))) s.cmp_cleared_tick[n] = ticks(s, now_ns);
  }
  settle(sm);
}

void FlexPwm::capture_edge(unsigned sm, unsigned index, bool rising, SimTime time_ns) {
  Submodule& s = sm_[sm];
  refresh(sm, chip_.now_ns());
  Channel& channel = s.channel[index];
  if (!(channel.ctrl & 1u) || !s.running) return;  // not armed, or no counter to capture
  const unsigned circuit = channel.next;
  const unsigned edges = (channel.ctrl >> (circuit == 0 ? 2 : 4)) & 3u;  // EDGx0 / EDGx1
  const bool matches = edges == 3u || (edges == 2u && rising) || (edges == 1u && !rising);
  if (!matches) return;
  channel.value[circuit] = counter(s, time_ns);
  channel.cycle[circuit] = static_cast<uint16_t>(reloads(s, time_ns) & 0xFu);
  channel.full[circuit] = true;
  s.sts = static_cast<uint16_t>(s.sts | kCaptureFlag[index][circuit]);
  const unsigned other_edges = (channel.ctrl >> (circuit == 0 ? 4 : 2)) & 3u;
  if (other_edges != 0) channel.next = static_cast<uint8_t>(1 - circuit);  // the circuits alternate
  if (circuit == 1 && (channel.ctrl & 2u)) channel.ctrl = static_cast<uint16_t>(channel.ctrl & ~1u);  // one-shot
  settle(sm);
}

void FlexPwm::settle(unsigned sm) {
  Submodule& s = sm_[sm];
  const SimTime now = chip_.now_ns();
  const uint16_t enables = s.regs[kInten / 2];
  const bool high = (status(sm, now) & enables) != 0;
  if (high != irq_high_[sm]) {
    irq_high_[sm] = high;
    chip_.set_irq_level(irq(sm), high);
  }
  // A reload interrupt needs a wake-up at the next reload (every 437 µs at 150 MHz).
  if (s.running && (enables & kRf) && !high) {
    const SimTime at = s.load_pending ? std::min(s.load_at_ns, next_reload_ns(s, now)) : next_reload_ns(s, now);
    if (!wake_[sm].scheduled() || wake_[sm].time() != at) chip_.scheduler().schedule(wake_[sm], at);
  } else {
    chip_.scheduler().cancel(wake_[sm]);
  }
}

}  // namespace stepdance::sim::image
