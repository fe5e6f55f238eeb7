// EBB motion commands: SM, XM, LM, LT, HM, EM and the pen's SP, TP, S2, queued for the frame.
#include "stepdance/interfaces/ebb/ebb_commands.hpp"

namespace stepdance::ebb {

namespace {

constexpr int64_t kInt32Min = -2147483648LL;
constexpr int64_t kInt32Max = 2147483647LL;
constexpr int64_t kUint32Max = 4294967295LL;
constexpr uint32_t kTicksPerMs = kTicksPerSecond / 1000;
constexpr int64_t kMaxDelayMs = 100000;  // SM/XM used as a delay are capped here

int64_t abs64(int64_t value) { return value < 0 ? -value : value; }
int64_t ceil_div(int64_t a, int64_t b) { return (a + b - 1) / b; }

/// Accumulator rate that takes |steps| steps in `ticks` ticks (at most one step per tick).
// Rounded up so the steps are done within the duration; capped at 2^31 (one step per tick, 25 kHz),
// the EBB's maximum rate.
int64_t constant_rate(int64_t steps, int64_t ticks) {
  const int64_t rate = ceil_div(abs64(steps) * kStepThreshold, ticks);
  return rate > kStepThreshold ? kStepThreshold : rate;
}

/// One LM/LT axis: the sign of Rate or of Steps gives the direction; |Rate| evolves by Accel.
// ebb-protocol.md, LM row: negative Steps (preferred) or negative Rate means reverse; both negative
// cancel out.
void set_axis(EbbMove& move, int axis, int64_t rate, int64_t steps, int64_t accel) {
  int8_t direction = 1;
  if (rate < 0) {
    direction = -direction;
    rate = -rate;
  }
  if (steps < 0) {
    direction = static_cast<int8_t>(-direction);
    steps = -steps;
  }
  move.rate[axis] = rate;
  move.accel[axis] = accel;
  move.steps[axis] = static_cast<uint32_t>(steps);
  move.direction[axis] = direction;
}

}  // namespace

bool EbbCommands::command_sm(EbbParameters& p) { return stepper_move(p, false); }
bool EbbCommands::command_xm(EbbParameters& p) { return stepper_move(p, true); }

// SM,Duration,Steps1[,Steps2[,Clear]] and XM,Duration,StepsA,StepsB[,Clear] (ebb-protocol.md):
// Duration 0 is invalid; both step counts 0 make a timed delay capped at 100 000 ms; XM mixes
// motor1 = A + B, motor2 = A − B for CoreXY machines.
bool EbbCommands::stepper_move(EbbParameters& p, bool mixed) {
  int64_t duration_ms = 0, a = 0, b = 0, clear = 0;
  p.integer(mixed ? 1 : 0, mixed ? kInt32Max : kUint32Max, true, duration_ms);
  p.integer(kInt32Min, kInt32Max, true, a);
  p.integer(kInt32Min, kInt32Max, mixed, b);
  p.integer(0, 3, false, clear);
  if (!p.finish()) return replies_.parameter_error(p), true;
  if (duration_ms == 0) return replies_.error(EbbError::kInvalid), true;
  const int64_t steps[2] = {mixed ? a + b : a, mixed ? a - b : b};
  EbbMove move;
  if (steps[0] == 0 && steps[1] == 0) {
    move.kind = EbbMove::Kind::kDelay;
    move.ticks = static_cast<uint32_t>((duration_ms < kMaxDelayMs ? duration_ms : kMaxDelayMs) * kTicksPerMs);
  } else if (!steps_move(steps, duration_ms, mixed, move)) {
    return true;  // refused, answered
  }
  move.clear = static_cast<uint8_t>(clear);
  return queue_and_reply(move);
}

// Fills a constant-rate SM/XM move; false (with the error reply) when it is refused.
// A constant-rate move on each axis; ebb-protocol.md: an out-of-range XM rate is an error and the move is
// not executed, while SM clamps the rate to 25 000 steps/s (the move then takes longer).
bool EbbCommands::steps_move(const int64_t (&steps)[2], int64_t duration_ms, bool mixed, EbbMove& move) {
  const int64_t ticks = duration_ms * kTicksPerMs;
  for (int axis = 0; axis < 2; ++axis) {
    if (steps[axis] < kInt32Min || steps[axis] > kInt32Max) return replies_.error(EbbError::kInvalid), false;
    // XM refuses a rate beyond 25,000 steps/s; SM runs at the limit instead.
    if (mixed && abs64(steps[axis]) > ticks) {
      replies_.error(EbbError::kRateTooHigh, static_cast<char>('1' + axis));
      return false;
    }
    move.kind = EbbMove::Kind::kSteps;
    move.steps[axis] = static_cast<uint32_t>(abs64(steps[axis]));
    move.direction[axis] = steps[axis] < 0 ? -1 : 1;
    move.rate[axis] = steps[axis] == 0 ? 0 : constant_rate(steps[axis], ticks);
  }
  return true;
}

bool EbbCommands::command_lm(EbbParameters& p) { return low_level_move(p, false); }
bool EbbCommands::command_lt(EbbParameters& p) { return low_level_move(p, true); }

// LM,Rate1,Steps1,Accel1,Rate2,Steps2,Accel2[,Clear] and LT,Intervals,Rate1,Accel1,Rate2,Accel2[,Clear]:
// the raw accumulator parameters, executed exactly as the EBB does (ebb_motion.cpp). saxi and the
// AxiDraw software send their own planned acceleration this way.
bool EbbCommands::low_level_move(EbbParameters& p, bool timed) {
  int64_t intervals = 0, rate[2] = {}, steps[2] = {}, accel[2] = {}, clear = 0;
  if (timed) p.integer(0, kUint32Max, true, intervals);
  for (int axis = 0; axis < 2; ++axis) {
    p.integer(kInt32Min, kInt32Max, true, rate[axis]);
    if (!timed) p.integer(kInt32Min, kInt32Max, true, steps[axis]);
    p.integer(kInt32Min, kInt32Max, true, accel[axis]);
  }
  p.integer(0, 3, false, clear);
  if (!p.finish()) return replies_.parameter_error(p), true;
  EbbMove move;
  move.kind = timed ? EbbMove::Kind::kTime : EbbMove::Kind::kSteps;
  move.ticks = static_cast<uint32_t>(intervals);
  for (int axis = 0; axis < 2; ++axis) set_axis(move, axis, rate[axis], steps[axis], accel[axis]);
  move.clear = static_cast<uint8_t>(clear);
  return queue_and_reply(move);
}

// HM,StepFrequency[,Position1,Position2]: StepFrequency 2…25000; without positions the target is
// home (0, 0). Queued: it waits for earlier motion (ebb-protocol.md).
bool EbbCommands::command_hm(EbbParameters& p) {
  int64_t frequency = 0, position[2] = {};
  p.integer(2, 25000, true, frequency);
  const bool has_position = p.integer(kInt32Min, kInt32Max, false, position[0]);
  if (has_position) p.integer(kInt32Min, kInt32Max, true, position[1]);
  if (!p.finish()) return replies_.parameter_error(p), true;
  EbbMove move;
  move.kind = EbbMove::Kind::kHome;
  move.frequency = static_cast<uint32_t>(frequency);
  move.target[0] = static_cast<int32_t>(position[0]);
  move.target[1] = static_cast<int32_t>(position[1]);
  return queue_and_reply(move);
}

// EM,Enable1[,Enable2]: 0 off, 1–5 on with 1/16 … full step; Enable1's mode applies to both motors
// (ebb-protocol.md). Queued like the EBB's, and the step counters reset when it runs.
bool EbbCommands::command_em(EbbParameters& p) {
  int64_t enable1 = 0, enable2 = -1;
  p.integer(0, 5, true, enable1);
  p.integer(0, 5, false, enable2);
  if (!p.finish()) return replies_.parameter_error(p), true;
  EbbMove move;
  move.kind = EbbMove::Kind::kEnable;
  move.microstep_mode = static_cast<uint8_t>(enable1);  // 0 leaves the mode as it is
  move.enable[0] = enable1 != 0;
  move.enable[1] = enable2 < 0 ? motors_enabled_[1] : enable2 != 0;
  if (!queue_and_reply(move)) return false;
  motors_enabled_[0] = move.enable[0];
  motors_enabled_[1] = move.enable[1];
  return true;
}

// SP,Value[,Duration[,Pin]]: 1 up, 0 down, queued (ebb-protocol.md). Values 2 and 3 act at once,
// outside the FIFO (3: and the down position becomes the up one).
bool EbbCommands::command_sp(EbbParameters& p) {
  int64_t value = 0, duration_ms = 0, pin = 1;
  p.integer(0, 3, true, value);
  p.integer(1, 65535, false, duration_ms);
  p.integer(0, 7, false, pin);
  if (!p.finish()) return replies_.parameter_error(p), true;
  if (value >= 2) {
    pen_.lift_now(value == 3);
    queue_.pen_now(pen_.up_position(), pen_.up_rate());
    replies_.ok();
    return true;
  }
  if (!queue_and_reply(pen_.move(value == 1, static_cast<uint32_t>(duration_ms)))) return false;
  pen_.commanded(value == 1);
  return true;
}

// TP[,Duration]: toggle the pen relative to the last commanded state, not the executed one, so two
// TPs queued back to back cancel out.
bool EbbCommands::command_tp(EbbParameters& p) {
  int64_t duration_ms = 0;
  p.integer(1, 65535, false, duration_ms);
  if (!p.finish()) return replies_.parameter_error(p), true;
  const bool up = !pen_.commanded_up();
  if (!queue_and_reply(pen_.move(up, static_cast<uint32_t>(duration_ms)))) return false;
  pen_.commanded(up);
  return true;
}

// S2,Position,Pin[,Rate[,Delay]] (ebb-protocol.md): clients drive the pen through S2 on the pen servo
// output (RB1, S2 pin 4); other outputs have no servo here and are accepted without effect.
bool EbbCommands::command_s2(EbbParameters& p) {
  int64_t position = 0, pin = 0, rate = 0, delay_ms = 0;
  p.integer(0, 65535, true, position);
  p.integer(0, 24, true, pin);
  p.integer(0, 65535, false, rate);
  p.integer(0, 65535, false, delay_ms);
  if (!p.finish()) return replies_.parameter_error(p), true;
  if (position == 0 ||
      pin != EbbPen::kServoPin) {  // S2,0,pin turns an output off at once; other pins have no servo here
    replies_.ok();
    return true;
  }
  const EbbMove move =
      pen_.position_move(static_cast<uint16_t>(position), static_cast<uint16_t>(rate), static_cast<uint32_t>(delay_ms));
  if (!queue_and_reply(move)) return false;
  pen_.commanded(move.pen_up);
  return true;
}

}  // namespace stepdance::ebb
