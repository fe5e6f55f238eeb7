// Eibotboard: line framing and flow control in the loop; FIFO execution and outputs in the frame.
#include "stepdance/interfaces/ebb/eibotboard.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/core/file_storage.hpp"

namespace stepdance {

using ebb::EbbMove;
using ebb::EbbParameters;

namespace {

constexpr uint8_t kCarriageReturn = 0x0D;
constexpr uint8_t kLineFeed = 0x0A;
constexpr double kServoNeutralSteps = 1500.0;  // servo-board steps (µs) at the neutral 1.5 ms
constexpr double kServoUnitsPerStep = 12.0;     // 1/12 µs per servo-board step
constexpr int kZeroTimeMovesPerFrame = 8;       // bounds how many EM/pen entries one frame applies

/// True for the moves that turn the motors (not pen, delay or enable moves).
bool moves_motors(const EbbMove& move) {
  return move.kind == EbbMove::Kind::kSteps || move.kind == EbbMove::Kind::kTime || move.kind == EbbMove::Kind::kHome;
}

}  // namespace

Eibotboard::Eibotboard() = default;

Status Eibotboard::begin() { return begin_stream(hal::console()); }

Status Eibotboard::begin_stream(ByteStream& stream) {
  stream_ = &stream;
  BlockPort* ports[8] = {&output_x, &output_y, &output_z, &output_e, &output_r, &output_t,
                         &output_parameter, &output_duration};
  for (int i = 0; i < 8; ++i) {
    state_[i] = 0;
    ports[i]->begin(&state_[i], BLOCKPORT_OUTPUT, this);
  }
  executor_.reset(servo_up_);
  const Status frame = register_in(Stage::kPreChannel);
  if (frame != Status::kOk) return frame;
  return register_in(Stage::kLoop);
}

void Eibotboard::set_ratio_xy(float output_units_mm, float input_units_steps) {
  if (input_units_steps != 0.0f && isfinite(output_units_mm)) mm_per_sixteenth_ = output_units_mm / input_units_steps;
}

void Eibotboard::set_ratio_z(float output_units_mm, float input_units_steps) {
  if (input_units_steps != 0.0f && isfinite(output_units_mm)) z_units_per_step_ = output_units_mm / input_units_steps;
}

// ---- the link -------------------------------------------------------------------------------------

void Eibotboard::loop() {
  if (stream_ == nullptr) return;
  flush_replies();
  read_lines();
  flush_replies();
}

void Eibotboard::read_lines() {
  for (int lines = 0; lines < 16; ++lines) {
    if (!line_ready_) {
      // Read up to the end of one line; a motion command that finds the FIFO full stays here.
      bool complete = false;
      while (!complete) {
        const int value = stream_->read_byte();
        if (value < 0) return;
        complete = take_byte(static_cast<uint8_t>(value));
      }
      line_ready_ = true;
    }
    if (reply_space() < kLargestReplyBytes) return;
    execute_line();
    if (line_ready_) return;  // waiting for room in the FIFO: read nothing more (flow control)
  }
}

// Collects one byte; true when a line ended. CR or LF ends a line; the other one right after it
// (CR LF, LF CR) and empty lines are ignored, control bytes are dropped, as the EBB does.
bool Eibotboard::take_byte(uint8_t byte) {
  if (byte == kCarriageReturn || byte == kLineFeed) {
    const bool ends = !last_was_terminator_ && (line_length_ > 0 || line_overrun_);
    last_was_terminator_ = true;
    return ends;
  }
  last_was_terminator_ = false;
  if (byte < 0x20 || byte > 0x7E) return false;
  if (line_length_ == kMaxLineBytes) {
    line_overrun_ = true;
    return false;
  }
  line_[line_length_++] = static_cast<char>(byte);
  return false;
}

void Eibotboard::execute_line() {
  if (line_overrun_) {
    command_name_[0] = '\0';
    reply_error(ebb::EbbError::kOverrun, "");
  } else {
    line_[line_length_] = '\0';
    // The command is one or two characters up to the first comma, case-insensitive.
    size_t name_length = 0;
    while (name_length < line_length_ && name_length < 2 && line_[name_length] != ',') {
      const char c = line_[name_length];
      command_name_[name_length] = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
      ++name_length;
    }
    command_name_[name_length] = '\0';
    EbbParameters parameters(line_ + name_length, line_length_ - name_length);
    if (!dispatch(command_name_, parameters)) {  // waits for FIFO room; the line stays
      if (!waiting_for_room_) ++fifo_full_waits_;
      waiting_for_room_ = true;
      return;
    }
  }
  waiting_for_room_ = false;
  ++commands_done_;
  line_length_ = 0;
  line_overrun_ = false;
  line_ready_ = false;
}

void Eibotboard::report_counters(CounterSink& sink) const {
  sink.counter("commands", commands_done_);
  sink.counter("fifo_full_waits", fifo_full_waits_);
  sink.counter("moves_started", moves_started_);
  sink.counter("errors_replied", errors_replied_);
  sink.counter("replies_dropped", replies_dropped_);
  sink.counter("alarm_stops", alarm_stops_);
}

void Eibotboard::send(const char* text) {
  for (const char* c = text; *c != '\0'; ++c) {
    if (reply_count_ == kReplyBufferBytes) {
      ++replies_dropped_;
      return;
    }
    replies_[(reply_head_ + reply_count_) % kReplyBufferBytes] = *c;
    ++reply_count_;
  }
}

void Eibotboard::flush_replies() {
  while (reply_count_ > 0) {
    const size_t contiguous = kReplyBufferBytes - reply_head_;
    const size_t chunk = reply_count_ < contiguous ? reply_count_ : contiguous;
    const size_t written = stream_->write_bytes(reinterpret_cast<const uint8_t*>(replies_ + reply_head_), chunk);
    reply_head_ = (reply_head_ + written) % kReplyBufferBytes;
    reply_count_ -= written;
    if (written < chunk) return;  // the host reads slowly: the rest waits
  }
}

bool Eibotboard::is_idle() const {
  return moves_queued_ == moves_started_ && controls_.empty() && !frame_busy_ && frame_servo_settled_;
}

bool Eibotboard::queue(const EbbMove& move) {
  const uint32_t waiting = moves_queued_ - moves_started_;
  if (waiting >= fifo_depth_ || fifo_.push(move) != Status::kOk) return false;
  moves_queued_ = moves_queued_ + 1;
  return true;
}

// ---- the frame --------------------------------------------------------------------------------------

void Eibotboard::run() {
  apply_controls();
  if (alarm_active()) stop_motion_for_alarm();
  if (!executor_.busy()) load_next_move();
  // The EBB's own 40 µs tick, whatever our frame period: a tick when 40 µs of frames have passed
  // (every frame at 40 µs, every 4th at 10 µs, 5 ticks in 8 frames at 25 µs).
  tick_time_us_ += frame_period_us();
  if (tick_time_us_ >= ebb::kTickPeriodUs) {
    tick_time_us_ -= ebb::kTickPeriodUs;
    if (executor_.tick()) {
      ++move_ticks_done_;
    } else if (!executor_.busy()) {
      move_ticks_done_ = 0;
    }
  }
  frame_busy_ = executor_.busy();
  frame_motor_moving_[0] = executor_.motor_moving(0);
  frame_motor_moving_[1] = executor_.motor_moving(1);
  frame_global_steps_[0] = executor_.global_steps(0);
  frame_global_steps_[1] = executor_.global_steps(1);
  frame_pen_up_ = executor_.pen_up();
  frame_servo_settled_ = executor_.servo_settled();
  for (int motor = 0; motor < 2; ++motor) {
    frame_motor_resolution_[motor] = static_cast<uint8_t>(executor_.motor_enabled(motor) ? 16 >> (executor_.microstep_mode() - 1) : 0);
  }
  update_outputs();
}

void Eibotboard::apply_controls() {
  Control control;
  while (controls_.pop(control) == Status::kOk) {
    switch (control) {
      case Control::kStop:
      case Control::kStopDisable: {
        executor_.stop();
        EbbMove discard;
        while (fifo_.pop(discard) == Status::kOk) moves_started_ = moves_started_ + 1;
        if (control == Control::kStopDisable) {
          EbbMove off;
          off.kind = EbbMove::Kind::kEnable;
          off.microstep_mode = 0;
          off.enable[0] = off.enable[1] = false;
          executor_.start(off);
        }
        break;
      }
      case Control::kClearSteps:
        executor_.clear_global_steps();
        break;
      case Control::kPenUpNow:
        executor_.servo_now(pen_now_target_, pen_now_rate_, true);
        break;
      case Control::kReset: {
        executor_.stop();
        EbbMove discard;
        while (fifo_.pop(discard) == Status::kOk) moves_started_ = moves_started_ + 1;
        executor_.reset(servo_up_);
        break;
      }
    }
  }
}

// An alarm on the fault path stops the motors at once, as ES does (EBB moves carry no
// deceleration of their own); pen, delay and enable moves go on, so the client can still lift the pen.
void Eibotboard::stop_motion_for_alarm() {
  if (!executor_.motor_moving(0) && !executor_.motor_moving(1)) return;
  executor_.stop();
  alarm_stops_ = alarm_stops_ + 1;
}

void Eibotboard::load_next_move() {
  for (int i = 0; i < kZeroTimeMovesPerFrame; ++i) {
    EbbMove move;
    if (fifo_.pop(move) != Status::kOk) return;
    moves_started_ = moves_started_ + 1;
    if (alarm_active() && moves_motors(move)) {  // queued before the loop saw the alarm
      alarm_stops_ = alarm_stops_ + 1;
      continue;
    }
    move_ticks_done_ = 0;
    move_duration_s_ = move_duration_s(move);
    executor_.start(move);
    if (executor_.busy()) return;  // it takes time: tick it this frame
  }
}

double Eibotboard::move_duration_s(const EbbMove& move) const {
  switch (move.kind) {
    case EbbMove::Kind::kSteps: {
      // The longer axis: steps·2^31 = rate·T + accel·T²/2, solved for T (ticks).
      double longest = 0.0;
      for (int axis = 0; axis < 2; ++axis) {
        const double distance = static_cast<double>(move.steps[axis]) * ebb::kStepThreshold;
        const double rate = static_cast<double>(move.rate[axis]);
        const double accel = static_cast<double>(move.accel[axis]);
        double ticks = 0.0;
        if (accel == 0.0) {
          ticks = rate > 0.0 ? distance / rate : 0.0;
        } else {
          const double discriminant = rate * rate + 2.0 * accel * distance;
          ticks = discriminant > 0.0 ? (-rate + sqrt(discriminant)) / accel : 0.0;
        }
        if (ticks > longest) longest = ticks;
      }
      return longest / ebb::kTicksPerSecond;
    }
    case EbbMove::Kind::kHome:
      return 0.0;  // known only when it starts
    default:
      return static_cast<double>(move.ticks) / ebb::kTicksPerSecond;
  }
}

void Eibotboard::update_outputs() {
  const double m1 = static_cast<double>(executor_.position_sixteenths(0)) * mm_per_sixteenth_;
  const double m2 = static_cast<double>(executor_.position_sixteenths(1)) * mm_per_sixteenth_;
  const bool core_xy = kinematics_ == EBB_KINEMATICS_COREXY;
  const double values[3] = {
      core_xy ? 0.5 * (m1 + m2) : m1,
      core_xy ? 0.5 * (m1 - m2) : m2,
      (executor_.servo_position() / kServoUnitsPerStep - kServoNeutralSteps) * z_units_per_step_,
  };
  BlockPort* ports[3] = {&output_x, &output_y, &output_z};
  for (int i = 0; i < 3; ++i) {
    if (values[i] == last_output_[i]) continue;  // unchanged: leave the port (and any reset) alone
    last_output_[i] = values[i];
    ports[i]->set(ports[i]->convert_world_to_block_units(values[i]));
    ports[i]->push();
  }
  const double duration = move_duration_s_;
  const double done = duration > 0.0 ? (move_ticks_done_ / static_cast<double>(ebb::kTicksPerSecond)) / duration : 1.0;
  output_parameter.set(executor_.busy() ? (done < 1.0 ? done : 1.0) : 1.0);
  output_parameter.push();
  output_duration.set(duration);
  output_duration.push();
}

}  // namespace stepdance
