// LPI2C master registers (RM §47.4): MCR, MSR (w1c flags), configuration, FIFO control/status,
// MTDR/MRDR.
#include "image/rt1062/lpi2c.hpp"

#include "image/rt1062/clock_roots.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

// Master register offsets (RM §47.4.1).
constexpr uint32_t kMcr = 0x10, kMsr = 0x14, kMier = 0x18, kMder = 0x1C, kMcfgr0 = 0x20, kMcfgr1 = 0x24;
constexpr uint32_t kMcfgr2 = 0x28, kMcfgr3 = 0x2C, kMdmr = 0x40, kMccr0 = 0x48, kMccr1 = 0x50;
constexpr uint32_t kMfcr = 0x58, kMfsr = 0x5C, kMtdr = 0x60, kMrdr = 0x70;
// MCR: MEN 0, RST 1, DOZEN 2, DBGEN 3, RTF 8, RRF 9 (the last two write-only).
constexpr uint32_t kMen = 1u << 0, kRst = 1u << 1, kRtf = 1u << 8, kRrf = 1u << 9;
// MSR: TDF 0, RDF 1, EPF 8, SDF 9, NDF 10, ALF 11, FEF 12, PLTF 13, DMF 14, MBF 24, BBF 25.
constexpr uint32_t kMsrW1c = 0x7F00u, kNdf = 1u << 10, kMbf = 1u << 24, kBbf = 1u << 25;
constexpr uint32_t kRxEmpty = 1u << 14;  // MRDR RXEMPTY
constexpr size_t kFifoWords = 4;         // PARAM MTXFIFO/MRXFIFO = 2: 4 words (RM §47.4.1.2)

}  // namespace

Lpi2c::Lpi2c(unsigned instance, const PeripheralBus& bus, ChipContext& chip, BoardIo& io)
    : instance_(instance), bus_(bus), chip_(chip), io_(io), wake_(*this) {}

Lpi2c::~Lpi2c() { chip_.scheduler().cancel(wake_); }

void Lpi2c::reset_master() {
  flags_ = 0;
  for (uint32_t& cfg : mcfgr_) cfg = 0;
  mccr0_ = mccr1_ = mfcr_ = mdmr_ = 0;
  tx_.clear();
  rx_.clear();
  head_started_ = halted_ = bus_busy_ = false;
  segment_ = Segment{};
}

uint32_t Lpi2c::scl_hz() const {
  uint32_t root_hz = 0;
  if (!lpi2c_root_hz(bus_, root_hz)) return 0;
  // SCL period = (CLKHI + CLKLO + 2 + SCL_LATENCY) × 2^PRESCALE clocks, SCL_LATENCY =
  // floor((2 + FILTSCL) / 2^PRESCALE) (RM §47.4.1.14 MCCR0).
  const uint32_t prescale = mcfgr_[1] & 7u;
  const uint32_t latency = (2u + ((mcfgr_[2] >> 16) & 0xFu)) >> prescale;
  const uint32_t period = ((mccr0_ & 0x3Fu) + ((mccr0_ >> 8) & 0x3Fu) + 2u + latency) << prescale;
  return root_hz / period;
}

uint32_t Lpi2c::msr() const {
  const SimTime now = chip_.now_ns();
  size_t rx_count = 0;
  for (const auto& byte : rx_) rx_count += byte.first <= now ? 1u : 0u;
  if (rx_count > kFifoWords) rx_count = kFifoWords;
  uint32_t value = flags_;
  if (tx_.size() <= (mfcr_ & 3u)) value |= 1u << 0;       // TDF: TXCOUNT ≤ TXWATER
  if (rx_count > ((mfcr_ >> 16) & 3u)) value |= 1u << 1;  // RDF: RXCOUNT > RXWATER
  if (bus_busy_) value |= kMbf | kBbf;
  return value;
}

