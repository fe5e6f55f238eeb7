// OutputPort: pending pulses, frame encoding, statistics, driver enable and current read-back.
#include "stepdance/io/output_port.hpp"

#include <stdint.h>

#include "stepdance/boards/board.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/fixed_list.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

constexpr const char* kPortNames[NUM_AVAILABLE_OUTPUT_PORTS] = {"OUTPUT A", "OUTPUT B", "OUTPUT C", "OUTPUT D"};
constexpr float kAdcFullScaleVolts = 3.3f;
constexpr float kAdcFullScaleCounts = 1023.0f;

FixedList<OutputPort*, NUM_AVAILABLE_OUTPUT_PORTS>& begun_ports() {
  static FixedList<OutputPort*, NUM_AVAILABLE_OUTPUT_PORTS> ports;
  return ports;
}

uint8_t bit(uint8_t signal) { return static_cast<uint8_t>(1u << signal); }

}  // namespace

void OutputPort::forget(OutputPort* port) { begun_ports().remove(port); }

// Two OutputPort objects on one hardware port would both transmit each frame; the newest begin()
// wins and the previous owner is removed from the engine and marked unbegun (port_ 255).
void OutputPort::release_previous_owner(uint8_t port) {
  OutputPort* previous = nullptr;
  for (OutputPort* other : begun_ports()) {
    if (other != this && other->port_ == port) previous = other;
  }
  if (previous == nullptr) return;
  begun_ports().remove(previous);
  engine().remove(previous);
  previous->port_ = 255;
}

Status OutputPort::begin(uint8_t port) { return claim(port, kFormatForPeriod, OUTPUT_TRANSMIT_ON_FRAME); }

// A fixed format must end before the frame period does (frame_format.hpp); it is checked against
// the current period now and again whenever the period changes (accept_frame_period).
Status OutputPort::begin(uint8_t port, uint8_t format, uint8_t transmit_mode) {
  if (format >= kNumOutputFrameFormats) {
    fault(FaultReason::kBadConfiguration, "OutputPort::begin: unknown format (OUTPUT_FRAME_32US/16US/8US/4US)");
    return Status::kBadArgument;
  }
  if (transmit_mode != OUTPUT_TRANSMIT_ON_FRAME && transmit_mode != OUTPUT_TRANSMIT_MANUAL) {
    fault(FaultReason::kBadConfiguration, "OutputPort::begin: unknown transmit mode");
    return Status::kBadArgument;
  }
  requested_format_ = format;
  if (!accept_frame_period(frame_period_us())) return Status::kBadArgument;
  return claim(port, format, transmit_mode);
}

// Engine hook, called when the frame period changes. Without a requested format the layout grows
// or shrinks with the period; a fixed format that no longer fits is a configuration fault, since
// pulses would run into the next frame and a receiver would misread their widths.
bool OutputPort::accept_frame_period(uint32_t period_us) {
  if (requested_format_ == kFormatForPeriod) {
    layout_ = protocol::layout_for_period(period_us);
    return true;
  }
  if (protocol::format_fits_period(requested_format_, period_us)) {
    layout_ = protocol::frame_layout(requested_format_);
    return true;
  }
  fault(FaultReason::kBadConfiguration,
        "OutputPort: the transmission format does not end before the frame period does (32US needs "
        "> 32 us, 16US > 16 us, 8US > 8 us, 4US > 4 us)");
  return false;
}

// Lets a caller check a wiring before committing it: a step/dir port carries its one signal; a
// Stepdance port carries a signal if its pulse and slot fit the layout at that period at all.
bool OutputPort::can_carry(uint8_t signal, uint32_t period_us) const {
  if (mode_ == OUTPUT_MODE_STEP_DIR) return signal == step_dir_signal_;
  const protocol::FrameLayout layout = requested_format_ == kFormatForPeriod
                                           ? protocol::layout_for_period(period_us)
                                           : protocol::frame_layout(requested_format_);
  return protocol::signal_fits(layout, signal);
}

Status OutputPort::set_output_mode(OutputMode mode, uint8_t step_dir_signal) {
  if ((mode != OUTPUT_MODE_STEPDANCE && mode != OUTPUT_MODE_STEP_DIR) || step_dir_signal >= kNumSignals) {
    return Status::kBadArgument;
  }
  hal::CriticalSection guard;
  step_dir_signal_ = step_dir_signal;
  mode_ = mode;
  return Status::kOk;
}

