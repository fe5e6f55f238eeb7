// PIT (RM §53.4).
#include "image/rt1062/pit.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Offsets (RM §53.4): MCR 0x000, LTMR64H 0x0E0, LTMR64L 0x0E4, channel n at 0x100 + 0x10 n:
// LDVAL +0, CVAL +4, TCTRL +8, TFLG +C.
constexpr uint32_t kMcr = 0x000, kFirstChannel = 0x100, kLdval = 0x0, kCval = 0x4, kTctrl = 0x8, kTflg = 0xC;
constexpr uint32_t kTctrlEnable = 1u << 0, kTctrlInterrupt = 1u << 1, kTctrlChain = 1u << 2;
constexpr unsigned kIrqPit = 122;  // RM table 4-2

}  // namespace

Pit::Pit(ChipContext& context, Ccm& ccm) : context_(context), ccm_(ccm) {
  for (size_t i = 0; i < channels_.size(); ++i) {
    channels_[i].expiry = std::make_unique<ModelEvent>([this, i] { expire(i); });
  }
  ccm_.add_rates_listener([this](const ClockRates& rates) {
    if (rates.perclk_hz == perclk_hz_) return;
    perclk_hz_ = rates.perclk_hz;
    restart_all();
  });
}

Pit::~Pit() {
  for (Channel& channel : channels_) context_.scheduler().cancel(*channel.expiry);
}

uint32_t Pit::current_value(const Channel& channel) const {
  if (!counting(channel)) return channel.period_ldval;
  const uint64_t ticks = channel.clock.ticks_at(context_.now_ns()) - channel.period_start;
  const uint64_t period = uint64_t{channel.period_ldval} + 1u;
  return static_cast<uint32_t>(channel.period_ldval - ticks % period);
}

// The channel starts counting now, from LDVAL (or stops, if it no longer counts).
void Pit::start_counting(Channel& channel) {
  channel.period_ldval = channel.ldval;
  channel.clock = TickClock(context_.now_ns(), ccm_.perclk_hz(), 1);
  channel.period_start = 0;
  schedule_expiry(channel);
}

// The running period's expiry, LDVAL + 1 ticks after it began.
void Pit::schedule_expiry(Channel& channel) {
  context_.scheduler().cancel(*channel.expiry);
  if (!counting(channel) || !channel.clock.running()) return;
  const uint64_t end = channel.period_start + channel.period_ldval + 1u;
  context_.scheduler().schedule(*channel.expiry, channel.clock.time_of(end));
}

void Pit::expire(size_t index) {
  Channel& channel = channels_[index];
  channel.tflg = 1;
  channel.period_start += uint64_t{channel.period_ldval} + 1u;
  channel.period_ldval = channel.ldval;  // reload with the LDVAL written by now
  schedule_expiry(channel);
  update_irq();
  if (trigger_sink_) trigger_sink_(static_cast<unsigned>(index));
}

// PERCLK changed or MDIS flipped: every running channel starts afresh from LDVAL now.
void Pit::restart_all() {
  for (Channel& channel : channels_) start_counting(channel);
}

void Pit::update_irq() {
  bool high = false;
  for (const Channel& channel : channels_) high = high || ((channel.tflg & 1u) && (channel.tctrl & kTctrlInterrupt));
  if (high == irq_high_) return;
  irq_high_ = high;
  context_.set_irq_level(kIrqPit, high);
}

Access Pit::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const uint32_t word = offset & ~3u;
  uint32_t result = 0;
  if (word == kMcr) {
    result = mcr_;
  } else if (word >= kFirstChannel && word < kFirstChannel + 0x40u) {
    const Channel& channel = channels_[(word - kFirstChannel) / 16u];
    switch (word & 0xFu) {
      case kLdval: result = channel.ldval; break;
      case kCval: result = current_value(channel); break;
      case kTctrl: result = channel.tctrl; break;
      default: result = channel.tflg; break;
    }
  } else {
    return Access::kUnmodelled;  // LTMR64H/L (the lifetime timer) among them
  }
  value = lane_read(result, offset, bytes);
  return Access::kOk;
}

Access Pit::write_channel(size_t index, uint32_t reg, uint32_t value) {
  Channel& channel = channels_[index];
  switch (reg) {
    case kLdval: channel.ldval = value; break;  // loads at the next expiry (or at enable)
    case kCval: break;                          // read only
    case kTctrl: {
      if (value & kTctrlChain) return Access::kUnmodelled;
      const bool was_enabled = (channel.tctrl & kTctrlEnable) != 0;
      channel.tctrl = value & (kTctrlEnable | kTctrlInterrupt);
      if (((channel.tctrl & kTctrlEnable) != 0) != was_enabled) start_counting(channel);
      break;
    }
    default: channel.tflg &= ~(value & 1u); break;  // TIF: write 1 to clear
  }
  update_irq();
  return Access::kOk;
}

Access Pit::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  if (word == kMcr) {
    const uint32_t old_mcr = mcr_;
    mcr_ = lane_merge(mcr_, offset, bytes, value) & 3u;
    if ((old_mcr ^ mcr_) & 2u) restart_all();
    return Access::kOk;
  }
  if (word < kFirstChannel || word >= kFirstChannel + 0x40u) return Access::kUnmodelled;
  const size_t index = (word - kFirstChannel) / 16u;
  const uint32_t reg = word & 0xFu;
  const uint32_t current = reg == kLdval ? channels_[index].ldval : reg == kTctrl ? channels_[index].tctrl : 0u;
  return write_channel(index, reg, lane_merge(current, offset, bytes, value));
}

}  // namespace stepdance::sim::image::rt1062
