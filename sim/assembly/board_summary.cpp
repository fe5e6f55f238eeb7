// The boards' part of a run's summary and warnings.
#include "assembly/board_summary.hpp"

namespace stepdance::sim {
namespace {

// Per image board: its image and how it ran (instructions, the frame interrupt's cost).
void add_firmware_extras(const BoardSet& boards, nlohmann::json& extra) {
  nlohmann::json firmware = nlohmann::json::object();
  for (const BoardSlot& slot : boards.slots()) {
    const BoardFirmware* program = slot.board->firmware();
    if (program == nullptr) continue;
    nlohmann::json& entry = firmware[slot.config->name] = {{"image", program->image_path()}};
    for (const auto& [name, value] : program->figures()) entry[name] = value;
  }
  if (!firmware.empty()) extra["firmware"] = firmware;
}

// The frame interrupt's cycles as a share of the frame's budget: the average over the measured
// frames and the peak, in percent. Precondition: load_frames and load_budget_cycles non-zero.
nlohmann::json cpu_load_of(const StepdanceBoardStatsV1& stats) {
  const double budget = stats.load_budget_cycles;
  return {{"average_percent",
           100.0 * static_cast<double>(stats.load_total_cycles) / static_cast<double>(stats.load_frames) / budget},
          {"peak_percent", 100.0 * stats.load_peak_cycles / budget}};
}

}  // namespace

// Per board: frames run, faults and every block's named counters; per stepper socket: where
// the motor ended up.
void add_board_extras(const BoardSet& boards, nlohmann::json& extra) {
  nlohmann::json faults = nlohmann::json::object(), frames = nlohmann::json::object();
  nlohmann::json counters = nlohmann::json::object(), load = nlohmann::json::object();
  nlohmann::json motors = nlohmann::json::object(), i2c = nlohmann::json::object();
  nlohmann::json console = nlohmann::json::object(), warnings = nlohmann::json::object();
  for (const BoardSlot& slot : boards.slots()) {
    // Each kind of warning the fault path tallied ("Eibotboard: overrun"), with its count.
    for (const SimBoard::BoardWarning& warning : slot.board->warnings()) {
      warnings[slot.config->name][warning.name] = warning.count;
    }
    // Console output that was dropped (nobody read a live terminal), when there was any.
    if (const uint64_t dropped = slot.board->console().dropped_bytes(); dropped > 0) {
      console[slot.config->name] = {{"dropped_unread_bytes", dropped}};
    }
    const StepdanceBoardStatsV1 stats = slot.board->stats();
    if (const I2cTiming& timing = slot.board->i2c().timing(); timing.transfers > 0) {
      i2c[slot.config->name] = {{"transfers", timing.transfers},
                                {"longest_loop_pass_us", static_cast<double>(timing.max_loop_pass_ns) / 1000.0},
                                {"loop_passes_with_i2c", timing.loop_passes_with_i2c},
                                {"wire_time_s", to_seconds(timing.total_ns)}};
    }
    frames[slot.config->name] = stats.frames;
    if (stats.load_frames > 0 && stats.load_budget_cycles > 0) load[slot.config->name] = cpu_load_of(stats);
    nlohmann::json& board_counters = counters[slot.config->name] = nlohmann::json::object();
    for (const SimBoard::BlockCounter& counter : slot.board->counters()) {
      board_counters[counter.block][counter.name] = counter.value;
    }
    if (stats.fault_reason != 0) {
      nlohmann::json log = nlohmann::json::array();
      for (const BoardFault& fault : slot.board->faults()) {
        log.push_back({{"time_s", to_seconds(fault.time_ns)}, {"fault", fault.text}});
      }
      faults[slot.config->name] = {{"first", std::string(stats.fault_name) + ": " + stats.fault_detail},
                                   {"count", stats.fault_count},
                                   {"log", log}};
    }
    for (uint8_t port = 0; port < 4; ++port) {
      if (const StepperDriver* motor = slot.sockets[port].stepper.get()) {
        motors[slot.config->name + ":" + static_cast<char>('A' + port)] = {
            {"steps", motor->position_steps()},
            {"forward", motor->forward_steps()},
            {"reverse", motor->reverse_steps()},
            {"ignored_while_disabled", motor->ignored_steps()}};
      }
    }
  }
  extra["faults"] = faults;
  extra["warnings"] = warnings;
  extra["frames"] = frames;
  if (!console.empty()) extra["console"] = console;
  extra["motors"] = motors;
  extra["counters"] = counters;
  extra["cpu_load"] = load;
  if (!i2c.empty()) extra["i2c"] = i2c;
  add_firmware_extras(boards, extra);
}

void add_port_summaries(const BoardSet& boards, RunSummary& summary) {
  for (const BoardSlot& slot : boards.slots()) {
    const StepdanceBoardStatsV1 stats = slot.board->stats();
    summary.boards[slot.config->name].frame_overruns = stats.frame_overruns;
    for (uint8_t port = 0; port < 4; ++port) {
      const std::string letter(1, static_cast<char>('A' + port));
      if (slot.board->ports().output_claimed(port)) {
        PortSummary& out = summary.ports[slot.config->name + ":OUT_" + letter];
        out.pulses = slot.board->ports().sent(port);
        out.carried = slot.board->port_counter("OutputPort", port, "carried");
      }
      if (slot.board->input_begun(port)) {
        PortSummary& in = summary.ports[slot.config->name + ":IN_" + letter];
        in.is_input = true;
        in.pulses = slot.board->ports().received(port);
      }
    }
  }
}

std::vector<std::string> board_warning_lines(const BoardSet& boards) {
  std::vector<std::string> lines;
  for (const BoardSlot& slot : boards.slots()) {
    for (const SimBoard::BoardWarning& warning : slot.board->warnings()) {
      std::string line = "[" + slot.config->name + "] warning ×" + std::to_string(warning.count) + ": " + warning.name;
      if (!warning.detail.empty()) line += " (first: " + warning.detail + ")";
      lines.push_back(line);
    }
  }
  return lines;
}

}  // namespace stepdance::sim
