// The simulator backend of the HAL facade: every hal:: function answered through the host table.
//
// Time comes from the simulator's clock (64-bit ns). cycles_now() is that clock at 600 MHz plus a
// cost model of the frame being run: kModelCyclesPerBlock for every block the engine has run in
// it so far. Simulated time does not move during a frame, so the model is what the engine's load
// figures (stepdance_get_cpu_usage, overruns) see: deterministic, and growing with the graph.
#if defined(STEPDANCE_PLATFORM_SIM)

#include "stepdance/platform/sim/sim_hal.hpp"

#include "stepdance/boards/board.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kPorts = 4;
constexpr uint8_t kEncoders = 2;

struct CaptureSink {
  hal::PulseSink sink = nullptr;
  void* context = nullptr;
};

hal::Isr frame_isr = nullptr;
hal::Isr khz_isr = nullptr;
CaptureSink capture_sinks[kPorts];
// Ports whose last handed-over frame had a high bit and may not have been played yet. An idle
// frame after a played (or idle) one changes nothing on the host, so it is not sent at all.
bool frame_pending[kPorts] = {};
bool irq_enabled = true;

const StepdanceHostV1& host() { return sim_runtime::host(); }
void* ctx() { return sim_runtime::host_context(); }
Status status(int code) { return static_cast<Status>(code); }

// The simulator models the Teensy the board is built around (its table's `teensy`).
const TeensyPinout& teensy() { return *active_board().teensy; }
bool has_adc(uint8_t pin) { return has_analog_input(teensy(), pin); }
bool has_gpio(uint8_t pin) { return has_pin(teensy(), pin); }

}  // namespace

namespace sim_runtime {

// Called by the simulator at each frame tick, in simulated time; one thread runs board and simulator,
// so the "ISR" is a plain call.
void run_frame_isr() {
  for (bool& pending : frame_pending) pending = false;  // the host has just played them
  if (frame_isr != nullptr) frame_isr();
}

void run_khz_isr() {
  if (khz_isr != nullptr) khz_isr();
}

void deliver_captured_pulse(uint8_t port, const StepdanceCapturedPulseV1& pulse) {
  if (port >= kPorts || capture_sinks[port].sink == nullptr) return;
  const protocol::CapturedPulse captured{pulse.rise_ticks, pulse.fall_ticks, pulse.dir_high != 0, pulse.extra_periods};
  capture_sinks[port].sink(capture_sinks[port].context, captured);
}

}  // namespace sim_runtime

