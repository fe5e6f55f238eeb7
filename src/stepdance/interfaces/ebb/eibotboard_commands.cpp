// Eibotboard commands: parameters checked as the EBB does, motion queued, queries answered.
#include <string.h>

#include "stepdance/interfaces/ebb/eibotboard.hpp"

#include "stepdance/core/fault.hpp"

namespace stepdance {

using ebb::EbbError;
using ebb::EbbParameters;
using ebb::EbbMove;
using ebb::kStepThreshold;
using ebb::kTicksPerSecond;

namespace {

constexpr int64_t kInt32Min = -2147483648LL;
constexpr int64_t kInt32Max = 2147483647LL;
constexpr int64_t kUint32Max = 4294967295LL;
constexpr uint32_t kTicksPerMs = kTicksPerSecond / 1000;
constexpr int64_t kMaxDelayMs = 100000;  // SM/XM used as a delay are capped here
constexpr uint8_t kPenServoPin = 4;      // S2's RP4 is RB1, the pen-lift servo output

int64_t abs64(int64_t value) { return value < 0 ? -value : value; }
int64_t ceil_div(int64_t a, int64_t b) { return (a + b - 1) / b; }

bool is(const char* name, const char* command) { return strcmp(name, command) == 0; }

/// Accumulator rate that takes |steps| steps in `ticks` ticks (at most one step per tick).
int64_t constant_rate(int64_t steps, int64_t ticks) {
  const int64_t rate = ceil_div(abs64(steps) * kStepThreshold, ticks);
  return rate > kStepThreshold ? kStepThreshold : rate;
}

/// One LM/LT axis: the sign of Rate or of Steps gives the direction; |Rate| evolves by Accel.
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

bool Eibotboard::reply_parameter_error(const EbbParameters& parameters) {
  if (parameters.error() == EbbError::kNone) return false;
  reply_error(parameters.error(), command_name_, parameters.offending());
  return true;
}

bool Eibotboard::dispatch(const char* name, EbbParameters& p) {
  // Motor moves are refused while an alarm is raised (the fault path); pen commands still run.
  if (alarm_active() && (is(name, "SM") || is(name, "XM") || is(name, "LM") || is(name, "LT") || is(name, "HM"))) {
    reply_error(EbbError::kAlarm, command_name_);
    return true;
  }
  // Motion (queued; false while the FIFO has no room, so the line waits)
  if (is(name, "SM")) return command_sm(p, false);
  if (is(name, "XM")) return command_sm(p, true);
  if (is(name, "LM")) return command_lm(p, false);
  if (is(name, "LT")) return command_lm(p, true);
  if (is(name, "HM")) return command_hm(p);
  if (is(name, "EM")) return command_em(p);
  if (is(name, "SP")) return command_sp(p);
  if (is(name, "S2")) return command_s2(p);
  if (is(name, "TP")) return command_tp(p);
  // Settings and queries (immediate)
  if (is(name, "SC")) return command_sc(p);
  if (is(name, "CU")) return command_cu(p);
  if (is(name, "QU")) return command_qu(p);
  if (is(name, "ES")) {
    command_es(p);
    return true;
  }
  char data[48];
  TextWriter text(data, sizeof(data));
  if (is(name, "V")) {
    if (p.finish()) {
      reply_data(version_, false);
    } else {
      reply_parameter_error(p);
    }
    return true;
  }
  if (is(name, "QM") || is(name, "QG")) {
    if (p.finish()) {
      query_motion();
    } else {
      reply_parameter_error(p);
    }
    return true;
  }
  if (is(name, "SR")) {
    int64_t timeout = 0, state = 0;
    p.integer(0, kUint32Max, true, timeout);
    p.integer(0, 1, false, state);
    if (!p.finish()) return reply_parameter_error(p), true;
    servo_timeout_ms_ = static_cast<uint32_t>(timeout);
    reply_ok();
    return true;
  }
  if (is(name, "SL")) {
    int64_t value = 0, index = 0;
    p.integer(0, 255, true, value);
    p.integer(0, 31, false, index);
    if (!p.finish()) return reply_parameter_error(p), true;
    variables_[index] = static_cast<uint8_t>(value);
    reply_ok();
    return true;
  }
  if (is(name, "QL")) {
    int64_t index = 0;
    p.integer(0, 31, false, index);
    if (!p.finish()) return reply_parameter_error(p), true;
    text.unsigned_number(variables_[index]);
    reply_data(text.c_str(), true);
    return true;
  }
  if (is(name, "ST")) {
    char tag[sizeof(tag_)] = {};
    p.text(tag, sizeof(tag), false);
    if (!p.finish()) return reply_parameter_error(p), true;
    memcpy(tag_, tag, sizeof(tag_));
    reply_ok();
    return true;
  }
  if (!p.finish()) {
    // Every remaining command takes no parameters.
    if (is(name, "QT") || is(name, "QS") || is(name, "CS") || is(name, "QP") || is(name, "QB") ||
        is(name, "QC") || is(name, "QE") || is(name, "QR") || is(name, "R")) {
      return reply_parameter_error(p), true;
    }
  }
  if (is(name, "QT")) {
    reply_data(tag_, true);
  } else if (is(name, "QS")) {
    text.signed_number(frame_global_steps_[0]).character(',').signed_number(frame_global_steps_[1]);
    reply_data(text.c_str(), true, "\n\r");
  } else if (is(name, "CS")) {
    controls_.push(Control::kClearSteps);
    reply_ok();
  } else if (is(name, "QP")) {
    // The pen as executed: a pen command still waiting in the FIFO does not show yet.
    reply_data(frame_pen_up_ ? "1" : "0", true, "\n\r");
  } else if (is(name, "QB")) {
    reply_data(button_pressed_ ? "1" : "0", true);
    button_pressed_ = false;
  } else if (is(name, "QC")) {
    // A 1.27 V current reference and a 12 V supply (clients check the supply is there).
    reply_data("0394,0394", true);
  } else if (is(name, "QE")) {
    // The drivers as the frame has set them (EM runs from the FIFO; motion enables them too).
    text.unsigned_number(frame_motor_resolution_[0]).character(',').unsigned_number(frame_motor_resolution_[1]);
    reply_data(text.c_str(), true);
  } else if (is(name, "QR")) {
    reply_data("1", true, "\n\r");
  } else if (is(name, "R")) {
    reply_ok();
    controls_.push(Control::kReset);
    future_syntax_ = false;
    ack_enabled_ = true;
    fifo_depth_ = 1;
    pen_commanded_up_ = true;
    motors_enabled_[0] = motors_enabled_[1] = false;
  } else {
    reply_error(EbbError::kUnknownCommand, name);
  }
  return true;
}

bool Eibotboard::command_sm(EbbParameters& p, bool mixed) {
  int64_t duration_ms = 0, a = 0, b = 0, clear = 0;
  p.integer(mixed ? 1 : 0, mixed ? kInt32Max : kUint32Max, true, duration_ms);
  p.integer(kInt32Min, kInt32Max, true, a);
  p.integer(kInt32Min, kInt32Max, mixed, b);
  p.integer(0, 3, false, clear);
  if (!p.finish()) return reply_parameter_error(p), true;
  if (duration_ms == 0) return reply_error(EbbError::kInvalid, command_name_), true;
  const int64_t steps[2] = {mixed ? a + b : a, mixed ? a - b : b};
  EbbMove move;
  if (steps[0] == 0 && steps[1] == 0) {
    move.kind = EbbMove::Kind::kDelay;
    move.ticks = static_cast<uint32_t>((duration_ms < kMaxDelayMs ? duration_ms : kMaxDelayMs) * kTicksPerMs);
  } else {
    const int64_t ticks = duration_ms * kTicksPerMs;
    for (int axis = 0; axis < 2; ++axis) {
      if (steps[axis] < kInt32Min || steps[axis] > kInt32Max) return reply_error(EbbError::kInvalid, command_name_), true;
      // XM refuses a rate beyond 25,000 steps/s; SM runs at the limit instead.
      if (mixed && abs64(steps[axis]) > ticks) {
        reply_error(EbbError::kRateTooHigh, command_name_, static_cast<char>('1' + axis));
        return true;
      }
      move.kind = EbbMove::Kind::kSteps;
      move.steps[axis] = static_cast<uint32_t>(abs64(steps[axis]));
      move.direction[axis] = steps[axis] < 0 ? -1 : 1;
      move.rate[axis] = steps[axis] == 0 ? 0 : constant_rate(steps[axis], ticks);
    }
    move.clear = static_cast<uint8_t>(clear);
  }
  if (!queue(move)) return false;
  reply_ok();
  return true;
}

bool Eibotboard::command_lm(EbbParameters& p, bool timed) {
  int64_t intervals = 0, rate[2] = {}, steps[2] = {}, accel[2] = {}, clear = 0;
  if (timed) p.integer(0, kUint32Max, true, intervals);
  for (int axis = 0; axis < 2; ++axis) {
    p.integer(kInt32Min, kInt32Max, true, rate[axis]);
    if (!timed) p.integer(kInt32Min, kInt32Max, true, steps[axis]);
    p.integer(kInt32Min, kInt32Max, true, accel[axis]);
  }
  p.integer(0, 3, false, clear);
  if (!p.finish()) return reply_parameter_error(p), true;
  EbbMove move;
  move.kind = timed ? EbbMove::Kind::kTime : EbbMove::Kind::kSteps;
  move.ticks = static_cast<uint32_t>(intervals);
  for (int axis = 0; axis < 2; ++axis) set_axis(move, axis, rate[axis], steps[axis], accel[axis]);
  move.clear = static_cast<uint8_t>(clear);
  if (!queue(move)) return false;
  reply_ok();
  return true;
}

bool Eibotboard::command_hm(EbbParameters& p) {
  int64_t frequency = 0, position[2] = {};
  p.integer(2, 25000, true, frequency);
  const bool has_position = p.integer(kInt32Min, kInt32Max, false, position[0]);
  if (has_position) p.integer(kInt32Min, kInt32Max, true, position[1]);
  if (!p.finish()) return reply_parameter_error(p), true;
  EbbMove move;
  move.kind = EbbMove::Kind::kHome;
  move.frequency = static_cast<uint32_t>(frequency);
  move.target[0] = static_cast<int32_t>(position[0]);
  move.target[1] = static_cast<int32_t>(position[1]);
  if (!queue(move)) return false;
  reply_ok();
  return true;
}

bool Eibotboard::command_em(EbbParameters& p) {
  int64_t enable1 = 0, enable2 = -1;
  p.integer(0, 5, true, enable1);
  p.integer(0, 5, false, enable2);
  if (!p.finish()) return reply_parameter_error(p), true;
  EbbMove move;
  move.kind = EbbMove::Kind::kEnable;
  move.microstep_mode = static_cast<uint8_t>(enable1);  // 0 leaves the mode as it is
  move.enable[0] = enable1 != 0;
  move.enable[1] = enable2 < 0 ? motors_enabled_[1] : enable2 != 0;
  if (!queue(move)) return false;
  motors_enabled_[0] = move.enable[0];
  motors_enabled_[1] = move.enable[1];
  reply_ok();
  return true;
}

EbbMove Eibotboard::servo_move(bool up, uint32_t delay_ms) const {
  EbbMove move;
  move.kind = EbbMove::Kind::kServo;
  move.servo_target = up ? servo_up_ : servo_down_;
  move.servo_rate = up ? servo_rate_up_ : servo_rate_down_;
  move.pen_up = up;
  move.ticks = delay_ms * kTicksPerMs;
  return move;
}

bool Eibotboard::command_sp(EbbParameters& p) {
  int64_t value = 0, duration_ms = 0, pin = 1;
  p.integer(0, 3, true, value);
  p.integer(1, 65535, false, duration_ms);
  p.integer(0, 7, false, pin);
  if (!p.finish()) return reply_parameter_error(p), true;
  if (value >= 2) {  // immediately up, bypassing the FIFO (3: and the down position becomes up)
    if (value == 3) servo_down_ = servo_up_;
    servo_now(servo_up_, servo_rate_up_);
    pen_commanded_up_ = true;
    reply_ok();
    return true;
  }
  if (!queue(servo_move(value == 1, static_cast<uint32_t>(duration_ms)))) return false;
  pen_commanded_up_ = value == 1;
  reply_ok();
  return true;
}

bool Eibotboard::command_tp(EbbParameters& p) {
  int64_t duration_ms = 0;
  p.integer(1, 65535, false, duration_ms);
  if (!p.finish()) return reply_parameter_error(p), true;
  if (!queue(servo_move(!pen_commanded_up_, static_cast<uint32_t>(duration_ms)))) return false;
  pen_commanded_up_ = !pen_commanded_up_;
  reply_ok();
  return true;
}

bool Eibotboard::command_s2(EbbParameters& p) {
  int64_t position = 0, pin = 0, rate = 0, delay_ms = 0;
  p.integer(0, 65535, true, position);
  p.integer(0, 24, true, pin);
  p.integer(0, 65535, false, rate);
  p.integer(0, 65535, false, delay_ms);
  if (!p.finish()) return reply_parameter_error(p), true;
  if (position == 0 || pin != kPenServoPin) {  // S2,0,pin turns an output off at once; other pins have no servo here
    reply_ok();
    return true;
  }
  EbbMove move;
  move.kind = EbbMove::Kind::kServo;
  move.servo_target = static_cast<uint16_t>(position);
  move.servo_rate = static_cast<uint16_t>(rate);
  // Up is the side of the pen-up position (SC,4) away from the pen-down one (SC,5).
  const int64_t middle = (int64_t{servo_up_} + servo_down_) / 2;
  move.pen_up = servo_up_ >= servo_down_ ? position > middle : position < middle;
  move.ticks = static_cast<uint32_t>(delay_ms) * kTicksPerMs;
  if (!queue(move)) return false;
  pen_commanded_up_ = move.pen_up;
  reply_ok();
  return true;
}

bool Eibotboard::command_sc(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(0, 65535, true, value);
  if (!p.finish()) return reply_parameter_error(p), true;
  switch (parameter) {
    case 4: servo_up_ = static_cast<uint16_t>(value); break;
    case 5: servo_down_ = static_cast<uint16_t>(value); break;
    case 10: servo_rate_up_ = servo_rate_down_ = static_cast<uint16_t>(value); break;
    case 11: servo_rate_up_ = static_cast<uint16_t>(value); break;
    case 12: servo_rate_down_ = static_cast<uint16_t>(value); break;
    default: break;  // solenoid, driver routing, S2 channels, alternate button: nothing to do here
  }
  reply_ok();
  return true;
}

bool Eibotboard::command_cu(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(-32768, 32767, true, value);
  if (!p.finish()) return reply_parameter_error(p), true;
  const bool boolean = value == 0 || value == 1;
  switch (parameter) {
    case 1:
      if (!boolean) return reply_error(EbbError::kInvalid, command_name_), true;
      ack_enabled_ = value == 1;
      break;
    case 4: {
      if (value < 1) return reply_error(EbbError::kInvalid, command_name_), true;
      fifo_depth_ = static_cast<uint32_t>(value > static_cast<int64_t>(kFifoCapacity) ? kFifoCapacity : value);
      break;
    }
    case 10:
      if (!boolean) return reply_error(EbbError::kInvalid, command_name_), true;
      // The reply is made half before and half after the switch, as on the EBB.
      if (!future_syntax_ && value == 1) {
        future_syntax_ = true;
        send("\n");
        return true;
      }
      if (future_syntax_ && value == 0) {
        future_syntax_ = false;
        send("CU");  // the future half; the legacy ending follows (its OK only while acks are on)
        send(ack_enabled_ ? "OK\r\n" : "\r\n");
        return true;
      }
      break;
    case 54:
      if (value != 0) return reply_error(EbbError::kInvalid, command_name_), true;  // no checksums here
      break;
    default:
      break;  // limit checks, LED, motor auto-enable, limit switches, thresholds: accepted
  }
  reply_ok();
  return true;
}

bool Eibotboard::command_qu(EbbParameters& p) {
  int64_t parameter = 0;
  p.integer(0, 255, true, parameter);
  if (!p.finish()) return reply_parameter_error(p), true;
  char data[32];
  TextWriter text(data, sizeof(data));
  text.text("QU,");
  switch (parameter) {
    case 2: text.unsigned_number(kFifoCapacity); break;
    case 3: text.unsigned_number(fifo_depth_); break;
    case 6: {
      const uint32_t waiting = moves_queued_ - moves_started_;
      if (waiting < 10) text.character('0');
      text.unsigned_number(waiting);
      break;
    }
    default: text.character('0'); break;
  }
  if (future_syntax_) {
    send(data);
    send("\n");
  } else {
    send(data);
    send(ack_enabled_ ? "\r\nOK\r\n" : "\r\n\r\n");
  }
  return true;
}

void Eibotboard::command_es(EbbParameters& p) {
  int64_t disable = 0;
  p.integer(0, 1, false, disable);
  if (!p.finish()) {
    reply_parameter_error(p);
    return;
  }
  const bool interrupted = frame_busy_ || moves_queued_ != moves_started_;
  controls_.push(disable == 1 ? Control::kStopDisable : Control::kStop);
  if (disable == 1) motors_enabled_[0] = motors_enabled_[1] = false;
  reply_data(interrupted ? "1" : "0", true, "\n\r");
}

void Eibotboard::query_motion() {
  const bool fifo = moves_queued_ != moves_started_;
  const bool executing = frame_busy_ || fifo;
  char data[24];
  TextWriter text(data, sizeof(data));
  if (command_name_[1] == 'M') {
    text.character(executing ? '1' : '0').character(',');
    text.character(frame_motor_moving_[0] ? '1' : '0').character(',');
    text.character(frame_motor_moving_[1] ? '1' : '0').character(',');
    text.character(fifo ? '1' : '0');
    if (future_syntax_) {
      reply_data(data, false);
    } else {
      send("QM,");
      send(data);
      send("\n\r");
    }
    return;
  }
  uint8_t status = 0;
  if (button_pressed_) status |= 0x20;
  if (frame_pen_up_) status |= 0x10;
  if (executing) status |= 0x08;
  if (frame_motor_moving_[0]) status |= 0x04;
  if (frame_motor_moving_[1]) status |= 0x02;
  if (fifo) status |= 0x01;
  button_pressed_ = false;
  static const char kHex[] = "0123456789ABCDEF";
  text.character(kHex[status >> 4]).character(kHex[status & 0x0F]);
  reply_data(data, false);
}

void Eibotboard::servo_now(uint16_t target, uint16_t rate) {
  pen_now_target_ = target;
  pen_now_rate_ = rate;
  controls_.push(Control::kPenUpNow);
}

}  // namespace stepdance
