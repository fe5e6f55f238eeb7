// EbbMotionExecutor: the EBB's 25 kHz accumulator algorithm, servo slewing and FIFO entry effects.
#include "stepdance/interfaces/ebb/ebb_motion.hpp"

#include <math.h>

namespace stepdance::ebb {
namespace {

constexpr double kTicksPerServoPeriod = 600.0;  // the servo rate is given per 24 ms pulse period

int64_t abs64(int64_t value) { return value < 0 ? -value : value; }

/// ⌈a / b⌉ for a ≥ 0, b > 0.
int64_t ceil_div(int64_t a, int64_t b) { return (a + b - 1) / b; }

}  // namespace

// How many 40 µs ticks an LM axis needs for its steps: the accumulator gains rate + k·accel on tick
// k, so distance D = steps × 2^31 is covered when rate·t + accel·t²/2 = D; t is the positive root of
// that quadratic (ebb-protocol.md, LM row). A constant rate is the linear case.
double ticks_to_cover(const EbbMove& move, int axis) {
  const double distance = static_cast<double>(move.steps[axis]) * kStepThreshold;
  const double rate = static_cast<double>(move.rate[axis]);
  const double accel = static_cast<double>(move.accel[axis]);
  if (accel == 0.0) return rate > 0.0 ? distance / rate : 0.0;
  const double discriminant = rate * rate + 2.0 * accel * distance;
  return discriminant > 0.0 ? (-rate + sqrt(discriminant)) / accel : 0.0;
}

// The fastest step rate the move asks of a motor, in steps per EBB tick (≤ 1: the accumulator can
// step at most once per tick). Linear in time, so the peak is at the first or last tick; a rate that
// goes negative wraps (as on the EBB) and is taken as the full rate. Used to stretch moves our frame
// period cannot carry.
double EbbMotionExecutor::peak_steps_per_tick() const {
  const bool accumulated = move_.kind == EbbMove::Kind::kSteps || move_.kind == EbbMove::Kind::kTime;
  if (!busy_ || !accumulated) return 0.0;  // kHome runs as kSteps (begin_home)
  double peak = 0.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (!axis_active_[axis]) continue;
    const double rate = static_cast<double>(move_.rate[axis]);
    const double accel = static_cast<double>(move_.accel[axis]);
    const double ticks = move_.kind == EbbMove::Kind::kTime ? move_.ticks : ticks_to_cover(move_, axis);
    const double first = rate + accel / 2.0;
    const double last = rate + accel * (ticks - 0.5);
    const double most = (first < 0.0 || last < 0.0) ? kStepThreshold : (first > last ? first : last);
    const double steps = most >= kStepThreshold ? 1.0 : most / kStepThreshold;
    if (steps > peak) peak = steps;
  }
  return peak;
}

void EbbMotionExecutor::reset(uint16_t servo_reset) {
  *this = EbbMotionExecutor{};
  servo_position_ = servo_reset;
  servo_target_ = servo_reset;
}

void EbbMotionExecutor::clear_global_steps() {
  global_steps_[0] = global_steps_[1] = 0;
  accumulator_[0] = accumulator_[1] = 0;
}

// Frame context, when the move reaches the head of the FIFO. Every command takes effect in FIFO order,
// as on the EBB: pen moves and EM too, so a client's "pen up, then move" never moves with the pen down.
void EbbMotionExecutor::start(const EbbMove& move) {
  move_ = move;
  busy_ = false;
  axis_active_[0] = axis_active_[1] = false;
  ticks_left_ = move.ticks;
  switch (move.kind) {
    case EbbMove::Kind::kSteps:
    case EbbMove::Kind::kTime: begin_accumulated(move); break;
    case EbbMove::Kind::kHome: begin_home(move); break;
    case EbbMove::Kind::kDelay: busy_ = ticks_left_ > 0; break;
    case EbbMove::Kind::kServo:
      servo_target_ = move.servo_target;
      servo_rate_per_tick_ = move.servo_rate / kTicksPerServoPeriod;
      if (move.servo_rate == 0) servo_position_ = servo_target_;
      pen_up_ = move.pen_up;
      busy_ = ticks_left_ > 0;
      break;
    case EbbMove::Kind::kEnable:
      if (move.microstep_mode >= 1 && move.microstep_mode <= 5) microstep_mode_ = move.microstep_mode;
      enabled_[0] = move.enable[0];
      enabled_[1] = move.enable[1];
      clear_global_steps();  // every EM, as the EBB's firmware: the counters and both accumulators
      break;
  }
}

// HM: a straight constant-rate line from the global step counters to the target.
// HM (ebb-protocol.md): the axis with the longer distance runs at StepFrequency, the other
// proportionally slower so the path is a straight line; rates are rounded up so the move never takes
// longer than the longest axis at that frequency. The target is computed when HM starts, from the
// step counters at that moment, which is why it is a FIFO entry and not a query.
void EbbMotionExecutor::begin_home(const EbbMove& move) {
  EbbMove line = move;
  line.kind = EbbMove::Kind::kSteps;
  line.clear = 3;  // a straight line from a clean start
  int64_t distance[2];
  int64_t longest = 0;
  for (int axis = 0; axis < 2; ++axis) {
    distance[axis] = int64_t{move.target[axis]} - global_steps_[axis];
    if (abs64(distance[axis]) > longest) longest = abs64(distance[axis]);
  }
  if (longest == 0 || move.frequency == 0) return;
  const int64_t ticks = ceil_div(longest * kTicksPerSecond, move.frequency);
  for (int axis = 0; axis < 2; ++axis) {
    line.steps[axis] = static_cast<uint32_t>(abs64(distance[axis]));
    line.direction[axis] = distance[axis] < 0 ? -1 : 1;
    line.rate[axis] = ceil_div(abs64(distance[axis]) * kStepThreshold, ticks);
    line.accel[axis] = 0;
  }
  move_ = line;
  begin_accumulated(line);
}

