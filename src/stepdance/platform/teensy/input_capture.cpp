// Input ports A–D: STEP pulses timed by eFlexPWM input capture (RM chapter 55), DIR read from a
// fast GPIO at the edge the input mode asks for.
//
// Each port owns one PWM submodule whose 16-bit counter runs free at the IPG clock (INIT 0,
// VAL1 0xFFFF: it wraps every 65536 ticks, 437 µs at 150 MHz). Capture circuit 0 latches the
// counter on the STEP rising edge, circuit 1 on the falling edge; in free-running mode they
// alternate, so every pulse yields (rise, fall).
//
// Long pulses: a wrapped 16-bit difference alone would read a 439 µs pulse as 2 µs (an X step).
// So the reload interrupt counts counter wraps, and every capture is placed on the extended time
// line (wraps × 2^16 + counter) when its interrupt runs: both capture edges interrupt, so a
// capture is always less than one counter period old when it is read. The decoder gets the
// wrapped values plus the whole periods in between (CapturedPulse::extra_periods).
//
// DIR sampling: the capture ISR runs at the highest priority we use and reads DIR as its first
// action. In falling-edge mode (STEPDANCE) DIR is the level read just after the falling edge
// (Stepdance senders hold DIR 1 µs past it); in rising-edge mode (STEP_DIR) it is the level read
// at the rising edge, kept for the pulse.
#if defined(__IMXRT1062__)

#include "stepdance/boards/board.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/clocks.hpp"
#include "stepdance/platform/teensy/irq.hpp"
#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_flexpwm.hpp"
#include "stepdance/platform/teensy/regs_nvic.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace pwm = regs::flexpwm;
namespace iomuxc = regs::iomuxc;
namespace nvic = regs::nvic;

/// Wiring of one input port (reference §4.4): PWM submodule and channel, pad ALT, input select.
struct CaptureWiring {
  uint32_t pwm_base;
  uint8_t submodule;
  bool channel_b;
  uint8_t step_pin;
  uint8_t dir_pin;
  uint8_t alt;
  uint16_t select_input;
  uint8_t select_value;
  uint8_t irq;
};

// STEP and DIR pins come from the board table (boards/board.hpp); the rest depends on the STEP
// pad, checked below so a changed board pin cannot silently keep the wrong ALT or select.
constexpr CaptureWiring kWiring[4] = {
    // A: pin 4 = EMC_06 → PWM2 SM0 A (ALT1), DIR pin 6
    {pwm::kPwm2Base, 0, false, kDriverModuleV1.input_ports[0].step, kDriverModuleV1.input_ports[0].dir, 1,
     iomuxc::kSelectFlexpwm2PwmA0, 0, nvic::kIrqFlexpwm2Sm0},
    // B: pin 5 = EMC_08 → PWM2 SM1 A (ALT1), DIR pin 7
    {pwm::kPwm2Base, 1, false, kDriverModuleV1.input_ports[1].step, kDriverModuleV1.input_ports[1].dir, 1,
     iomuxc::kSelectFlexpwm2PwmA1, 0, nvic::kIrqFlexpwm2Sm1},
    // C: pin 8 = B1_00 → PWM1 SM3 A (ALT6), DIR pin 10
    {pwm::kPwm1Base, 3, false, kDriverModuleV1.input_ports[2].step, kDriverModuleV1.input_ports[2].dir, 6,
     iomuxc::kSelectFlexpwm1PwmA3, 4, nvic::kIrqFlexpwm1Sm3},
    // D: pin 9 = B0_11 → PWM2 SM2 B (ALT2), DIR pin 11
    {pwm::kPwm2Base, 2, true, kDriverModuleV1.input_ports[3].step, kDriverModuleV1.input_ports[3].dir, 2,
     iomuxc::kSelectFlexpwm2PwmB2, 1, nvic::kIrqFlexpwm2Sm2},
};
static_assert(pin_pad(kWiring[0].step_pin).mux == pad::emc(6).mux, "input A STEP must be pad EMC_06 (ALT1)");
static_assert(pin_pad(kWiring[1].step_pin).mux == pad::emc(8).mux, "input B STEP must be pad EMC_08 (ALT1)");
static_assert(pin_pad(kWiring[2].step_pin).mux == pad::b1(0).mux, "input C STEP must be pad B1_00 (ALT6)");
static_assert(pin_pad(kWiring[3].step_pin).mux == pad::b0(11).mux, "input D STEP must be pad B0_11 (ALT2)");
// Every registered board wires its input port n as port n here.
constexpr bool boards_match_wiring() {
  for (const BoardDefinition* board : kBoards) {
    for (uint8_t port = 0; port < board->input_port_count; ++port) {
      const InputPortPins& pins = board->input_ports[port];
      if (pins.step != kWiring[port].step_pin || pins.dir != kWiring[port].dir_pin) return false;
    }
  }
  return true;
}
static_assert(boards_match_wiring(), "a board's input port n is not wired as port n of this backend");

