// FLEXIO3's registers (RM §50.5.1): decoding, reserved bits, write-one-to-clear flags, checks.
#include "image/rt1062/flexio3.hpp"

#include "image/rt1062/clock_roots.hpp"
#include "image/rt1062/flexio3_pins.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

// Register offsets, RM §50.5.1 (FlexIO memory map).
constexpr uint32_t kCtrl = 0x008u;       // CTRL
constexpr uint32_t kShiftstat = 0x010u;  // SHIFTSTAT (w1c)
constexpr uint32_t kShifterr = 0x014u;   // SHIFTERR (w1c)
constexpr uint32_t kTimstat = 0x018u;    // TIMSTAT (w1c)
constexpr uint32_t kShiftsien = 0x020u;  // SHIFTSIEN
constexpr uint32_t kShifteien = 0x024u;  // SHIFTEIEN
constexpr uint32_t kTimien = 0x028u;     // TIMIEN
constexpr uint32_t kShiftctl = 0x080u;   // SHIFTCTL0..7
constexpr uint32_t kShiftcfg = 0x100u;   // SHIFTCFG0..7
constexpr uint32_t kShiftbuf = 0x200u;   // SHIFTBUF0..7
constexpr uint32_t kTimctl = 0x400u;     // TIMCTL0..7
constexpr uint32_t kTimcfg = 0x480u;     // TIMCFG0..7
constexpr uint32_t kTimcmp = 0x500u;     // TIMCMP0..7

// Writable bits (the rest are reserved: read 0, writes ignored), RM §50.5.1.
constexpr uint32_t kCtrlBits = 0xC0000007u;  // DOZEN, DBGE, FASTACC, SWRST, FLEXEN
constexpr uint32_t kCtrlFlexen = 1u << 0;
constexpr uint32_t kCtrlSwrst = 1u << 1;
constexpr uint32_t kFlagBits = 0xFFu;            // one bit per shifter / timer
constexpr uint32_t kShiftctlBits = 0x07831F87u;  // TIMSEL, TIMPOL, PINCFG, PINSEL, PINPOL, SMOD
constexpr uint32_t kShiftcfgBits = 0x001F0133u;  // PWIDTH, INSRC, SSTOP, SSTART
constexpr uint32_t kTimctlBits = 0x3FC31F83u;    // TRGSEL, TRGPOL, TRGSRC, PINCFG, PINSEL, PINPOL, TIMOD
constexpr uint32_t kTimcfgBits = 0x03377732u;    // TIMOUT, TIMDEC, TIMRST, TIMDIS, TIMENA, TSTOP, TSTART
constexpr uint32_t kTimcmpBits = 0xFFFFu;        // CMP

constexpr uint32_t kSmodTransmit = 2u;  // SHIFTCTL SMOD
constexpr uint32_t kPinOutput = 3u;     // SHIFTCTL PINCFG

/// Index of a register in an array of 8 at `first`, or -1.
int index_in(uint32_t offset, uint32_t first) {
  return offset >= first && offset < first + 0x20u ? static_cast<int>((offset - first) / 4u) : -1;
}

uint32_t reverse_bits(uint32_t v) {
  uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= ((v >> i) & 1u) << (31 - i);
  return r;
}
uint32_t swap_bytes(uint32_t v) { return (v >> 24) | ((v >> 8) & 0xFF00u) | ((v << 8) & 0xFF0000u) | (v << 24); }
uint32_t swap_nibbles_in_bytes(uint32_t v) { return ((v >> 4) & 0x0F0F0F0Fu) | ((v << 4) & 0xF0F0F0F0u); }
uint32_t reverse_nibbles(uint32_t v) { return swap_nibbles_in_bytes(swap_bytes(v)); }

/// The SHIFTBUF aliases (RM §50.5.1): each shows SHIFTBUF through an involution.
struct BufferAlias {
  uint32_t offset;
  uint32_t (*view)(uint32_t);
};
constexpr BufferAlias kAliases[] = {
    {0x280u, reverse_bits},                                            // SHIFTBUFBIS: bit swapped
    {0x300u, swap_bytes},                                              // SHIFTBUFBYS: byte swapped
    {0x380u, [](uint32_t v) { return swap_bytes(reverse_bits(v)); }},  // SHIFTBUFBBS: bits in bytes
    {0x680u, swap_nibbles_in_bytes},                                   // SHIFTBUFNBS: nibbles in bytes
    {0x700u, [](uint32_t v) { return (v >> 16) | (v << 16); }},        // SHIFTBUFHWS: half words
    {0x780u, reverse_nibbles},                                         // SHIFTBUFNIS: nibbles
};

}  // namespace

