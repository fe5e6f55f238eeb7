// ADC1/ADC2 (RM §66.8).
#include "image/rt1062/adc.hpp"

#include "image/rt1062/pads.hpp"
#include "image/rt1062/tick_clock.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Offsets (RM §66.8): HC0..7 0x00..0x1C, HS 0x20, R0..7 0x24..0x40, CFG 0x44, GC 0x48, GS 0x4C,
// CV 0x50, OFS 0x54, CAL 0x58.
constexpr uint32_t kHs = 0x20, kR0 = 0x24, kR7 = 0x40, kCfg = 0x44, kGc = 0x48, kGs = 0x4C, kCv = 0x50, kOfs = 0x54,
                   kCal = 0x58;
constexpr uint32_t kHcAien = 1u << 7, kHcChannelMask = 0x1Fu, kChannelOff = 0x1Fu;
constexpr uint32_t kCfgAdhsc = 1u << 10, kCfgAdlsmp = 1u << 4, kCfgAdtrg = 1u << 13, kCfgOvwren = 1u << 16;
constexpr uint32_t kGcAdco = 1u << 6, kGcAvge = 1u << 5, kGcAcfe = 1u << 4, kGcCal = 1u << 7;
constexpr uint32_t kGsAdact = 1u << 0, kGsCalf = 1u << 1;
constexpr unsigned kIrqAdc1 = 67;  // RM table 4-2 (ADC2 = 68)

constexpr uint32_t kBaseConversion[4] = {17, 21, 25, 25};          // BCT by MODE (3 reserved: as 12-bit)
constexpr uint32_t kLongSample[8] = {3, 5, 7, 9, 13, 17, 21, 25};  // LSTAdder by ADLSMP:ADSTS
constexpr uint32_t kFirstConversionAdder = 6;                      // SFCAdder
constexpr uint32_t kResolutionMax[4] = {255, 1023, 4095, 4095};

}  // namespace

Adc::Adc(unsigned module, ChipContext& context, Ccm& ccm, BoardIo& world, TeensyModel model)
    : module_(module), context_(context), ccm_(ccm), world_(world), model_(model), done_([this] { finish(); }) {
  hc_.fill(kChannelOff);
}

Adc::~Adc() { context_.scheduler().cancel(done_); }

uint32_t Adc::adck_hz() const {
  uint32_t source = 0;
  switch (cfg_ & 3u) {
    case 0: source = ccm_.ipg_clock_hz(); break;
    case 1: source = ccm_.ipg_clock_hz() / 2u; break;
    case 3: source = (cfg_ & kCfgAdhsc) ? 20000000u : 10000000u; break;
    default: break;  // reserved: no clock
  }
  return source >> ((cfg_ >> 5) & 3u);
}

uint32_t Adc::conversion_cycles(bool first, bool calibration) const {
  const uint32_t average = calibration ? 32u : (gc_ & kGcAvge) ? 4u << ((cfg_ >> 14) & 3u) : 1u;
  const uint32_t lst = kLongSample[((cfg_ & kCfgAdlsmp) ? 4u : 0u) + ((cfg_ >> 8) & 3u)];
  const uint32_t each = kBaseConversion[(cfg_ >> 2) & 3u] + lst + ((cfg_ & kCfgAdhsc) ? 2u : 0u);
  return (first ? kFirstConversionAdder : 0u) + average * each;
}

// A job starts now (`first`), or right where the previous continuous conversion ended.
void Adc::start(Job job, bool first) {
  job_ = job;
  gs_ |= kGsAdact;
  if (first) {
    adck_ = TickClock(context_.now_ns(), adck_hz(), 1);
    end_cycle_ = 0;
  }
  end_cycle_ += conversion_cycles(first, job == Job::kCalibration);
  context_.scheduler().schedule(done_, adck_.time_of(end_cycle_));
}