struct CaptureState {
  hal::PulseSink sink = nullptr;
  void* context = nullptr;
  bool dir_at_rise = false;  // STEP_DIR mode: DIR is the level read at the rising edge
  bool have_rise = false;
  bool rise_dir_high = false;
  uint64_t rise_ticks = 0;  // on the extended time line
  uint64_t wraps = 0;       // counter wraps seen by the reload interrupt
};

CaptureState states[4];
protocol::CaptureClock capture_clock{};
volatile bool capture_clock_known = false;

// The counters tick at the IPG clock: derive ticks per µs from the real bus frequency.
void refresh_capture_clock() {
  capture_clock.ticks_per_us = (bus_clock_hz() + 500000u) / 1000000u;
  capture_clock.counter_mask = 0xFFFFu;
  capture_clock_known = true;
}

// Flags, capture registers and interrupt enables of a port's channel.
uint16_t flag_rise(const CaptureWiring& w) { return w.channel_b ? pwm::kCaptureB0 : pwm::kCaptureA0; }
uint16_t flag_fall(const CaptureWiring& w) { return w.channel_b ? pwm::kCaptureB1 : pwm::kCaptureA1; }
regs::Reg16 sm(const CaptureWiring& w, uint32_t offset) { return pwm::sm_reg(w.pwm_base, w.submodule, offset); }

// Now on the extended time line: counts a pending wrap first, and one that lands between reading
// the flags and the counter (the counter then reads small).
uint64_t extended_now(const CaptureWiring& w, CaptureState& s, uint16_t status) {
  if (status & pwm::kReload) {
    sm(w, pwm::kSmSts) = pwm::kReload;
    ++s.wraps;
  }
  const uint16_t counter = sm(w, pwm::kSmCnt);
  if ((sm(w, pwm::kSmSts) & pwm::kReload) && counter < 0x8000u) {
    sm(w, pwm::kSmSts) = pwm::kReload;
    ++s.wraps;
  }
  return (s.wraps << 16) | counter;
}

// A capture latched less than one counter period before `now`, on the extended time line.
uint64_t extended_capture(uint64_t now, uint16_t captured) {
  return now - ((static_cast<uint16_t>(now) - captured) & 0xFFFFu);
}

void service(uint8_t port) {
  const CaptureWiring& w = kWiring[port];
  CaptureState& s = states[port];
  const bool dir_high = pin_level(*pin_info(w.dir_pin));  // first, as close to the edge as we can
  const uint16_t status = sm(w, pwm::kSmSts);
  const uint64_t now = extended_now(w, s, status);
  if (status & flag_rise(w)) {
    s.rise_ticks = extended_capture(now, sm(w, w.channel_b ? pwm::kSmCval4 : pwm::kSmCval2));
    s.rise_dir_high = dir_high;
    s.have_rise = true;
    sm(w, pwm::kSmSts) = flag_rise(w);
  }
  if (status & flag_fall(w)) {
    const uint64_t fall_ticks = extended_capture(now, sm(w, w.channel_b ? pwm::kSmCval5 : pwm::kSmCval3));
    sm(w, pwm::kSmSts) = flag_fall(w);
    if (s.have_rise && s.sink != nullptr) {
      const bool pulse_dir = s.dir_at_rise ? s.rise_dir_high : dir_high;
      s.sink(s.context, protocol::captured_from_ticks(s.rise_ticks, fall_ticks, pulse_dir, capture_clock));
    }
    s.have_rise = false;
  }
  regs::data_sync_barrier();  // flag clears land before the exception returns
}

void capture_isr_a() { service(0); }
void capture_isr_b() { service(1); }
void capture_isr_c() { service(2); }
void capture_isr_d() { service(3); }
constexpr void (*kIsrs[4])() = {capture_isr_a, capture_isr_b, capture_isr_c, capture_isr_d};

/// A Teensy pin whose pad can carry another channel of an input port's PWM submodule: Teensyduino's
/// analogWrite() on it puts the pad in `pwm_alt` and reprograms the whole submodule (its counter
/// period, VAL registers and RUN bit), which breaks the capture. Facts from the Teensy 4.x PWM pin
/// list (FlexPWM2_0: pins 4, 33; FlexPWM2_1: pin 5; FlexPWM1_3: pins 7, 8, 25; FlexPWM2_2: 6, 9).
struct SharedPwmPin {
  uint8_t port;
  uint8_t pin;
  uint8_t pwm_alt;
};
constexpr SharedPwmPin kSharedPwmPins[] = {{0, 33, 1}, {2, 7, 6}, {2, 25, 4}, {3, 6, 2}};
/// The fault detail per input port (static strings: log_fault keeps the pointer).
constexpr const char* kSharedPwmMessages[4] = {
    "input port A: analogWrite on pin 33 uses its FlexPWM2 submodule 0",
    "input port B: no shared PWM pin",
    "input port C: analogWrite on pin 7 or 25 uses its FlexPWM1 submodule 3",
    "input port D: analogWrite on pin 6 uses its FlexPWM2 submodule 2",
};

