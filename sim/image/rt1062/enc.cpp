// ENC registers (RM §56.8) and the position counter on the knob's counts.
#include "image/rt1062/enc.hpp"

namespace stepdance::sim::image {
namespace {

// Register offsets (RM §56.8).
constexpr uint32_t kCtrl = 0x00, kFilt = 0x02, kWtr = 0x04, kPosd = 0x06, kPosdh = 0x08, kRev = 0x0A;
constexpr uint32_t kRevh = 0x0C, kUpos = 0x0E, kLpos = 0x10, kUposh = 0x12, kLposh = 0x14, kUinit = 0x16;
constexpr uint32_t kLinit = 0x18, kCtrl2 = 0x1E, kUmod = 0x20, kLmod = 0x22, kUcomp = 0x24, kLcomp = 0x26;
// CTRL bits: HIRQ 15, HIE 14, HIP 13, HNE 12, SWIP 11, REV 10, PH1 9, XIRQ 8, XIE 7, XIP 6, XNE 5,
// DIRQ 4, DIE 3, WDE 2, CMPIE 1, CMPIRQ 0.
constexpr uint16_t kSwip = 1u << 11, kRevDir = 1u << 10;
constexpr uint16_t kIrqFlags = (1u << 15) | (1u << 8) | (1u << 4) | 1u;  // w1c
constexpr uint16_t kRefused = (1u << 14) | (1u << 9) | (1u << 7) | (1u << 3) | (1u << 2) | (1u << 1);
constexpr uint16_t kUpdateHolds = 1u << 0;  // CTRL2 UPDHLD; the other CTRL2 bits are refused

/// Each encoder's phase pins: XBAR1 output, the INOUT input it must select, and the pad
/// (SW_MUX_CTL offset, ALT, XBAR1_INnn_SELECT_INPUT offset and value), RM §11.7 / chapter 4:
/// ENC1 A = pin 0 (AD_B0_03 ALT1, INOUT17), B = pin 1 (AD_B0_02 ALT1, INOUT16);
/// ENC2 A = pin 2 (EMC_04 ALT3, INOUT06), B = pin 3 (EMC_05 ALT3, INOUT07).
struct Phase {
  uint8_t output;
  uint8_t inout;
  uint16_t mux;
  uint8_t alt;
  uint16_t select;
  uint8_t select_value;
};
constexpr Phase kPhases[2][2] = {
    {{66, 17, 0x0C8, 1, 0x62C, 1}, {67, 16, 0x0C4, 1, 0x64C, 0}},
    {{71, 6, 0x024, 3, 0x61C, 0}, {72, 7, 0x028, 3, 0x620, 0}},
};
constexpr uint32_t kIomuxc = 0x401F8000u, kGpr6 = 0x400AC018u;  // RM §11.7, §11.4 GPR6

bool read_word(const PeripheralBus& bus, uint32_t address, uint32_t& value) {
  BusRefusal refusal;
  return bus.read(address, 4, value, refusal);
}

}  // namespace

Enc::Enc(unsigned index, const PeripheralBus& bus, ChipContext& chip, BoardIo& io, const Xbar1& xbar)
    : index_(index), bus_(bus), chip_(chip), io_(io), xbar_(xbar) {}

bool Enc::phases_routed() const {
  for (const Phase& phase : kPhases[index_]) {
    if (xbar_.input_of(phase.output) != phase.inout) return false;
    uint32_t mux = 0, select = 0, gpr6 = 0;
    if (!read_word(bus_, kIomuxc + phase.mux, mux)) continue;  // no IOMUXC: the XBAR decides
    if ((mux & 0xFu) != phase.alt) return false;
    if (read_word(bus_, kIomuxc + phase.select, select) && (select & 1u) != phase.select_value) return false;
    if (read_word(bus_, kGpr6, gpr6) && (gpr6 & (1u << (phase.inout + 12u)))) return false;  // an output
  }
  return true;
}

int64_t Enc::counts_now() const {
  const int64_t counts = io_.encoder_counts(chip_.now_ns(), static_cast<uint8_t>(index_));
  return (ctrl_ & kRevDir) ? -counts : counts;
}

uint32_t Enc::position() {
  routing_changed();
  return static_cast<uint32_t>(routed_ ? counts_now() + offset_ : held_);
}

void Enc::routing_changed() {
  const bool routed = phases_routed();
  if (routed == routed_) return;
  if (routed) {
    offset_ = held_ - counts_now();  // counting resumes from the held position
  } else {
    held_ = counts_now() + offset_;
  }
  routed_ = routed;
}

void Enc::trigger() {
  if (!(ctrl2_ & kUpdateHolds)) return;
  if (first_trigger_ns_ < 0) first_trigger_ns_ = chip_.now_ns();
  latch_holds();
}

void Enc::latch_holds() {
  const uint32_t pos = position();
  posdh_ = static_cast<uint16_t>(static_cast<int64_t>(pos) - posd_base_);
  posd_base_ = pos;
  revh_ = 0;  // no index pulses, no modulus: the revolution counter stays 0
  uposh_ = static_cast<uint16_t>(pos >> 16);
  lposh_ = static_cast<uint16_t>(pos);
}

Access Enc::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 2) return Access::kUnmodelled;
  switch (offset) {
    case kCtrl: value = ctrl_; break;
    case kFilt: value = filt_; break;
    case kWtr: value = wtr_; break;
    case kPosd:
      latch_holds();
      value = posdh_;
      break;
    case kRev:
      latch_holds();
      value = revh_;
      break;
    case kUpos:
      latch_holds();
      value = uposh_;
      break;
    case kLpos:
      latch_holds();
      value = lposh_;
      break;
    case kPosdh: value = posdh_; break;
    case kRevh: value = revh_; break;
    case kUposh: value = uposh_; break;
    case kLposh: value = lposh_; break;
    case kUinit: value = uinit_; break;
    case kLinit: value = linit_; break;
    case kCtrl2: value = ctrl2_; break;
    case kUmod: value = umod_; break;
    case kLmod: value = lmod_; break;
    case kUcomp: value = ucomp_; break;
    case kLcomp: value = lcomp_; break;
    default: return Access::kUnmodelled;  // IMR (input monitor), TST
  }
  return Access::kOk;
}

