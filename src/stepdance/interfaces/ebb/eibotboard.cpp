// Eibotboard: begin, line framing and flow control in the loop, the reply ring, counters.
#include "stepdance/interfaces/ebb/eibotboard.hpp"

#include <math.h>
#include <string.h>

#include "stepdance/core/file_storage.hpp"

namespace stepdance {

using ebb::EbbParameters;

namespace {

constexpr uint8_t kCarriageReturn = 0x0D;
constexpr uint8_t kLineFeed = 0x0A;

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
    finish_line();
    return;
  }
  line_[line_length_] = '\0';
  take_command_name();
  const size_t name_length = strlen(command_name_);
  EbbParameters parameters(line_ + name_length, line_length_ - name_length);
  if (!dispatch(command_name_, parameters)) {  // waits for FIFO room; the line stays
    if (!waiting_for_room_) ++fifo_full_waits_;
    waiting_for_room_ = true;
    return;
  }
  finish_line();
}

// The command is one or two characters up to the first comma, case-insensitive.
void Eibotboard::take_command_name() {
  size_t name_length = 0;
  while (name_length < line_length_ && name_length < 2 && line_[name_length] != ',') {
    const char c = line_[name_length];
    command_name_[name_length] = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    ++name_length;
  }
  command_name_[name_length] = '\0';
}

void Eibotboard::finish_line() {
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

}  // namespace stepdance
