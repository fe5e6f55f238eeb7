// InputPort: capture-ISR pulse counting and the per-frame hand-off to the axis BlockPorts.
#include "stepdance/io/input_port.hpp"

#include "stepdance/boards/board.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

// The port each capture ISR delivers to. The HAL context is the port index, not the object,
// so a destroyed InputPort simply stops receiving instead of leaving a dangling pointer behind.
InputPort* receivers[NUM_AVAILABLE_INPUT_PORTS] = {};

void pulse_trampoline(void* context, const protocol::CapturedPulse& pulse) {
  const uintptr_t port = reinterpret_cast<uintptr_t>(context);
  if (port >= NUM_AVAILABLE_INPUT_PORTS) return;
  InputPort* receiver = receivers[port];
  if (receiver != nullptr) receiver->receive_pulse(pulse);
}

uint8_t bit(uint8_t signal) { return static_cast<uint8_t>(1u << signal); }

// Difference of two free-running counters, correct across the int32 wrap.
int32_t counter_difference(int32_t now, int32_t before) {
  return static_cast<int32_t>(static_cast<uint32_t>(now) - static_cast<uint32_t>(before));
}

}  // namespace

InputPort::InputPort() : outputs_{&output_x, &output_y, &output_r, &output_t, &output_z, &output_e} {}

// Called on destruction: unhooks this port from the capture ISR's table. Only clears the slot if it
// is still ours, since a later InputPort may have claimed the same hardware port.
void InputPort::detach() {
  if (port_ < NUM_AVAILABLE_INPUT_PORTS && receivers[port_] == this) {
    hal::CriticalSection guard;
    receivers[port_] = nullptr;
  }
}

// counts_seen_ starts at the ISR's current counts so pulses received before begin() (or by a
// previous owner) are not handed off as a jump. Hand-off runs in the kInputPorts frame stage.
Status InputPort::begin(uint8_t port) {
  if (port >= active_board().input_port_count || port >= NUM_AVAILABLE_INPUT_PORTS) {
    hal::log_message("InputPort::begin: this board has no such input port");
    return Status::kNoSuchPin;
  }
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    outputs_[signal]->begin(&positions_pulses_[signal], BLOCKPORT_UNDEFINED, this);
  }
  enable_all_signals();
  {
    hal::CriticalSection guard;
    port_ = port;
    receivers[port] = this;
    for (uint8_t signal = 0; signal < kNumSignals; ++signal) counts_seen_[signal] = counts_[signal];
  }
  const Status armed = arm_capture();
  if (armed != Status::kOk) return armed;
  return register_in(Stage::kInputPorts);
}

// Stepdance streams are read at the STEP falling edge, step/dir drivers' convention at the rising
// edge (spec "Stepdance Ports": modules sample DIR at the fall so one interrupt per pulse suffices).
Status InputPort::arm_capture() {
  const protocol::DirSampleEdge edge = protocol::dir_sample_edge(mode_);
  return hal::port_in_begin(port_, edge, &pulse_trampoline, reinterpret_cast<void*>(uintptr_t{port_}));
}

// INPUT_MODE_STEP_DIR accepts any pulse as one step of step_dir_signal (for a plain step/dir
// source); INPUT_MODE_STEPDANCE decodes the signal from the pulse width (spec table X 2 µs … E 7 µs).
Status InputPort::set_input_mode(InputMode mode, uint8_t step_dir_signal) {
  if (step_dir_signal >= kNumSignals) return Status::kBadArgument;
  if (mode != INPUT_MODE_STEPDANCE && mode != INPUT_MODE_STEP_DIR) return Status::kBadArgument;
  {
    hal::CriticalSection guard;
    mode_ = mode;
    step_dir_signal_ = step_dir_signal;
  }
  if (port_ >= NUM_AVAILABLE_INPUT_PORTS) return Status::kOk;  // begin() arms it later
  return arm_capture();
}