// OUTPUT_TRANSMIT_MANUAL ports are claimed but not registered: the sketch calls transmit_frame()
// itself (e.g. from its own timer), so the engine must not transmit them too.
Status OutputPort::claim(uint8_t port, uint8_t format, uint8_t transmit_mode) {
  requested_format_ = format;
  if (format == kFormatForPeriod) accept_frame_period(frame_period_us());
  if (port >= active_board().output_port_count) {
    hal::log_message("OutputPort::begin: this board has no such output port");
    return Status::kNoSuchPin;
  }
  const Status claimed = hal::port_out_begin(port);
  if (claimed != Status::kOk) return claimed;
  port_ = port;
  port_name = kPortNames[port];
  clear_statistics();
  release_previous_owner(port);
  if (!begun_ports().contains(this) && begun_ports().push_back(this) != Status::kOk) return Status::kFull;
  transmit_mode_ = transmit_mode;
  if (transmit_mode == OUTPUT_TRANSMIT_MANUAL) {
    engine().remove(this);  // begun again in manual mode: the engine no longer sends it
    return Status::kOk;
  }
  return register_in(Stage::kOutputPorts);
}

// Pulses are accumulated as a signed count per signal: a forward and a reverse in the same frame
// cancel instead of sending two opposite pulses. Frame or critical-section context.
void OutputPort::add_signal(uint8_t signal, uint8_t direction) {
  if (signal >= kNumSignals) return;
  const bool carried =
      mode_ == OUTPUT_MODE_STEP_DIR ? signal == step_dir_signal_ : protocol::signal_fits(layout_, signal);
  if (!carried) {
    refuse_pulse();
    return;
  }
  set_pending(signal, pending_[signal] + (direction == DIRECTION_FORWARD ? 1 : -1));
}

// Warns once per port (the counter keeps counting) so a miswired signal does not flood the log
// at 25 kHz.
void OutputPort::refuse_pulse() {
  if (pulses_refused_++ != 0) return;
  report_fault(FaultLevel::kWarning, FaultReason::kBadConfiguration, "OutputPort",
               "pulse refused: a STEP_DIR port sends one signal, and a short frame has no room for the wide ones");
}

// Keeps the two masks the encoder wants (which signals have pulses, which of them go forward) in
// step with the counts, so encoding a frame needs no loop over all six signals.
void OutputPort::set_pending(uint8_t signal, int32_t count) {
  pending_[signal] = count;
  const uint8_t mask = bit(signal);
  pending_mask_ = count != 0 ? (pending_mask_ | mask) : (pending_mask_ & ~mask);
  forward_mask_ = count > 0 ? (forward_mask_ | mask) : (forward_mask_ & ~mask);
}

void OutputPort::step_now(uint8_t direction, uint8_t signal) {
  hal::CriticalSection guard;
  add_signal(signal, direction);
}

// The sketch's call. While the engine runs, the engine's output stage owns an ON_FRAME port's
// frame (it comes after the channels, so their pulses leave in the frame that made them).
void OutputPort::transmit_frame() {
  if (transmit_mode_ == OUTPUT_TRANSMIT_ON_FRAME && engine().running()) {
    refuse_transmit();
    return;
  }
  transmit_once_this_frame();
}

void OutputPort::refuse_transmit() {
  if (transmits_refused_++ != 0) return;
  report_fault(
      FaultLevel::kWarning, FaultReason::kBadConfiguration, "OutputPort",
      "transmit_frame() ignored: the port already sends once every frame (OUTPUT_TRANSMIT_ON_FRAME, or called twice)");
}

// Frame context, at most once per engine frame (the frame count changes only between frames);
// with the engine stopped every call sends. Encodes at most one frame's worth of pulses; the rest
// stays pending for the next frames.
void OutputPort::transmit_once_this_frame() {
  if (engine().running()) {
    const uint32_t frame = engine().frame_count();
    if (transmitted_ && transmitted_in_frame_ == frame) {
      refuse_transmit();
      return;
    }
    transmitted_ = true;
    transmitted_in_frame_ = frame;
  }
  if (idle_timeout_ms_ != 0) idle_check(pending_mask_ != 0);
  const protocol::FrameWords words = mode_ == OUTPUT_MODE_STEP_DIR ? encode_step_dir() : encode_stepdance();
  if (port_ < NUM_AVAILABLE_OUTPUT_PORTS) hal::port_out_frame(port_, words);
}

