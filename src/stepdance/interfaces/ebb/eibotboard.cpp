// Eibotboard: begin, line framing and flow control in the loop (on the link primitives), counters.
#include "stepdance/interfaces/ebb/eibotboard.hpp"

#include <math.h>
#include <string.h>

namespace stepdance {

Eibotboard::Eibotboard() = default;

// Two stages: commands are parsed and answered in the loop, moves are executed in the frame (as the
// EBB's own 25 kHz ISR executes its FIFO).
Status Eibotboard::begin_stream(ByteStream&) {
  BlockPort* ports[8] = {&output_x, &output_y, &output_z,         &output_e,
                         &output_r, &output_t, &output_parameter, &output_duration};
  for (int i = 0; i < 8; ++i) {
    state_[i] = 0;
    ports[i]->begin(&state_[i], BLOCKPORT_OUTPUT, this);
  }
  queue_.begin(pen_.up_position());
  const Status frame = register_in(Stage::kPreChannel);
  if (frame != Status::kOk) return frame;
  return register_in(Stage::kLoop);
}

// mm per EBB motor step, where an EBB step is a 1/16 microstep (the AxiDraw moves 80 per mm at 1/16,
// ebb-protocol.md). Checked at start against the channels' own steps/mm (eibotboard_wiring.cpp).
void Eibotboard::set_ratio_xy(float output_units_mm, float input_units_steps) {
  if (input_units_steps == 0.0f || !isfinite(output_units_mm)) return;
  mm_per_sixteenth_ = static_cast<double>(output_units_mm) / input_units_steps;
  ratio_xy_given_ = true;
}

void Eibotboard::set_ratio_z(float output_units_mm, float input_units_steps) {
  if (input_units_steps != 0.0f && isfinite(output_units_mm)) z_units_per_step_ = output_units_mm / input_units_steps;
}

// ---- the link -------------------------------------------------------------------------------------

// Loop context: replies are flushed before and after reading so the reply ring is as empty as
// possible when a command needs room.
void Eibotboard::loop() {
  ByteStream* stream = link_stream();
  if (stream == nullptr) return;
  replies_.flush(*stream);
  read_lines(*stream);
  replies_.flush(*stream);
}

// Flow control the EBB way: a motion command that finds the FIFO full is not answered and not
// consumed; the client, waiting for its OK, sends nothing more, and the line is retried next pass.
// A command is executed only when its largest reply surely fits, so no reply is ever dropped.
void Eibotboard::read_lines(ByteStream& stream) {
  for (int lines = 0; lines < 16; ++lines) {
    // Reads up to the end of one line; a motion command that finds the FIFO full stays there.
    if (!lines_.pump(stream)) return;
    if (!replies_.reserve_largest()) return;
    execute_line();
    if (lines_.ready()) return;  // waiting for room in the FIFO: read nothing more (flow control)
  }
}

// A line longer than the EBB's buffer gets the EBB's own "!3 Err: RX Buffer overrun" (ebb-protocol.md:
// at most 256 bytes per command), never a truncated command.
void Eibotboard::execute_line() {
  if (lines_.overflowed()) {
    replies_.set_command("");
    replies_.error(ebb::EbbError::kOverrun);
    finish_line();
    return;
  }
  const size_t name_length = take_command_name();
  replies_.set_command(command_name_);
  ebb::EbbParameters parameters(lines_.text() + name_length, lines_.length() - name_length);
  if (!commands_.execute(command_name_, parameters)) {  // waits for FIFO room; the line stays
    if (!waiting_for_room_) ++fifo_full_waits_;
    waiting_for_room_ = true;
    return;
  }
  finish_line();
}

// The command is one or two characters up to the first comma, case-insensitive: folded to upper case
// here, the form the command table lists.
// Returns the name's length. The line holds no NUL before its end (control bytes are dropped).
size_t Eibotboard::take_command_name() {
  const char* line = lines_.text();
  size_t name_length = 0;
  for (; name_length < 2 && line[name_length] != '\0' && line[name_length] != ','; ++name_length) {
    const char c = line[name_length];
    command_name_[name_length] = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }
  command_name_[name_length] = '\0';
  return name_length;
}

void Eibotboard::finish_line() {
  waiting_for_room_ = false;
  ++commands_done_;
  lines_.take();
}

void Eibotboard::report_counters(CounterSink& sink) const {
  sink.counter("commands", commands_done_);
  sink.counter("fifo_full_waits", fifo_full_waits_);
  sink.counter("moves_started", queue_.moves_started());
  sink.counter("errors_replied", replies_.errors());
  sink.counter("replies_dropped", replies_.dropped());
  sink.counter("alarm_stops", queue_.alarm_stops());
  sink.counter("moves_stretched", queue_.moves_stretched());
}

bool Eibotboard::is_idle() const { return queue_.idle(); }

}  // namespace stepdance