// True if a pin sharing `port`'s submodule has its pad in its PWM function (analogWrite ran on it).
bool pwm_pin_in_use(uint8_t port) {
  for (const SharedPwmPin& shared : kSharedPwmPins) {
    if (shared.port != port) continue;
    const uint32_t mux = iomuxc::pad_mux(pin_info(shared.pin)->mux);
    if ((mux & iomuxc::kMuxModeMask) == shared.pwm_alt) return true;
  }
  return false;
}

// Pads: STEP to the PWM input (ALT + input select), DIR to a fast-GPIO input. SION: the RM
// (§11.7, SW_MUX_CTL_PAD SION) asks for the input path to be forced on when a pad mux carries an
// input to a peripheral through the daisy chain (the IOMUXC_*_SELECT_INPUT registers).
void attach_pins(const CaptureWiring& w) {
  const PinInfo& step = *pin_info(w.step_pin);
  pad_configure(step, kPadInput);
  iomuxc::select_input(w.select_input) = w.select_value;
  pad_select(step, w.alt | iomuxc::kMuxSion);
  const PinInfo& dir = *pin_info(w.dir_pin);
  pad_configure(dir, kPadInput);
  pin_make_gpio(dir, false);
}

// A free-running 16-bit counter on the IPG clock with both capture circuits armed (RM §55.8);
// both capture edges and the reload (counter wrap) interrupt.
void start_capture(const CaptureWiring& w) {
  const unsigned n = w.submodule;
  regs::Reg16 mctrl = pwm::mctrl(w.pwm_base);
  mctrl = static_cast<uint16_t>(mctrl & ~pwm::mctrl_run(n));
  sm(w, pwm::kSmInten) = 0;
  sm(w, pwm::kSmCaptctrlA) = 0;
  sm(w, pwm::kSmCaptctrlB) = 0;
  mctrl = static_cast<uint16_t>(mctrl | pwm::mctrl_clear_load_ok(n));
  sm(w, pwm::kSmCtrl2) = pwm::kCtrl2Independent;
  sm(w, pwm::kSmCtrl) = pwm::kCtrlFullReload;
  sm(w, pwm::kSmInit) = 0;
  sm(w, pwm::kSmVal0) = 0;
  sm(w, pwm::kSmVal1) = 0xFFFF;
  for (uint32_t val = 0; val < 4; ++val) sm(w, pwm::kSmVal2 + 4u * val) = 0;
  sm(w, pwm::kSmOctrl) = 0;
  regs::Reg16 outen = pwm::outen(w.pwm_base);
  outen = static_cast<uint16_t>(outen & ~(w.channel_b ? pwm::outen_b(n) : pwm::outen_a(n)));
  mctrl = static_cast<uint16_t>(mctrl | pwm::mctrl_load_ok(n));
  sm(w, pwm::kSmSts) = 0xFFFF;
  sm(w, w.channel_b ? pwm::kSmCaptctrlB : pwm::kSmCaptctrlA) =
      pwm::kCaptEdge0Rising | pwm::kCaptEdge1Falling | pwm::kCaptArm;
  mctrl = static_cast<uint16_t>(mctrl | pwm::mctrl_run(n));
  sm(w, pwm::kSmInten) = static_cast<uint16_t>(flag_fall(w) | flag_rise(w) | pwm::kReload);
}

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status port_in_begin(uint8_t port, protocol::DirSampleEdge edge, PulseSink sink, void* context) {
  if (port >= 4) return Status::kNoSuchPin;
  if (sink == nullptr) return Status::kBadArgument;
  if (teensy::pwm_pin_in_use(port)) {  // refused before touching the submodule
    report_fault(FaultLevel::kWarning, FaultReason::kBadConfiguration, "port_in_begin",
                 teensy::kSharedPwmMessages[port]);
    return Status::kBusy;
  }
  const teensy::CaptureWiring& wiring = teensy::kWiring[port];
  teensy::irq::disable(wiring.irq);  // no capture ISR while the port is rebuilt
  namespace ccm = teensy::regs::ccm;
  ccm::gate_on(wiring.pwm_base == teensy::pwm::kPwm1Base ? ccm::kGatePwm1 : ccm::kGatePwm2);
  teensy::refresh_capture_clock();
  teensy::attach_pins(wiring);
  teensy::CaptureState& state = teensy::states[port];
  state = teensy::CaptureState{};
  state.sink = sink;
  state.context = context;
  state.dir_at_rise = edge == protocol::DirSampleEdge::kRising;
  teensy::start_capture(wiring);
  teensy::irq::install(wiring.irq, teensy::kIsrs[port], teensy::irq::kCapturePriority);
  return Status::kOk;
}

protocol::CaptureClock port_in_clock(uint8_t) {
  // Computed once (and again by every port_in_begin): the decoder asks for it on every pulse.
  if (!teensy::capture_clock_known) teensy::refresh_capture_clock();
  return teensy::capture_clock;
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