// Spec "Frames": each signal occurs at most once per frame. When the pending signals do not all
// fit, those left over last frame (carried_mask_) go first, so no signal is starved while others
// keep it busy; a signal with several pending pulses is sent one per frame.
protocol::FrameWords OutputPort::encode_stepdance() {
  protocol::FrameRequest request;
  request.active_mask = pending_mask_;
  if (request.active_mask == 0) return {};
  request.forward_mask = forward_mask_;
  request.priority_mask = carried_mask_ & request.active_mask;
  const protocol::EncodedFrame frame = protocol::encode_frame(request, layout_);
  account_sent(frame.sent_mask);
  carried_mask_ = frame.carried_mask;
  for (uint8_t carried = frame.carried_mask; carried != 0; carried &= carried - 1) ++signals_carried_;
  return frame.words;
}

// Step/dir mode sends as many equal (X-width) pulses of the one signal as fit the frame window,
// one direction per frame; a remainder is counted as carried and waits for the next frame.
protocol::FrameWords OutputPort::encode_step_dir() {
  const uint8_t signal = step_dir_signal_;
  const int32_t pending = pending_[signal];
  if (pending == 0) return {};
  const bool forward = pending > 0;
  const uint32_t count = forward ? static_cast<uint32_t>(pending) : static_cast<uint32_t>(-pending);
  const protocol::StepDirFrame frame = protocol::encode_step_dir_frame(count, forward, layout_);
  set_pending(signal, forward ? pending - frame.sent : pending + frame.sent);
  sent_[signal][forward ? DIRECTION_FORWARD : DIRECTION_REVERSE] += frame.sent;
  if (count > frame.sent) ++signals_carried_;
  return frame.words;
}

void OutputPort::report_counters(CounterSink& sink) const {
  static const char* const kSent[kNumSignals][2] = {
      {"sent_x_forward", "sent_x_reverse"}, {"sent_y_forward", "sent_y_reverse"}, {"sent_r_forward", "sent_r_reverse"},
      {"sent_t_forward", "sent_t_reverse"}, {"sent_z_forward", "sent_z_reverse"}, {"sent_e_forward", "sent_e_reverse"},
  };
  sink.counter("port", port_);
  sink.counter("carried", signals_carried_);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    sink.counter(kSent[signal][0], pulses_sent(signal, DIRECTION_FORWARD));
    sink.counter(kSent[signal][1], pulses_sent(signal, DIRECTION_REVERSE));
  }
}

void OutputPort::clear_statistics() {
  hal::CriticalSection guard;
  carried_mask_ = 0;
  signals_carried_ = 0;
  pulses_refused_ = 0;
  transmits_refused_ = 0;
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    set_pending(signal, 0);
    sent_[signal][0] = sent_[signal][1] = 0;
  }
}

// One pulse per sent signal moves its pending count one step toward zero, in the pulse's
// direction, and is counted as sent.
void OutputPort::account_sent(uint8_t sent_mask) {
  for (uint8_t rest = sent_mask; rest != 0; rest &= static_cast<uint8_t>(rest - 1)) {
    const uint8_t signal = lowest_signal(rest);
    const bool forward = pending_[signal] > 0;
    set_pending(signal, pending_[signal] + (forward ? -1 : 1));
    ++sent_[signal][forward ? DIRECTION_FORWARD : DIRECTION_REVERSE];
  }
}

const OutputPortPins* OutputPort::pins() const {
  const BoardDefinition& board = active_board();
  if (port_ >= board.output_port_count) return nullptr;
  return &board.output_ports[port_];
}

// The driver ENABLE pin is active low (the Driver Module's stepper drivers), hence writing false
// to enable. Re-enabling also clears the idle timer so the idle timeout starts over.
Status OutputPort::enable_driver() {
  const OutputPortPins* p = pins();
  if (p == nullptr || p->enable == kNoPin) {
    hal::log_message("enable_driver: this board has no stepper driver on that port");
    return Status::kNoSuchPin;
  }
  const Status mode = hal::gpio_mode(p->enable, hal::PinMode::kOutput);
  if (mode != Status::kOk) return mode;
  idle_us_ = 0;
  idle_disabled_ = false;
  driver_enabled_ = true;
  hal::gpio_write(p->enable, false);
  return Status::kOk;
}

