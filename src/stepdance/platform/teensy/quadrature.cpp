// Quadrature decoders: pins 0/1 → ENC1 and 2/3 → ENC2 through XBAR1 (RM chapters 56 and 61).
// While frames run, each counter is read from its hold registers, which the sample clock's
// trigger fills at one instant before every frame tick (sample_clock.cpp); before that, live.
#if defined(__IMXRT1062__)

#include "stepdance/boards/board.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/clocks.hpp"
#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_enc.hpp"
#include "stepdance/platform/teensy/regs_xbar.hpp"
#include "stepdance/platform/teensy/timers.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace ccm = regs::ccm;
namespace enc = regs::enc;
namespace iomuxc = regs::iomuxc;
namespace xbar1 = regs::xbar1;

/// One phase input: Teensy pin, pad ALT that makes it XBAR1_INOUTnn, its input select.
struct PhaseWiring {
  uint8_t pin;
  uint8_t alt;
  uint8_t xbar_inout;
  uint16_t select_input;
  uint8_t select_value;
  uint8_t xbar_output;
};

struct EncoderWiring {
  PhaseWiring a;
  PhaseWiring b;
  uint8_t trigger_output;  // XBAR1 output of this ENC's TRIGGER input
  ccm::ClockGate gate;
};

// Pins from the board table (boards/board.hpp); the rest depends on the pad, checked below.
// Pin 0 = AD_B0_03 (ALT1, INOUT17, select 1), pin 1 = AD_B0_02 (ALT1, INOUT16, select 0),
// pin 2 = EMC_04 (ALT3, INOUT06, select 0), pin 3 = EMC_05 (ALT3, INOUT07, select 0).
constexpr const uint8_t (&kPins)[2][2] = kDriverModuleV1.encoder_pins;
constexpr EncoderWiring kWiring[2] = {
    {{kPins[0][0], 1, 17, iomuxc::kSelectXbar1In17, 1, xbar1::kOutEnc1PhaseA},
     {kPins[0][1], 1, 16, iomuxc::kSelectXbar1In16, 0, xbar1::kOutEnc1PhaseB},
     xbar1::kOutEnc1Trigger,
     ccm::kGateEnc1},
    {{kPins[1][0], 3, 6, iomuxc::kSelectXbar1In06, 0, xbar1::kOutEnc2PhaseA},
     {kPins[1][1], 3, 7, iomuxc::kSelectXbar1In07, 0, xbar1::kOutEnc2PhaseB},
     xbar1::kOutEnc2Trigger,
     ccm::kGateEnc2},
};
static_assert(pin_pad(kPins[0][0]).mux == pad::ad_b0(3).mux && pin_pad(kPins[0][1]).mux == pad::ad_b0(2).mux,
              "ENC1 phases must be pads AD_B0_03/AD_B0_02 (XBAR1 INOUT17/16)");
static_assert(pin_pad(kPins[1][0]).mux == pad::emc(4).mux && pin_pad(kPins[1][1]).mux == pad::emc(5).mux,
              "ENC2 phases must be pads EMC_04/EMC_05 (XBAR1 INOUT06/07)");
// Every registered board wires ENCn as ENCn here (or leaves it out).
constexpr bool boards_match_wiring() {
  for (const BoardDefinition* board : kBoards) {
    for (uint8_t index = 0; index < 2; ++index) {
      for (uint8_t phase = 0; phase < 2; ++phase) {
        const uint8_t pin = board->encoder_pins[index][phase];
        if (pin != kNoPin && pin != kPins[index][phase]) return false;
      }
    }
  }
  return true;
}
static_assert(boards_match_wiring(), "a board's encoder n is not wired as encoder n of this backend");

volatile bool begun[2] = {false, false};
// What quadrature_write() set: the position the sketch sees is the counter's plus this (the
// counter itself is never rewritten, so the hold registers stay true to the last sample).
volatile int32_t offsets[2] = {0, 0};

void attach_phase(const PhaseWiring& phase) {
  const PinInfo& pin = *pin_info(phase.pin);
  pad_configure(pin, kPadInput);  // the boards pull A and B up with 10 kΩ
  iomuxc::select_input(phase.select_input) = phase.select_value;
  iomuxc::gpr6() &= ~iomuxc::gpr6_xbar_output(phase.xbar_inout);  // INOUT as input
  pad_select(pin, phase.alt);
  xbar1::connect(phase.xbar_inout, phase.xbar_output);
}

// Glitch filter: 5 equal samples (FILT_CNT 2) about 0.1 µs apart, i.e. edges must hold ~0.5 µs.
uint16_t filter_setting() {
  uint32_t period = bus_clock_hz() / 10000000u;
  if (period < 1) period = 1;
  if (period > 255) period = 255;
  return enc::filter(2, static_cast<uint16_t>(period));
}

// The counter's 32-bit position: the last sample's while the sample clock runs (read until two
// reads agree, in case a trigger came between the halves), else now. Context: any, guarded.
uint32_t counter_position(uint8_t index) {
  if (!sample_clock_sampled()) {
    const uint32_t upper = enc::upos(index);  // latches LPOSH
    return (upper << 16) | enc::lposh(index);
  }
  uint32_t last = (uint32_t{enc::uposh(index)} << 16) | enc::lposh(index);
  for (int tries = 0; tries < 3; ++tries) {
    const uint32_t again = (uint32_t{enc::uposh(index)} << 16) | enc::lposh(index);
    if (again == last) break;
    last = again;
  }
  return last;
}

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status quadrature_begin(uint8_t index) {
  if (index >= 2) return Status::kNoSuchPin;
  namespace enc = teensy::enc;
  const teensy::EncoderWiring& wiring = teensy::kWiring[index];
  teensy::ccm::gate_on(teensy::ccm::kGateXbar1);
  teensy::ccm::gate_on(wiring.gate);
  teensy::attach_phase(wiring.a);
  teensy::attach_phase(wiring.b);
  CriticalSection guard;
  enc::ctrl(index) = 0;                                 // quadrature mode (x4: every edge counts), no interrupts
  enc::ctrl2(index) = enc::kCtrl2UpdateHoldsOnTrigger;  // free 32-bit counter, sampled on TRIGGER
  teensy::xbar1::connect(teensy::xbar1::in_pit_trigger(teensy::kSampleClockPitChannel), wiring.trigger_output);
  enc::umod(index) = 0;
  enc::lmod(index) = 0;
  enc::filt(index) = teensy::filter_setting();
  enc::uinit(index) = 0;
  enc::linit(index) = 0;
  enc::ctrl(index) = enc::kCtrlSoftwareInitPosition;
  teensy::offsets[index] = 0;
  teensy::begun[index] = true;
  return Status::kOk;
}

int32_t quadrature_read(uint8_t index) {
  if (index >= 2 || !teensy::begun[index]) return 0;
  CriticalSection guard;  // the UPOS read latches LPOSH: no other reader may come in between
  return static_cast<int32_t>(teensy::counter_position(index) + static_cast<uint32_t>(teensy::offsets[index]));
}

void quadrature_write(uint8_t index, int32_t count) {
  if (index >= 2 || !teensy::begun[index]) return;
  CriticalSection guard;
  teensy::offsets[index] = static_cast<int32_t>(static_cast<uint32_t>(count) - teensy::counter_position(index));
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
