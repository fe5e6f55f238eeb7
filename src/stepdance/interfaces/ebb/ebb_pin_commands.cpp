// EBB pin commands: PD, PO and PI on the emulated ports, PC and PG accepted.
#include "stepdance/interfaces/ebb/ebb_commands.hpp"

namespace stepdance::ebb {

// Reads "Port,Pin": false (with the error reply) when either is missing or out of range.
// Port is a letter A–E and pin 0–7 on the EBB's PIC ports.
bool EbbCommands::read_pin(EbbParameters& p, int& port, int& pin) {
  char letter = 0;
  int64_t number = 0;
  p.letter(true, letter);
  p.integer(0, 255, true, number);
  if (p.error() != EbbError::kNone) return replies_.parameter_error(p), false;
  port = EbbPins::port_index(letter);
  pin = static_cast<int>(number);
  if (port < 0 || pin >= EbbPins::kPinsPerPort) return replies_.error(EbbError::kInvalid), false;
  return true;
}

// PD,Port,Pin,Direction: 1 input, 0 output, as on the PIC (TRIS register convention).
bool EbbCommands::command_pd(EbbParameters& p) {
  int port = 0, pin = 0;
  int64_t direction = 0;
  if (!read_pin(p, port, pin)) return true;
  p.integer(0, 1, true, direction);
  if (!p.finish()) return replies_.parameter_error(p), true;
  pins_.set_direction(port, pin, direction == 1);
  replies_.ok();
  return true;
}

bool EbbCommands::command_po(EbbParameters& p) {
  int port = 0, pin = 0;
  int64_t value = 0;
  if (!read_pin(p, port, pin)) return true;
  p.integer(0, 1, true, value);
  if (!p.finish()) return replies_.parameter_error(p), true;
  pins_.set_output(port, pin, value == 1);
  replies_.ok();
  return true;
}

// PI answers "PI,<value>" in both syntaxes, with no OK (legacy ends it CR LF).
bool EbbCommands::command_pi(EbbParameters& p) {
  int port = 0, pin = 0;
  if (!read_pin(p, port, pin)) return true;
  if (!p.finish()) return replies_.parameter_error(p), true;
  EbbDriverState driver;
  driver.motor_enabled[0] = queue_.motor_resolution(0) != 0;
  driver.motor_enabled[1] = queue_.motor_resolution(1) != 0;
  driver.microstep_mode = queue_.microstep_mode();
  driver.pen_up = queue_.pen_up();
  const char value[2] = {static_cast<char>('0' + pins_.read(port, pin, driver)), '\0'};
  if (!replies_.future_syntax()) replies_.send("PI,");
  replies_.data(value, false);
  return true;
}

// PC: pulse lengths and periods (ms) for RB0 … RB3; the first pair is required.
bool EbbCommands::command_pc(EbbParameters& p) {
  int64_t length = 0, period = 0;
  p.integer(0, 65535, true, length);
  p.integer(0, 65535, true, period);
  for (int pair = 1; pair < 4 && p.integer(0, 65535, false, length); ++pair) {
    if (!p.integer(0, 65535, false, period)) break;
  }
  if (!p.finish()) return replies_.parameter_error(p), true;
  replies_.ok();
  return true;
}

bool EbbCommands::command_pg(EbbParameters& p) {
  int64_t value = 0;
  p.integer(0, 1, true, value);
  if (!p.finish()) return replies_.parameter_error(p), true;
  replies_.ok();
  return true;
}

}  // namespace stepdance::ebb