Status OutputPort::disable_driver() {
  const OutputPortPins* p = pins();
  if (p == nullptr || p->enable == kNoPin) return Status::kNoSuchPin;
  driver_enabled_ = false;
  idle_disabled_ = false;
  // Level first, then direction: a pin that was still an input starts driving high, no glitch.
  hal::gpio_write(p->enable, true);
  return hal::gpio_mode(p->enable, hal::PinMode::kOutput);
}

void OutputPort::set_driver_idle_timeout_ms(uint32_t ms) {
  idle_timeout_ms_ = ms;
  if (ms == 0 && idle_disabled_) write_enable_pin(true);  // turned off while idle: back on
}

// Frame context: counts quiet frames; disables the driver at the timeout, enables it on motion.
void OutputPort::idle_check(bool moving) {
  if (!driver_enabled_) return;
  if (moving) {
    idle_us_ = 0;
    if (idle_disabled_) write_enable_pin(true);
    return;
  }
  if (idle_disabled_) return;
  idle_us_ += frame_period_us();
  if (idle_us_ < uint64_t{idle_timeout_ms_} * 1000u) return;
  write_enable_pin(false);
}

void OutputPort::write_enable_pin(bool enabled) {
  const OutputPortPins* p = pins();
  if (p == nullptr || p->enable == kNoPin) return;
  idle_disabled_ = !enabled;
  hal::gpio_write(p->enable, !enabled);  // ENABLE is active low
}

float OutputPort::read_drive_current_amps() { return read_drive_current_amps(current_gain_a_per_v_); }

// The driver's VREF is read on the 10-bit ADC (0…1023 over 0…3.3 V); the current per volt depends
// on the driver and its sense resistor, hence the gain parameter. −1 means the board has no VREF
// pin here or the ADC could not start.
float OutputPort::read_drive_current_amps(float amps_per_volt) {
  const OutputPortPins* p = pins();
  if (p == nullptr || p->vref == kNoPin) return -1.0f;
  if (!vref_started_) {
    if (hal::adc_begin(p->vref) != Status::kOk) return -1.0f;
    vref_started_ = true;
  }
  const float volts = hal::adc_read(p->vref) * kAdcFullScaleVolts / kAdcFullScaleCounts;
  return volts * amps_per_volt;
}

bool OutputPort::read_limit_switch() {
  const OutputPortPins* p = pins();
  if (p == nullptr || p->limit == kNoPin) return false;
  return hal::gpio_read(p->limit);
}

uint32_t OutputPort::pulses_sent(uint8_t signal, uint8_t direction) const {
  if (signal >= kNumSignals) return 0;
  return sent_[signal][direction == DIRECTION_FORWARD ? 1 : 0];
}

// In the original this was the engine's own output stage, over the OUTPUT_TRANSMIT_ON_FRAME ports
// (original-library.md §1.3). Here the engine's kOutputPorts stage sends those, so a sketch that
// also called this every frame sent them twice a frame; now it adds only the frames the engine does
// not send.
void transmit_frames_on_all_output_ports() {
  const bool engine_sends_on_frame_ports = engine().running();
  for (OutputPort* port : begun_ports()) {
    if (engine_sends_on_frame_ports && port->transmit_mode() == OUTPUT_TRANSMIT_ON_FRAME) continue;
    port->transmit_frame();
  }
}

void iterate_across_all_output_ports(void (*fn)(OutputPort* port)) {
  if (fn == nullptr) return;
  for (OutputPort* port : begun_ports()) fn(port);
}

namespace {
// Applies a driver call to every begun port; reports the last failure (and keeps going).
Status for_each_driver(Status (OutputPort::*call)()) {
  Status result = Status::kOk;
  for (OutputPort* port : begun_ports()) {
    const Status status = (port->*call)();
    if (status != Status::kOk) result = status;
  }
  return result;
}
}  // namespace

Status enable_drivers() { return for_each_driver(&OutputPort::enable_driver); }
void set_drivers_idle_timeout_ms(uint32_t ms) {
  for (OutputPort* port : begun_ports()) port->set_driver_idle_timeout_ms(ms);
}
Status disable_drivers() { return for_each_driver(&OutputPort::disable_driver); }

}  // namespace stepdance