Access Enc::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 2) return Access::kUnmodelled;
  const uint16_t half = static_cast<uint16_t>(value);
  switch (offset) {
    case kCtrl: {
      if (half & kRefused) return Access::kUnmodelled;  // interrupts, watchdog, single phase
      routing_changed();
      const int64_t pos = routed_ ? counts_now() + offset_ : held_;
      ctrl_ = static_cast<uint16_t>((half & ~(kSwip | kIrqFlags)) | (ctrl_ & kIrqFlags & ~half));
      const int64_t start = (half & kSwip) ? static_cast<int64_t>((uint32_t{uinit_} << 16) | linit_) : pos;
      held_ = start;                   // SWIP loads UINIT:LINIT; REV changes only the direction
      offset_ = start - counts_now();  // (SWIP self-clears: reads 0)
      break;
    }
    case kFilt: filt_ = half; break;
    case kWtr: wtr_ = half; break;
    case kUinit: uinit_ = half; break;
    case kLinit: linit_ = half; break;
    case kCtrl2:
      if (half & ~kUpdateHolds) return Access::kUnmodelled;  // modulus, UPDPOS, interrupts
      ctrl2_ = half;
      break;
    case kUmod: umod_ = half; break;
    case kLmod: lmod_ = half; break;
    case kUcomp: ucomp_ = half; break;
    case kLcomp: lcomp_ = half; break;
    default: return Access::kUnmodelled;  // positions, holds, IMR, TST
  }
  return Access::kOk;
}

}  // namespace stepdance::sim::image