void InputPort::enable_signal(uint8_t signal) {
  if (signal >= kNumSignals) return;
  hal::CriticalSection guard;
  enabled_mask_ = static_cast<uint8_t>(enabled_mask_ | bit(signal));
}

void InputPort::disable_signal(uint8_t signal) {
  if (signal >= kNumSignals) return;
  hal::CriticalSection guard;
  enabled_mask_ = static_cast<uint8_t>(enabled_mask_ & ~bit(signal));
}

bool InputPort::signal_enabled(uint8_t signal) const {
  return signal < kNumSignals && (enabled_mask_ & bit(signal)) != 0;
}

void InputPort::set_ratio(double world_units, double pulses) {
  for (BlockPort* port : outputs_) port->set_ratio(world_units, pulses);
}

// Counters for diagnosis of a cable or a sender: accepted pulses per signal and direction, and
// pulses rejected by width (too short: noise; too long: a stretched or foreign pulse).
void InputPort::report_counters(CounterSink& sink) const {
  static const char* const kReceived[kNumSignals][2] = {
      {"received_x_forward", "received_x_reverse"}, {"received_y_forward", "received_y_reverse"},
      {"received_r_forward", "received_r_reverse"}, {"received_t_forward", "received_t_reverse"},
      {"received_z_forward", "received_z_reverse"}, {"received_e_forward", "received_e_reverse"},
  };
  sink.counter("port", port_);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    sink.counter(kReceived[signal][0], pulses_received(signal, DIRECTION_FORWARD));
    sink.counter(kReceived[signal][1], pulses_received(signal, DIRECTION_REVERSE));
  }
  sink.counter("rejected_too_short", rejected_too_short_);
  sink.counter("rejected_too_long", rejected_too_long_);
  sink.counter("ignored", ignored_);
}

uint32_t InputPort::pulses_received(uint8_t signal, uint8_t direction) const {
  if (signal >= kNumSignals) return 0;
  return received_[signal][direction == DIRECTION_FORWARD ? 1 : 0];
}

BlockPort& InputPort::output(uint8_t signal) { return *outputs_[signal < kNumSignals ? signal : 0]; }

// Capture-ISR context: one call per STEP pulse. Only counters change here; the frame picks the
// counts up in hand_off_pulses(). Disabled signals are counted as ignored, not as motion.
void InputPort::receive_pulse(const protocol::CapturedPulse& pulse) {
  const protocol::DecodedPulse decoded =
      protocol::decode_pulse(pulse, hal::port_in_clock(port_), mode_, step_dir_signal_);
  switch (decoded.verdict) {
    case protocol::PulseVerdict::kTooShort: rejected_too_short_ = rejected_too_short_ + 1; return;
    case protocol::PulseVerdict::kTooLong: rejected_too_long_ = rejected_too_long_ + 1; return;
    case protocol::PulseVerdict::kAccepted: break;
  }
  const uint8_t signal = decoded.signal;
  if (!(enabled_mask_ & bit(signal))) {
    ignored_ = ignored_ + 1;
    return;
  }
  counts_[signal] = counts_[signal] + decoded.direction;
  const uint8_t slot = decoded.direction > 0 ? 1 : 0;
  received_[signal][slot] = received_[signal][slot] + 1;
}

// Frame context. The ISR only ever adds to counts_[], so the frame takes the difference from the
// last snapshot instead of resetting it: no read-modify-write race with the ISR and no lost pulse.
// Each axis port gets the frame's pulses as an incremental move, pushed downstream at once.
void InputPort::hand_off_pulses() {
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    const int32_t snapshot = counts_[signal];  // the one read of an ISR-owned counter
    const int32_t delta = counter_difference(snapshot, counts_seen_[signal]);
    counts_seen_[signal] = snapshot;
    outputs_[signal]->set(delta, INCREMENTAL);
    outputs_[signal]->push();
  }
}

}  // namespace stepdance
