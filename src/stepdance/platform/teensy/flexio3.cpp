// FlexIO3 frame clock and port shifters (RM chapter 50; clock root RM §14.7 CCM_CSCMR2/CS1CDR).
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/flexio3.hpp"

#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_dwt.hpp"
#include "stepdance/platform/teensy/regs_flexio.hpp"

namespace stepdance::platform::teensy::flexio {

namespace ccm = regs::ccm;
namespace fio = regs::flexio3;

namespace {

volatile bool is_powered = false;
// Bits each port shifts per frame: 32, or fewer in a frame of 32 µs or less (set by the clock).
uint32_t port_bits = kFrameBits;

// Baud mode: lower byte = half a bit period - 1, upper byte = 2 × bits - 1.
constexpr uint32_t port_timer_compare(uint32_t bits) { return ((2u * bits - 1u) << 8) | (kClocksPerBit / 2u - 1u); }

constexpr uint32_t timer_bit(uint8_t timer) { return 1u << timer; }

// Routes PLL3 (480 MHz) / 2 / 2 = 120 MHz to the FlexIO2/3 root, with the gates off while the
// mux and dividers change (RM §14.7: change a root only while its clock gates are off).
void set_clock_root() {
  const bool flexio2_was_on = ccm::gate_is_on(ccm::kGateFlexio2);
  ccm::gate_off(ccm::kGateFlexio2);
  ccm::gate_off(ccm::kGateFlexio3);
  ccm::cscmr2() =
      (ccm::cscmr2() & ~ccm::kCscmr2Flexio2SelMask) | regs::field(ccm::kFlexio2SelPll3, ccm::kCscmr2Flexio2SelShift);
  ccm::cs1cdr() = (ccm::cs1cdr() & ~(ccm::kCs1cdrFlexio2PodfMask | ccm::kCs1cdrFlexio2PredMask)) |
                  regs::field(1, ccm::kCs1cdrFlexio2PodfShift) | regs::field(1, ccm::kCs1cdrFlexio2PredShift);
  static_assert(ccm::kPll3Hz / 2 / 2 == kClockHz, "FlexIO clock root settings");
  if (flexio2_was_on) ccm::gate_on(ccm::kGateFlexio2);
  ccm::gate_on(ccm::kGateFlexio3);
}

}  // namespace

void power_up() {
  if (is_powered) return;
  set_clock_root();
  fio::ctrl() = fio::kCtrlSoftReset;  // every FlexIO3 register back to its reset value
  fio::ctrl() = 0;
  fio::ctrl() = fio::kCtrlEnable;
  is_powered = true;
}

bool powered() { return is_powered; }

void configure_port(uint8_t port, uint8_t step_pin, uint8_t dir_pin) {
  const uint8_t step = port;
  const uint8_t dir = static_cast<uint8_t>(port + 4u);
  fio::timctl(port) = fio::kTimodDisabled;
  // No start or stop bit, 1-bit wide, shift on the timer's rising edge (SHIFTCFG = 0).
  fio::shiftcfg(step) = 0;
  fio::shiftcfg(dir) = 0;
  fio::shiftctl(step) =
      fio::shiftctl_timer(port) | fio::kShiftctlPinOutput | fio::shiftctl_pin(step_pin) | fio::kShiftctlTransmit;
  fio::shiftctl(dir) =
      fio::shiftctl_timer(port) | fio::kShiftctlPinOutput | fio::shiftctl_pin(dir_pin) | fio::kShiftctlTransmit;
  fio::shiftbuf(step) = 0;
  fio::shiftbuf(dir) = 0;
  fio::timcmp(port) = port_timer_compare(port_bits);
  fio::timcfg(port) = fio::timcfg_enable(fio::kTimenaTriggerRising) | fio::timcfg_disable(fio::kTimdisOnCompare);
  fio::timctl(port) = fio::timctl_trigger_timer(kFrameClockTimer) | fio::kTimctlTriggerInternal | fio::kTimodDual8Baud;
}

void write_port(uint8_t port, uint32_t step_bits, uint32_t dir_bits) {
  fio::shiftbuf(port + 4u) = dir_bits;
  fio::shiftbuf(port) = step_bits;
}

void settle_writes() {
  const uint32_t readback = fio::ctrl();  // completes only after the earlier writes to FlexIO3
  (void)readback;
  regs::data_sync_barrier();
  // kMarkerDelayClocks FlexIO clocks (33 ns) plus synchronisation: 64 core cycles is longer at
  // any core clock up to 1 GHz.
  const uint32_t start = regs::dwt::cyccnt();
  while (regs::dwt::cyccnt() - start < 64u) {
  }
}

bool tick_flag() { return (fio::timstat() & timer_bit(kTickMarkerTimer)) != 0; }

bool guard_flag() { return (fio::timstat() & timer_bit(kCommitGuardTimer)) != 0; }

void clear_tick_flag() {
  fio::timstat() = timer_bit(kTickMarkerTimer) | timer_bit(kCommitGuardTimer);
  regs::data_sync_barrier();
}

Status start_frame_clock(uint32_t period_us) {
  // The 16-bit timer counts half a period: at most 65536 clocks, 1092 µs at 120 MHz. A frame
  // shifts 32 bits, or period − 1 in a shorter one, so each ends with its lines low (the core's
  // formats are low from their window on; see protocol/frame_format.hpp).
  if (period_us < kMinFramePeriodUs || period_us > 2u * 0x10000u / kClocksPerBit) return Status::kBadArgument;
  const uint32_t half_period = period_us * kClocksPerBit / 2u;
  if (half_period <= kCommitGuardClocks) return Status::kBadArgument;
  port_bits = period_us > kFrameBits ? kFrameBits : period_us - 1u;
  for (uint8_t port = 0; port < kPorts; ++port) fio::timcmp(port) = port_timer_compare(port_bits);
  fio::timctl(kFrameClockTimer) = fio::kTimodDisabled;
  fio::timctl(kTickMarkerTimer) = fio::kTimodDisabled;
  fio::timcmp(kTickMarkerTimer) = kMarkerDelayClocks - 1u;
  fio::timcfg(kTickMarkerTimer) =
      fio::timcfg_enable(fio::kTimenaTriggerRising) | fio::timcfg_disable(fio::kTimdisOnCompare);
  fio::timctl(kTickMarkerTimer) =
      fio::timctl_trigger_timer(kFrameClockTimer) | fio::kTimctlTriggerInternal | fio::kTimod16Bit;
  // The commit guard starts at mid-period (trigger inverted: the frame clock's falling edge) and
  // raises its flag kCommitGuardClocks before the next rising edge.
  fio::timctl(kCommitGuardTimer) = fio::kTimodDisabled;
  fio::timcmp(kCommitGuardTimer) = half_period - kCommitGuardClocks - 1u;
  fio::timcfg(kCommitGuardTimer) =
      fio::timcfg_enable(fio::kTimenaTriggerRising) | fio::timcfg_disable(fio::kTimdisOnCompare);
  fio::timctl(kCommitGuardTimer) = fio::timctl_trigger_timer(kFrameClockTimer) | fio::kTimctlTriggerInternal |
                                   fio::kTimctlTriggerActiveLow | fio::kTimod16Bit;
  fio::timstat() = timer_bit(kTickMarkerTimer) | timer_bit(kCommitGuardTimer);
  fio::timien() |= timer_bit(kTickMarkerTimer);
  // The frame clock's output is high from enable and toggles every half period.
  fio::timcmp(kFrameClockTimer) = half_period - 1u;
  fio::timcfg(kFrameClockTimer) = fio::timcfg_enable(fio::kTimenaAlways) | fio::timcfg_disable(fio::kTimdisNever);
  fio::timctl(kFrameClockTimer) = fio::kTimod16Bit;
  return Status::kOk;
}

void stop_frame_clock() {
  if (!is_powered) return;
  fio::timien() &= ~timer_bit(kTickMarkerTimer);
  fio::timctl(kFrameClockTimer) = fio::kTimodDisabled;
  fio::timctl(kTickMarkerTimer) = fio::kTimodDisabled;
  fio::timctl(kCommitGuardTimer) = fio::kTimodDisabled;
  clear_tick_flag();
}

}  // namespace stepdance::platform::teensy::flexio

#endif  // __IMXRT1062__
