// EBB command set: the command table and the dispatch every command line goes through.
#include "stepdance/interfaces/ebb/ebb_commands.hpp"

#include "stepdance/core/fault.hpp"

namespace stepdance::ebb {

const link::Command<EbbCommands::Handler>* EbbCommands::find(const char* name) {
  constexpr uint8_t kMotors = kMovesMotors;
  constexpr uint8_t kBare = kNoParameters;
  // Two commands a row in the reference's groups; clang-format would put one a row (and this
  // function past the 39-line limit of scripts/check-interfaces-structure.sh).
  // clang-format off
  static constexpr auto kTable = link::make_command_table<Handler>(
      {
          // Motion, queued in the FIFO
          {"SM", {&EbbCommands::command_sm, kMotors}}, {"XM", {&EbbCommands::command_xm, kMotors}},
          {"LM", {&EbbCommands::command_lm, kMotors}}, {"LT", {&EbbCommands::command_lt, kMotors}},
          {"HM", {&EbbCommands::command_hm, kMotors}}, {"EM", {&EbbCommands::command_em, 0}},
          {"SP", {&EbbCommands::command_sp, 0}},       {"S2", {&EbbCommands::command_s2, 0}},
          {"TP", {&EbbCommands::command_tp, 0}},
          // Settings and queries, answered at once
          {"SC", {&EbbCommands::command_sc, 0}},       {"CU", {&EbbCommands::command_cu, 0}},
          {"QU", {&EbbCommands::command_qu, 0}},       {"ES", {&EbbCommands::command_es, 0}},
          {"SR", {&EbbCommands::command_sr, 0}},       {"SL", {&EbbCommands::command_sl, 0}},
          {"QL", {&EbbCommands::command_ql, 0}},       {"ST", {&EbbCommands::command_st, 0}},
          {"V", {&EbbCommands::command_v, kBare}},     {"QM", {&EbbCommands::command_qm, kBare}},
          {"QG", {&EbbCommands::command_qg, kBare}},   {"QT", {&EbbCommands::command_qt, kBare}},
          {"QS", {&EbbCommands::command_qs, kBare}},   {"CS", {&EbbCommands::command_cs, kBare}},
          {"QP", {&EbbCommands::command_qp, kBare}},   {"QB", {&EbbCommands::command_qb, kBare}},
          {"QC", {&EbbCommands::command_qc, kBare}},   {"QE", {&EbbCommands::command_qe, kBare}},
          {"QR", {&EbbCommands::command_qr, kBare}},   {"R", {&EbbCommands::command_r, kBare}},
          // Pins
          {"PD", {&EbbCommands::command_pd, 0}},       {"PO", {&EbbCommands::command_po, 0}},
          {"PI", {&EbbCommands::command_pi, 0}},       {"PC", {&EbbCommands::command_pc, 0}},
          {"PG", {&EbbCommands::command_pg, 0}},
      });
  // clang-format on
  static_assert(kTable.names_unique(), "an EBB command is listed twice");
  return kTable.find(name);
}

// Unknown commands get an error, never silence and never a bare OK (ebb-protocol.md "Framing"; the
// original answered OK to everything it did not know). Returns false only when a command must wait
// for FIFO room.
bool EbbCommands::execute(const char* name, EbbParameters& p) {
  const link::Command<Handler>* command = find(name);
  if (command == nullptr) {
    replies_.error(EbbError::kUnknownCommand);
    return true;
  }
  // Motor moves are refused while an alarm is raised (the fault path); pen commands still run.
  if ((command->handler.flags & kMovesMotors) != 0 && alarm_active()) {
    replies_.error(EbbError::kAlarm);
    return true;
  }
  if ((command->handler.flags & kNoParameters) != 0 && !p.finish()) return replies_.parameter_error(p), true;
  return (this->*command->handler.run)(p);
}

// The FIFO depth a client sees is CU,4's (EbbMotionQueue); a command that finds it full is not
// answered and waits (USB flow control).
bool EbbCommands::queue_and_reply(const EbbMove& move) {
  if (!queue_.push(move, replies_.command())) return false;
  replies_.ok();
  return true;
}

}  // namespace stepdance::ebb