void Adc::finish() {
  const Job job = job_;
  job_ = Job::kNone;
  gs_ &= ~kGsAdact;
  if (job == Job::kCalibration) {
    gc_ &= ~kGcCal;
    hs_ |= 1u;
  } else if (job == Job::kConversion) {
    const unsigned channel = hc_[0] & kHcChannelMask;
    const int pin = pad_teensy_pin(model_, adc_input_pad(module_, channel));
    const uint32_t level = world_.analog_level(context_.now_ns(), static_cast<uint8_t>(pin)) & 0x3FFu;
    const uint32_t full = kResolutionMax[(cfg_ >> 2) & 3u];
    if (!(hs_ & 1u) || (cfg_ & kCfgOvwren)) r0_ = (level * full + 511u) / 1023u;
    hs_ |= 1u;
    if (gc_ & kGcAdco) start(Job::kConversion, false);
  }
  update_irq();
}

void Adc::update_irq() {
  const bool high = (hs_ & 1u) && (hc_[0] & kHcAien);
  if (high == irq_high_) return;
  irq_high_ = high;
  context_.set_irq_level(kIrqAdc1 + module_, high);
}

Access Adc::write_hc0(uint32_t value) {
  const uint32_t channel = value & kHcChannelMask;
  const bool on_pin = channel < 16 && pad_teensy_pin(model_, adc_input_pad(module_, channel)) >= 0;
  if (channel != kChannelOff && !on_pin) return Access::kUnmodelled;
  context_.scheduler().cancel(done_);  // a write to HC0 aborts the conversion in progress
  job_ = Job::kNone;
  gs_ &= ~kGsAdact;
  hc_[0] = value & (kHcAien | kHcChannelMask);
  hs_ &= ~1u;
  if (channel != kChannelOff) start(Job::kConversion, true);
  update_irq();
  return Access::kOk;
}

Access Adc::write_cfg(uint32_t value) {
  if (value & kCfgAdtrg) return Access::kUnmodelled;
  cfg_ = value & 0x1FFFFu;
  return Access::kOk;
}

Access Adc::write_gc(uint32_t value) {
  if (value & kGcAcfe) return Access::kUnmodelled;
  gc_ = value & 0xFFu;
  if (gc_ & kGcCal) {
    context_.scheduler().cancel(done_);
    gs_ &= ~kGsCalf;
    hs_ &= ~1u;
    start(Job::kCalibration, true);
  }
  update_irq();
  return Access::kOk;
}

Access Adc::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  const uint32_t word = offset & ~3u;
  uint32_t result = 0;
  if (word < kHs) {
    result = hc_[word / 4u];
  } else if (word == kHs) {
    result = hs_;
  } else if (word >= kR0 && word <= kR7) {
    result = word == kR0 ? r0_ : 0u;
    if (word == kR0) {
      hs_ &= ~1u;  // reading R0 clears COCO0 (RM §66.8.3)
      update_irq();
    }
  } else {
    switch (word) {
      case kCfg: result = cfg_; break;
      case kGc: result = gc_; break;
      case kGs: result = gs_; break;
      case kCv: result = cv_; break;
      case kOfs: result = ofs_; break;
      case kCal: result = cal_; break;
      default: return Access::kUnmodelled;
    }
  }
  value = lane_read(result, offset, bytes);
  return Access::kOk;
}

Access Adc::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  if (word == 0) return write_hc0(lane_merge(hc_[0], offset, bytes, value));
  if (word < kHs) {  // HC1..7 serve hardware triggers only
    const uint32_t merged = lane_merge(hc_[word / 4u], offset, bytes, value);
    if ((merged & kHcChannelMask) != kChannelOff) return Access::kUnmodelled;
    hc_[word / 4u] = merged & (kHcAien | kHcChannelMask);
    return Access::kOk;
  }
  switch (word) {
    case kCfg: return write_cfg(lane_merge(cfg_, offset, bytes, value));
    case kGc: return write_gc(lane_merge(gc_, offset, bytes, value));
    case kGs: gs_ &= ~(lane_merge(0u, offset, bytes, value) & ~kGsAdact); return Access::kOk;  // W1C
    case kCv: cv_ = lane_merge(cv_, offset, bytes, value); return Access::kOk;
    case kOfs: ofs_ = lane_merge(ofs_, offset, bytes, value); return Access::kOk;
    case kCal: cal_ = lane_merge(cal_, offset, bytes, value) & 0xFu; return Access::kOk;
    default: break;
  }
  if (word == kHs || (word >= kR0 && word <= kR7)) return Access::kOk;  // read only
  return Access::kUnmodelled;
}

}  // namespace stepdance::sim::image::rt1062