Access Lpi2c::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  if (bytes != 4) return Access::kUnmodelled;
  const SimTime now = chip_.now_ns();
  advance(now);
  switch (offset) {
    case kMcr: value = mcr_; break;
    case kMsr: value = msr(); break;
    case kMier:
    case kMder: value = 0; break;
    case kMcfgr0:
    case kMcfgr1:
    case kMcfgr2:
    case kMcfgr3: value = mcfgr_[(offset - kMcfgr0) / 4]; break;
    case kMdmr: value = mdmr_; break;
    case kMccr0: value = mccr0_; break;
    case kMccr1: value = mccr1_; break;
    case kMfcr: value = mfcr_; break;
    case kMfsr: {
      uint32_t rx_count = 0;
      for (const auto& byte : rx_) rx_count += byte.first <= now ? 1u : 0u;
      value = static_cast<uint32_t>(tx_.size()) | ((rx_count > kFifoWords ? kFifoWords : rx_count) << 16);
      break;
    }
    case kMrdr:
      if (!rx_.empty() && rx_.front().first <= now) {
        value = rx_.front().second;
        rx_.pop_front();
      } else {
        value = kRxEmpty;
      }
      break;
    default: return Access::kUnmodelled;  // VERID, PARAM, slave registers
  }
  return Access::kOk;
}

Access Lpi2c::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  if (bytes != 4) return Access::kUnmodelled;
  const SimTime now = chip_.now_ns();
  advance(now);
  if ((mcr_ & kRst) && offset != kMcr) return Access::kOk;  // held in reset
  switch (offset) {
    case kMcr: return write_mcr(value);
    case kMsr:
      flags_ &= ~(value & kMsrW1c);
      if (value & kNdf) halted_ = false;  // the master goes on once NDF is cleared
      break;
    case kMier:
    case kMder:
    case kMcfgr0:
      if (value != 0) return Access::kUnmodelled;  // interrupts, DMA, host request, …
      break;
    case kMcfgr1:
      if (value & ~7u) return Access::kUnmodelled;  // AUTOSTOP, IGNACK, TIMECFG, MATCFG, PINCFG
      mcfgr_[1] = value;
      break;
    case kMcfgr2: mcfgr_[2] = value & 0x0F0F0FFFu; break;  // FILTSDA, FILTSCL, BUSIDLE
    case kMcfgr3: mcfgr_[3] = value & 0x000FFF00u; break;  // PINLOW
    case kMdmr: mdmr_ = value & 0x00FF00FFu; break;
    case kMccr0: mccr0_ = value & 0x3F3F3F3Fu; break;
    case kMccr1: mccr1_ = value & 0x3F3F3F3Fu; break;
    case kMfcr: mfcr_ = value & 0x00030003u; break;  // RXWATER, TXWATER
    case kMtdr: {
      const uint32_t command = (value >> 8) & 7u;
      if (command == 3u || command >= 5u) return Access::kUnmodelled;  // discard, HS, expect NACK
      if (tx_.size() < kFifoWords) tx_.push_back(Command{static_cast<uint16_t>(value & 0x7FFu), now});
      break;
    }
    default: return Access::kUnmodelled;
  }
  advance(now);
  schedule_wake(now);
  return Access::kOk;
}

Access Lpi2c::write_mcr(uint32_t value) {
  const SimTime now = chip_.now_ns();
  if (value & kRst) reset_master();  // every master register but MCR (RM §47.4.1.3)
  if (value & kRtf) {
    tx_.clear();
    head_started_ = false;
    halted_ = false;
  }
  if (value & kRrf) rx_.clear();
  mcr_ = value & 0x0Fu;
  if (!(mcr_ & kMen)) head_started_ = false;
  advance(now);
  schedule_wake(now);
  return Access::kOk;
}

void Lpi2c::Wake::fire(Event& event, Scheduler& scheduler) {
  Lpi2c& self = static_cast<Wake&>(event).owner;
  self.advance(scheduler.now());
  self.schedule_wake(scheduler.now());
}

}  // namespace stepdance::sim::image
