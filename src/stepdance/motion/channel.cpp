// Channel: the per-frame stepping law, its exact rate limiter, soft limits and deep sync.
#include "stepdance/motion/channel.hpp"

#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance {
namespace {

// The rate limiter counts credit in milli-pulses per second, one add per frame. A pulse costs
// one second's worth of frames of credit, so a rate of N pulses/s earns exactly N pulses in any
// second of frames; fractional rates keep a resolution of 0.001 pulses/s. At the shortest period
// (200 000 frames/s) a reversal's price is 4e8, so credit stays well inside 32 bits.
constexpr uint32_t kCreditScale = 1000;
// credit_per_frame_ when no limit is set: one pulse every frame, whatever the period.
constexpr uint32_t kUnlimitedCredit = UINT32_MAX;

uint32_t credit_per_pulse() { return frame_rate_hz() * kCreditScale; }

// Half a step: the dead band around the target.
constexpr double kDeadBandSteps = 0.5;

}  // namespace

Channel::Channel() = default;

Status Channel::begin(OutputPort* port, uint8_t signal) {
  if (signal >= kNumSignals) return Status::kBadArgument;
  return start(port, signal);
}

// Without a port the channel still runs: current_position follows the target and pulses are counted,
// but nothing is sent. The original never ran a port-less channel (original-library.md §4.2).
Status Channel::begin() { return start(nullptr, 255); }

// Checked at dance_start(), when the period is final: a channel whose signal can never leave its port
// would silently never move its motor, so the start is refused instead.
bool Channel::accept_frame_period(uint32_t period_us) {
  if (port_ == nullptr || port_->can_carry(signal_, period_us)) return true;
  fault(FaultReason::kBadConfiguration,
        "Channel: its output port cannot carry its signal (a STEP_DIR port sends one signal; "
        "OUTPUT_FRAME_8US has no room for E, OUTPUT_FRAME_4US only for X)");
  return false;
}

// What an interface that speaks in motor steps (the EBB, Grbl's $100…) asks the ports it reaches:
// a channel's target is in steps, so its input ratio is the world units of one step.
bool Channel::world_units_per_step(const BlockPort& input, double& world_units) const {
  if (&input != &input_target_position && &input != &input_target_position_2) return false;
  world_units = input.ratio();
  return true;
}

Status Channel::start(OutputPort* port, uint8_t signal) {
  port_ = port;
  signal_ = signal;
  reset_state();
  input_target_position.begin(&target_position, BLOCKPORT_INPUT, this);
  input_target_position_2.begin(&target_position_2, BLOCKPORT_INPUT, this);
  return register_in(Stage::kChannels);
}

// Unlimited rate by default: one pulse per frame at most, the spec's frame rule (each signal at most
// once per frame), which is 25 kHz at the default 40 µs period.
void Channel::reset_state() {
  target_position = 0;
  target_position_2 = 0;
  current_position = 0;
  filtered_target_position = 0;
  direction_ = 1;
  last_pulse_step_ = 0;
  credit_per_frame_ = kUnlimitedCredit;
  credit_ = credit_per_pulse() - 1;  // as after a long idle time: the first pulse may go at once
  pulses_forward_ = 0;
  pulses_reverse_ = 0;
  pulses_withheld_ = 0;
}

// Rounded to the nearest milli-pulse per second. A rate ≤ 0 (or NaN) stops the channel's pulses
// rather than removing the limit: a sketch asking for 0 means "do not move".
void Channel::set_max_pulse_rate(double pulses_per_s) {
  if (!(pulses_per_s > 0.0)) {  // also catches NaN
    credit_per_frame_ = 0;
    return;
  }
  // Kept as asked even above today's frame rate: a shorter period chosen later raises the cap.
  if (pulses_per_s * kCreditScale >= static_cast<double>(kUnlimitedCredit)) {
    credit_per_frame_ = kUnlimitedCredit;
    return;
  }
  credit_per_frame_ = static_cast<uint32_t>(pulses_per_s * kCreditScale + 0.5);
}

void Channel::set_ratio(double world_units, double channel_units) {
  input_target_position.set_ratio(world_units, channel_units);
  input_target_position_2.set_ratio(world_units, channel_units);
  update_limit_steps();
}

void Channel::set_upper_limit(double world_position) {
  upper_limit_world_ = world_position;
  update_limit_steps();
  upper_enabled_ = true;
}

void Channel::set_lower_limit(double world_position) {
  lower_limit_world_ = world_position;
  update_limit_steps();
  lower_enabled_ = true;
}

void Channel::disable_limits() {
  upper_enabled_ = false;
  lower_enabled_ = false;
}