namespace hal {

uint32_t micros_now() { return static_cast<uint32_t>(sim_runtime::now_ns() / 1000); }
// 600 MHz × simulated ns (×3/5 cycles per ns), plus a fixed cost per block already run this frame,
// so load and overrun figures are deterministic and grow with the sketch's block graph.
uint32_t cycles_now() {
  const uint64_t clock = static_cast<uint64_t>(sim_runtime::now_ns()) * 3 / 5;
  return static_cast<uint32_t>(clock + uint64_t{engine().blocks_run_in_frame()} * sim_runtime::kModelCyclesPerBlock);
}
uint32_t cycles_per_second() { return 600000000u; }

Status frame_timer_start(uint32_t period_us, Isr on_frame) {
  frame_isr = on_frame;
  return status(host().timer_start(ctx(), STEPDANCE_TIMER_FRAME, period_us));
}

Status khz_timer_start(uint32_t period_us, Isr on_tick) {
  khz_isr = on_tick;
  return status(host().timer_start(ctx(), STEPDANCE_TIMER_KHZ, period_us));
}

void timers_stop() {
  frame_isr = nullptr;
  khz_isr = nullptr;
  host().timers_stop(ctx());
}

// One thread runs everything, so "interrupts off" only has to be remembered, not enforced.
uint32_t irq_save() {
  const uint32_t previous = irq_enabled ? 1u : 0u;
  irq_enabled = false;
  return previous;
}
void irq_restore(uint32_t state) { irq_enabled = state != 0; }

Status port_out_begin(uint8_t port) {
  if (port >= active_board().output_port_count) return Status::kNoSuchPin;
  return status(host().port_out_begin(ctx(), port));
}

// Idle frames are sent only when the previous frame had pulses (the lines must be seen to go low once);
// after that, silence is implied. This keeps the host's work proportional to motion, not to time.
void port_out_frame(uint8_t port, const protocol::FrameWords& words) {
  if (port >= kPorts) return;
  const bool idle = (words.step_bits | words.dir_bits) == 0;
  if (idle && !frame_pending[port]) return;
  frame_pending[port] = !idle;
  host().port_out_frame(ctx(), port, words.step_bits, words.dir_bits);
}

// The simulator's wire model samples DIR at the edge the port asks for (spec "Frames": Stepdance
// inputs read DIR at the falling edge; step/dir inputs at the rising one).
Status port_in_begin(uint8_t port, protocol::DirSampleEdge edge, PulseSink sink, void* context) {
  if (port >= active_board().input_port_count || port >= kPorts) return Status::kNoSuchPin;
  capture_sinks[port] = {sink, context};
  const int dir_edge = edge == protocol::DirSampleEdge::kRising ? STEPDANCE_DIR_AT_RISING : STEPDANCE_DIR_AT_FALLING;
  return status(host().port_in_begin(ctx(), port, dir_edge));
}

// The Teensy 4.x capture timer at its usual 150 MHz bus clock, 16 bits wide, so the decoder's
// wrap and rounding are exercised as on the board.
protocol::CaptureClock port_in_clock(uint8_t) { return protocol::CaptureClock{150, 0xFFFFu}; }

Status quadrature_begin(uint8_t index) {
  if (index >= kEncoders) return Status::kNoSuchPin;
  return status(host().quadrature_begin(ctx(), index));
}
int32_t quadrature_read(uint8_t index) { return index < kEncoders ? host().quadrature_read(ctx(), index) : 0; }
void quadrature_write(uint8_t index, int32_t count) {
  if (index < kEncoders) host().quadrature_write(ctx(), index, count);
}

// Pins are checked against the modelled Teensy's pinout, so a sketch using a pin the real board lacks
// fails in the simulator too.
Status adc_begin(uint8_t pin) {
  if (!has_adc(pin)) return Status::kNoSuchPin;
  return status(host().adc_begin(ctx(), pin));
}
uint16_t adc_read(uint8_t pin) { return has_adc(pin) ? host().adc_read(ctx(), pin) : 0; }
uint32_t adc_sample_count(uint8_t pin) { return has_adc(pin) ? host().adc_sample_count(ctx(), pin) : 0; }

Status gpio_mode(uint8_t pin, PinMode mode) {
  if (!has_gpio(pin)) return Status::kNoSuchPin;
  return status(host().gpio_mode(ctx(), pin, static_cast<int>(mode)));
}
bool gpio_read(uint8_t pin) { return has_gpio(pin) && host().gpio_read(ctx(), pin) != 0; }
void gpio_write(uint8_t pin, bool high) {
  if (has_gpio(pin)) host().gpio_write(ctx(), pin, high ? 1 : 0);
}

// A fatal fault stops the board's timers, as the firmware's safe state does, and tells the simulator,
// which records it.
void enter_safe_state() {
  timers_stop();
  host().enter_safe_state(ctx());
}
void log_fault(const char* reason, const char* detail) { host().log_fault(ctx(), reason, detail); }
void log_message(const char* text) {
  const char* end = text;
  while (*end != '\0') ++end;
  host().console_write(ctx(), reinterpret_cast<const uint8_t*>(text), static_cast<size_t>(end - text));
  host().console_write(ctx(), reinterpret_cast<const uint8_t*>("\r\n"), 2);
}

}  // namespace hal
}  // namespace stepdance

#endif  // STEPDANCE_PLATFORM_SIM