Flexio3::Flexio3(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model)
    : bus_(bus), chip_(chip), io_(io), model_(model), wake_(*this) {}

Flexio3::~Flexio3() { chip_.scheduler().cancel(wake_); }

void Flexio3::reset_registers() {
  shiftstat_ = shifterr_ = timstat_ = shiftsien_ = shifteien_ = timien_ = 0;
  for (Timer& timer : timers_) timer = Timer{};
  for (Shifter& shifter : shifters_) shifter = Shifter{};
}

Access Flexio3::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;  // the backend accesses FlexIO 32 bits wide
  advance();
  const Access result = read_register(offset, value);
  settle();
  return result;
}

Access Flexio3::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  advance();
  const Access result = (ctrl_ & kCtrlSwrst) && offset != kCtrl ? Access::kOk  // held in reset
                                                                : write_register(offset, value);
  settle();
  return result;
}

Access Flexio3::read_register(uint32_t offset, uint32_t& value) {
  int n = -1;
  if (offset == kCtrl)
    value = ctrl_;
  else if (offset == kShiftstat)
    value = shiftstat_;
  else if (offset == kShifterr)
    value = shifterr_;
  else if (offset == kTimstat)
    value = timstat_;
  else if (offset == kShiftsien)
    value = shiftsien_;
  else if (offset == kShifteien)
    value = shifteien_;
  else if (offset == kTimien)
    value = timien_;
  else if ((n = index_in(offset, kShiftctl)) >= 0)
    value = shifters_[n].ctl;
  else if ((n = index_in(offset, kShiftcfg)) >= 0)
    value = shifters_[n].cfg;
  else if ((n = index_in(offset, kShiftbuf)) >= 0)
    value = shifters_[n].buf;
  else if ((n = index_in(offset, kTimctl)) >= 0)
    value = timers_[n].ctl;
  else if ((n = index_in(offset, kTimcfg)) >= 0)
    value = timers_[n].cfg;
  else if ((n = index_in(offset, kTimcmp)) >= 0)
    value = timers_[n].cmp;
  else
    return access_buffer_alias(offset, false, value);
  return Access::kOk;
}

Access Flexio3::write_register(uint32_t offset, uint32_t value) {
  int n = -1;
  if (offset == kCtrl) return write_ctrl(value);
  if (offset == kShiftstat)
    shiftstat_ &= ~(value & kFlagBits);
  else if (offset == kShifterr)
    shifterr_ &= ~(value & kFlagBits);
  else if (offset == kTimstat)
    timstat_ &= ~(value & kFlagBits);
  else if (offset == kShiftsien)
    shiftsien_ = value & kFlagBits;
  else if (offset == kShifteien)
    shifteien_ = value & kFlagBits;
  else if (offset == kTimien)
    timien_ = value & kFlagBits;
  else if ((n = index_in(offset, kShiftctl)) >= 0)
    return write_shiftctl(n, value & kShiftctlBits);
  else if ((n = index_in(offset, kShiftcfg)) >= 0) {
    // Only 1-bit shifters without start/stop bits or pin input are modelled.
    if ((value & kShiftcfgBits) != 0) return Access::kUnmodelled;
    shifters_[n].cfg = 0;
  } else if ((n = index_in(offset, kShiftbuf)) >= 0)
    return write_shiftbuf(n, value);
  else if ((n = index_in(offset, kTimctl)) >= 0)
    return write_timctl(n, value & kTimctlBits);
  else if ((n = index_in(offset, kTimcfg)) >= 0)
    return write_timcfg(n, value & kTimcfgBits);
  else if ((n = index_in(offset, kTimcmp)) >= 0)
    timers_[n].cmp = value & kTimcmpBits;
  else
    return access_buffer_alias(offset, true, value);
  return Access::kOk;
}