// Limits are kept in world units and converted again whenever the ratio changes, so
// set_ratio() after set_upper_limit() still limits at the same world position.
void Channel::update_limit_steps() {
  upper_limit_steps_ = input_target_position.convert_world_to_block_units(upper_limit_world_);
  lower_limit_steps_ = input_target_position.convert_world_to_block_units(lower_limit_world_);
}

// Looks at the commanded (filtered) target as well as the position, unlike the original, which only
// checked current_position: a target beyond a limit is reported before the axis reaches it.
int8_t Channel::is_outside_limits() const {
  const double current = current_position;
  const double commanded = filtered_target_position;
  if (upper_enabled_ && (current > upper_limit_steps_ || commanded > upper_limit_steps_)) return 1;
  if (lower_enabled_ && (current < lower_limit_steps_ || commanded < lower_limit_steps_)) return -1;
  return 0;
}

// The original's smoothing (original-library.md §4.2): an exponential moving average with α = 1/n,
// not a box average. n = 0 would divide by zero, so it means 1 (no smoothing).
void Channel::enable_filtering(uint16_t samples) {
  filter_samples_ = samples == 0 ? 1 : samples;
  filtering_ = true;
}

// Deep sync (original-library.md §3.4): the position becomes the target, so the error is zero and no
// pulse is produced for the jump.
void Channel::push_deep() {
  hal::CriticalSection guard;
  const double summed = target_position + target_position_2;
  filtered_target_position = summed;
  current_position = summed;
}

// Frame context (channel stage, after every block that feeds it; original-library.md §1.3). The
// stepping law: the target (two summed inputs, e.g. a jog and a program) is followed to within half a
// step, at most one pulse per frame, at most the set pulse rate.
void Channel::run() {
  input_target_position.pull();
  input_target_position.update();
  input_target_position_2.pull();
  input_target_position_2.update();
  const double error_steps = advance_filter() - current_position;
  track_direction(error_steps);
  meter_credit(demanded_step(error_steps));
}

double Channel::advance_filter() {
  const double summed = target_position + target_position_2;
  if (!filtering_) {
    filtered_target_position = summed;
  } else {
    const double n = filter_samples_;
    filtered_target_position = (filtered_target_position * (n - 1.0) + summed) / n;
  }
  return filtered_target_position;
}

// Inside the dead band the last direction is kept (original §4.2 step 4), so a target hovering around
// a half step does not flip DIR every frame.
void Channel::track_direction(double error_steps) {
  if (error_steps >= kDeadBandSteps) {
    direction_ = 1;
  } else if (error_steps < -kDeadBandSteps) {
    direction_ = -1;
  }
}

// A soft limit withholds the pulse and does not advance the position, so position and motor agree;
// the original counted the step but did not emit it, leaving them out of step. Withheld pulses are
// counted for diagnosis.
int8_t Channel::demanded_step(double error_steps) {
  if (error_steps <= kDeadBandSteps && error_steps >= -kDeadBandSteps) return 0;
  if (!limit_allows(direction_)) {
    ++pulses_withheld_;
    return 0;
  }
  return direction_;
}

bool Channel::limit_allows(int8_t step) const {
  const double next = current_position + step;
  if (step > 0) return !upper_enabled_ || next <= upper_limit_steps_;
  return !lower_enabled_ || next >= lower_limit_steps_;
}

// A reversal costs two pulses' credit, as in the original: the motor gets at least one idle pulse
// period before changing direction, so a driver never sees a reversal at full rate.
uint32_t Channel::threshold_for(int8_t step) const {
  const bool reversing = step != 0 && last_pulse_step_ != 0 && step != last_pulse_step_;
  return reversing ? 2 * credit_per_pulse() : credit_per_pulse();
}

// Earns this frame's credit and pulses if the step is affordable. Without a pulse the credit is
// capped just below the price, so idle (or blocked) time never banks a burst, while a pending
// reversal may still save up its double price.
void Channel::meter_credit(int8_t step) {
  const uint32_t one_pulse = credit_per_pulse();
  credit_ += credit_per_frame_ < one_pulse ? credit_per_frame_ : one_pulse;
  const uint32_t price = threshold_for(step);
  if (step != 0 && credit_ >= price) {
    credit_ -= price;  // keep the remainder: exact long-run rate
    emit(step);
    return;
  }
  if (credit_ > price - 1) credit_ = price - 1;
}

// The position counts logical steps; inversion only flips what goes on the wire (DIR), so limits and
// read-backs stay in the machine's own direction.
void Channel::emit(int8_t step) {
  current_position = current_position + step;
  last_pulse_step_ = step;
  if (step > 0) {
    ++pulses_forward_;
  } else {
    ++pulses_reverse_;
  }
  if (port_ == nullptr) return;
  const bool forward_on_wire = (step > 0) != inverted_;
  port_->add_signal(signal_, forward_on_wire ? DIRECTION_FORWARD : DIRECTION_REVERSE);
}

}  // namespace stepdance