// LM's first tick starts from Rate − Accel/2 (ebb-protocol.md, LM row): the rate at mid-tick, so the
// distance over a tick matches the continuous motion. Clear bit n zeroes axis n's accumulator, so a
// client can start a move without a fractional step left over from the previous one.
void EbbMotionExecutor::begin_accumulated(const EbbMove& move) {
  enabled_[0] = enabled_[1] = true;  // motion commands enable both drivers, as the EBB does
  for (int axis = 0; axis < 2; ++axis) {
    if ((move.clear >> axis) & 1) accumulator_[axis] = 0;
    rate_[axis] = move.rate[axis] - move.accel[axis] / 2;
    steps_left_[axis] = move.steps[axis];
    const bool can_step = move.rate[axis] != 0 || move.accel[axis] != 0;
    axis_active_[axis] = can_step && (move.kind == EbbMove::Kind::kTime || steps_left_[axis] > 0);
  }
  busy_ = move.kind == EbbMove::Kind::kTime ? ticks_left_ > 0 : (axis_active_[0] || axis_active_[1]);
}

// One EBB tick (40 µs of EBB time; the frame maps its own period onto it). Step moves end when every
// axis has made its steps, LT moves after their tick count, delays and pen moves after their
// duration. Returns whether the move still runs.
bool EbbMotionExecutor::tick() {
  slew_servo();
  if (!busy_) return false;
  switch (move_.kind) {
    case EbbMove::Kind::kSteps:
    case EbbMove::Kind::kHome:
      for (int axis = 0; axis < 2; ++axis) {
        if (axis_active_[axis]) step_axis(axis);
      }
      busy_ = axis_active_[0] || axis_active_[1];
      break;
    case EbbMove::Kind::kTime:
      for (int axis = 0; axis < 2; ++axis) {
        if (axis_active_[axis]) step_axis(axis);
      }
      busy_ = --ticks_left_ > 0;
      break;
    default: busy_ = --ticks_left_ > 0; break;
  }
  return busy_;
}

// The EBB's accumulator rule (ebb-protocol.md, LM row): every tick Rate += Accel and Accumulator +=
// Rate; a step is taken when the accumulator reaches 2^31, which is then subtracted (the remainder
// kept, so the long-run rate is exact). position_16_ counts in 1/16 steps whatever the microstep
// mode, the unit the outputs are scaled from.
void EbbMotionExecutor::step_axis(int axis) {
  int64_t rate = rate_[axis] + move_.accel[axis];
  if (rate < 0) rate += kStepThreshold;  // the EBB rolls a negative rate over
  rate_[axis] = rate;
  accumulator_[axis] += rate;
  if (accumulator_[axis] >= kStepThreshold) {
    accumulator_[axis] -= kStepThreshold;
    const int direction = move_.direction[axis];
    global_steps_[axis] += direction;
    position_16_[axis] += direction * sixteenths_per_step();
    if (move_.kind != EbbMove::Kind::kTime && --steps_left_[axis] == 0) axis_active_[axis] = false;
  }
  // A step-limited axis whose rate and acceleration are both zero can never finish: drop it
  // rather than hang the FIFO (a real EBB would wait for ever; ES would be the only way out).
  if (move_.kind != EbbMove::Kind::kTime && rate_[axis] == 0 && move_.accel[axis] == 0) axis_active_[axis] = false;
}

// The servo moves toward its target by the rate per tick (SC,11/12 rates are per 24 ms servo period,
// 600 ticks); rate 0 jumps at once.
void EbbMotionExecutor::slew_servo() {
  if (servo_position_ == servo_target_) return;
  if (servo_rate_per_tick_ <= 0.0) {
    servo_position_ = servo_target_;
    return;
  }
  const double gap = servo_target_ - servo_position_;
  if (gap > servo_rate_per_tick_) {
    servo_position_ += servo_rate_per_tick_;
  } else if (gap < -servo_rate_per_tick_) {
    servo_position_ -= servo_rate_per_tick_;
  } else {
    servo_position_ = servo_target_;
  }
}

void EbbMotionExecutor::servo_now(uint16_t target, uint16_t rate, bool pen_up) {
  servo_target_ = target;
  servo_rate_per_tick_ = rate / kTicksPerServoPeriod;
  if (rate == 0) servo_position_ = servo_target_;
  pen_up_ = pen_up;
}

// ES (ebb-protocol.md): abort the current move; the reply reports whether one was running.
bool EbbMotionExecutor::stop() {
  const bool was_busy = busy_;
  busy_ = false;
  axis_active_[0] = axis_active_[1] = false;
  return was_busy;
}

}  // namespace stepdance::ebb