Access Flexio3::access_buffer_alias(uint32_t offset, bool is_write, uint32_t& value) {
  for (const BufferAlias& alias : kAliases) {
    const int n = index_in(offset, alias.offset);
    if (n < 0) continue;
    if (!is_write) {
      value = alias.view(shifters_[n].buf);
      return Access::kOk;
    }
    return write_shiftbuf(static_cast<unsigned>(n), alias.view(value));
  }
  return Access::kUnmodelled;  // VERID, PARAM, PIN, SHIFTSDEN, SHIFTSTATE: not used, not modelled
}

Access Flexio3::write_ctrl(uint32_t value) {
  value &= kCtrlBits;
  const bool was_enabled = (ctrl_ & kCtrlFlexen) != 0;
  if (value & kCtrlSwrst) reset_registers();  // every register but CTRL (RM §50.5.1.3, SWRST)
  const bool enabled = (value & kCtrlFlexen) != 0 && !(value & kCtrlSwrst);
  if (enabled && !was_enabled) {
    uint32_t hz = 0;
    if (!flexio2_root_hz(bus_, hz) || hz == 0) return Access::kUnmodelled;  // no clock root to count
    clock_ = ClockDomain{chip_.now_ns(), hz};
    ctrl_ = value;
    start_free_runners(0);
    return Access::kOk;
  }
  if (!enabled) {
    for (Timer& timer : timers_) timer.running = false;
  }
  ctrl_ = value;
  return Access::kOk;
}

Access Flexio3::write_timctl(unsigned n, uint32_t value) {
  Timer& timer = timers_[n];
  const Kind kind = kind_of(value, timer.cfg);
  if (kind == Kind::kInvalid || (kind != Kind::kOff && !trigger_valid(n, value))) return Access::kUnmodelled;
  const bool was_on = (timer.ctl & 3u) != 0;
  timer.ctl = value;
  if (kind == Kind::kOff) {
    timer.running = false;  // a disabled timer's output is low; no edge is modelled (RM §50.5.1.9)
  } else if (!was_on) {
    enable_timer(n, now_clk());
  }
  return Access::kOk;
}

Access Flexio3::write_timcfg(unsigned n, uint32_t value) {
  Timer& timer = timers_[n];
  if (kind_of(timer.ctl, value) == Kind::kInvalid) return Access::kUnmodelled;
  if ((timer.ctl & 3u) != 0 && kind_of(timer.ctl, value) != kind_of(timer.ctl, timer.cfg)) {
    return Access::kUnmodelled;  // reshaping a timer that is on
  }
  timer.cfg = value;
  return Access::kOk;
}

Access Flexio3::write_shiftctl(unsigned n, uint32_t value) {
  const uint32_t smod = value & 7u;
  const uint32_t pincfg = (value >> 16) & 3u;
  if (smod != 0 && smod != kSmodTransmit) return Access::kUnmodelled;  // only transmitters
  if (value & ((1u << 23) | (1u << 7))) return Access::kUnmodelled;    // TIMPOL, PINPOL: not modelled
  if (pincfg != 0 && pincfg != kPinOutput) return Access::kUnmodelled;
  if (pincfg == kPinOutput) {
    const uint8_t pin = flexio3_teensy_pin(model_, static_cast<uint8_t>((value >> 8) & 0x1Fu));
    if (pin == kNoFlexioRoute || output_port_line(pin).port == kNoFlexioRoute) return Access::kUnmodelled;
  }
  const bool was_transmit = (shifters_[n].ctl & 7u) == kSmodTransmit;
  shifters_[n].ctl = value;
  // A transmitter starts with its buffer empty (RM §50.5.1.4, SSF).
  if (smod == kSmodTransmit && !was_transmit) shiftstat_ |= 1u << n;
  return Access::kOk;
}

Access Flexio3::write_shiftbuf(unsigned n, uint32_t value) {
  shifters_[n].buf = value;
  shiftstat_ &= ~(1u << n);  // a transmitter's SSF clears when SHIFTBUF is written (RM §50.5.1.4)
  return Access::kOk;
}

void Flexio3::Wake::fire(Event& event, Scheduler&) {
  Flexio3& self = static_cast<Wake&>(event).owner;
  self.advance();
  self.settle();
}

}  // namespace stepdance::sim::image
