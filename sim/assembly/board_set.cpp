// BoardSet: sketches → boards (each checked against its scenario module), and the driver
// sockets → stepper and servo models.
#include "assembly/board_set.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>

#include "assembly/step_feeder.hpp"
#include "board/loader/board_library.hpp"

namespace stepdance::sim {
namespace {

ServoBuild servo_build(scenario::ServoBuild build) {
  return build == scenario::ServoBuild::k180deg ? ServoBuild::k180deg : ServoBuild::k90deg;
}

SdCardSettings sd_card_settings(const scenario::SdCardConfig& config) {
  SdCardSettings settings;
  settings.write_kb_per_s = config.write_kb_per_s;
  settings.read_kb_per_s = config.read_kb_per_s;
  settings.stall_every_kb = config.stall_every_kb;
  settings.stall = static_cast<SimTime>(config.stall_ms * 1e6 + 0.5);
  settings.fail_after_bytes = static_cast<uint64_t>(config.fail_after_kb * 1000.0 + 0.5);
  return settings;
}

/// Every file the boards' compilers read, and every image a board runs, as inputs no output may
/// replace (output_plan.hpp).
std::vector<RunInput> compiled_inputs(const scenario::Scenario& scenario, const std::vector<SketchBuild>& builds,
                                      const std::vector<bool>& runs_image) {
  std::vector<RunInput> inputs;
  for (size_t i = 0; i < builds.size(); ++i) {
    const std::string& board = scenario.boards[i].name;
    const std::string what = runs_image[i] ? "the firmware image board '" + board + "' runs"
                                           : "a file the sketch of board '" + board + "' includes";
    for (const std::string& file : builds[i].inputs) inputs.push_back({file, what});
  }
  return inputs;
}

/// "" when `board` is the module the scenario says, else why not: the scenario's `module` must
/// be the board the sketch selects with its #define.
std::string module_mismatch(const scenario::BoardConfig& config, const SimBoard& board) {
  const BoardDefinition& selected = board.definition();
  if (config.module == &selected) return "";
  return "board '" + config.name + "' is a " + config.module->name + " in the scenario, but its sketch selects the " +
         selected.name + " (#define " + selected.sketch_macro + ")";
}

}  // namespace

// Every sketch is built first, and the outputs checked against every file the compilers read,
// before any board library is loaded (loading runs the sketch's global constructors). A board
// that runs a firmware image compiles nothing.
bool BoardSet::build(const scenario::Scenario& scenario, const std::string& storage_directory,
                     const std::vector<PlannedOutput>& outputs, std::function<void(const SketchStop&)> on_stop,
                     SimulationError& error) {
  on_stop_ = std::move(on_stop);
  for (const auto& [name, image] : options_.images) {
    if (scenario.board(name) == nullptr) {
      error = {SimulationError::kBadInput,
               "--image " + name + "=" + image + ": the scenario has no board '" + name + "'"};
      return false;
    }
  }
  std::vector<SketchBuild> builds;
  std::vector<bool> runs_image;
  if (!build_sketches(scenario, builds, runs_image, error)) return false;
  if (std::string conflicts = output_conflicts_text(outputs, compiled_inputs(scenario, builds, runs_image));
      !conflicts.empty()) {
    error = {SimulationError::kBadInput, std::move(conflicts)};
    return false;
  }
  slots_.reserve(scenario.boards.size());
  for (size_t index = 0; index < scenario.boards.size(); ++index) {
    if (!add_board(scenario, scenario.boards[index], builds[index], storage_directory, error)) return false;
  }
  return true;
}

// Loads and attaches one board, checks its module, hooks its console and stops, fills its sockets.
bool BoardSet::add_board(const scenario::Scenario& scenario, const scenario::BoardConfig& config,
                         const SketchBuild& build, const std::string& storage_directory, SimulationError& error) {
  std::unique_ptr<SimBoard> board = make_board(scenario, config, build, storage_directory, error);
  if (!board) return false;
  slots_.push_back(BoardSlot{&config, std::move(board), {}});
  BoardSlot& slot = slots_.back();
  std::string attach_error;
  if (!slot.board->attach(attach_error)) {
    error = {SimulationError::kFailure, attach_error};
    return false;
  }
  if (const std::string mismatch = module_mismatch(config, *slot.board); !mismatch.empty()) {
    error = {SimulationError::kBadInput, scenario_place(scenario, config.line) + mismatch};
    return false;
  }
  slot.board->console().on_line([this, &config](const std::string& line) {
    if (options_.console) options_.console(config.name, line);
  });
  slot.board->on_sketch_stop([this](const SketchStop& stop) { on_stop_(stop); });
  fill_sockets(slot);
  return true;
}

// Builds each board's sketch, or notes the image it runs instead (an image board's only input).
bool BoardSet::build_sketches(const scenario::Scenario& scenario, std::vector<SketchBuild>& builds,
                              std::vector<bool>& runs_image, SimulationError& error) const {
  for (const scenario::BoardConfig& config : scenario.boards) {
    runs_image.push_back(!image_of(config).empty());
    if (runs_image.back()) {
      SketchBuild nothing_compiled;
      nothing_compiled.inputs.push_back(std::filesystem::absolute(image_of(config)).lexically_normal().string());
      builds.push_back(std::move(nothing_compiled));
      continue;
    }
    if (!options_.boards) {
      error = {SimulationError::kFailure, "no board source: this simulation cannot compile or load sketches"};
      return false;
    }
    builds.push_back(options_.boards->build(config.sketch));
    const SketchBuild& build = builds.back();
    if (!build.ok) {
      error = {SimulationError::kBadInput,
               scenario_place(scenario, config.line) + "board '" + config.name + "': " + build.error};
      return false;
    }
    if (!build.diagnostics.empty() && options_.build_diagnostics)
      options_.build_diagnostics(config.sketch, build.diagnostics);
  }
  return true;
}

std::string BoardSet::image_of(const scenario::BoardConfig& config) const {
  const auto named = options_.images.find(config.name);
  return named != options_.images.end() ? named->second : config.image;
}

std::unique_ptr<SimBoard> BoardSet::make_board(const scenario::Scenario& scenario, const scenario::BoardConfig& config,
                                               const SketchBuild& build, const std::string& storage_directory,
                                               SimulationError& error) const {
  BoardOptions board_options;
  board_options.name = config.name;
  board_options.frame_phase_ns = config.frame_phase_ns.value_or(SimTime{config.frame_phase_us} * kMicrosecond);
  board_options.khz_phase_ns = config.khz_phase_ns;
  board_options.encoder_sample_phase_ns = config.encoder_sample_phase_ns;
  board_options.loop_period_ns = config.loop_period_us * kMicrosecond;
  board_options.storage_dir = (std::filesystem::path(storage_directory) / (config.name + ".sd")).string();
  board_options.sd_card = sd_card_settings(config.sd_card);
  board_options.board_source = options_.boards.get();
  if (!image_of(config).empty()) return load_image(scenario, config, board_options, error);
  std::string load_error;
  auto library = BoardLibrary::load(build.library_path, load_error);
  if (!library) {
    error = {SimulationError::kFailure, load_error};
    return nullptr;
  }
  return std::make_unique<SimBoard>(scheduler_, board_options, std::move(library));
}

std::unique_ptr<SimBoard> BoardSet::load_image(const scenario::Scenario& scenario, const scenario::BoardConfig& config,
                                               const BoardOptions& board_options, SimulationError& error) const {
  if (!options_.firmware) {
    error = {SimulationError::kBadInput, scenario_place(scenario, config.line) + "board '" + config.name +
                                             "': this simulator cannot run firmware images (built without sim/image)"};
    return nullptr;
  }
  std::string load_error;
  auto firmware = options_.firmware->load(image_of(config), *config.module, scheduler_, load_error);
  if (!firmware) {
    error = {SimulationError::kBadInput,
             scenario_place(scenario, config.line) + "board '" + config.name + "': " + load_error};
    return nullptr;
  }
  return std::make_unique<SimBoard>(scheduler_, board_options, std::move(firmware), *config.module);
}

// Each populated socket gets its model, fed by the port's STEP/DIR; a stepper also follows its
// socket's ENABLE pin (active low, disabled until the sketch drives it).
void BoardSet::fill_sockets(BoardSlot& slot) {
  const BoardDefinition& definition = slot.board->definition();
  for (const scenario::SocketConfig& config : slot.config->sockets) {
    const uint8_t port = static_cast<uint8_t>(config.port - 'A');
    BoardSocket& socket = slot.sockets[port];
    if (config.device == scenario::SocketDevice::kStepper) {
      StepperDriverSettings settings;
      settings.microsteps = config.microsteps;
      settings.full_steps_per_rev = config.full_steps_per_rev;
      settings.reversed = config.reversed;
      const uint8_t enable_pin = definition.output_ports[port].enable;
      settings.enabled = enable_pin == kNoPin;  // a socket without an ENABLE line is always on
      socket.stepper = std::make_unique<StepperDriver>(settings);
      socket.feeder = std::make_unique<StepFeeder<StepperDriver>>(*socket.stepper, motion_);
      StepperDriver* stepper = socket.stepper.get();
      if (enable_pin != kNoPin) {
        slot.board->wire(terminal::OutputPin{enable_pin},
                         [stepper](SimTime, bool level, bool driven) { stepper->set_enabled(driven && !level); });
      }
    } else {
      socket.servo = std::make_unique<ServoBoard>(servo_build(config.build), 0);
      socket.feeder = std::make_unique<StepFeeder<ServoBoard>>(*socket.servo, motion_);
    }
    slot.board->wire(terminal::OutputPort{port}, socket.feeder.get());
  }
}

// ---- the run and lookups ---------------------------------------------------------------------------

SimBoard* BoardSet::board(const std::string& name) const {
  const BoardSlot* found = find(name);
  return found != nullptr ? found->board.get() : nullptr;
}

BoardSlot& BoardSet::slot(const std::string& name) { return const_cast<BoardSlot&>(*find(name)); }

const BoardSlot* BoardSet::find(const std::string& name) const {
  for (const BoardSlot& slot : slots_) {
    if (slot.config->name == name) return &slot;
  }
  return nullptr;
}

const StepperDriver* BoardSet::stepper(const std::string& board, char port) const {
  const BoardSlot* found = find(board);
  if (found == nullptr || port < 'A' || port > 'D') return nullptr;
  return found->sockets[port - 'A'].stepper.get();
}

const ServoBoard* BoardSet::servo(const std::string& board, char port) const {
  const BoardSlot* found = find(board);
  if (found == nullptr || port < 'A' || port > 'D') return nullptr;
  return found->sockets[port - 'A'].servo.get();
}

void BoardSet::set_end_time(SimTime end_ns) {
  for (BoardSlot& slot : slots_) slot.board->set_end_time(end_ns);
}

void BoardSet::power_on(SimTime end_ns) {
  for (BoardSlot& slot : slots_) {
    slot.board->set_end_time(end_ns);
    slot.board->power_on(slot.config->power_on_ns.value_or(0));
  }
}

void BoardSet::flush_console_lines() {
  for (BoardSlot& slot : slots_) slot.board->console().flush_line();
}

void BoardSet::add_storage_violations(std::vector<ExpectationResult>& results) const {
  for (const BoardSlot& slot : slots_) {
    const uint64_t calls = slot.board->storage_calls_in_isr();
    if (calls == 0) continue;
    results.push_back({false, "board '" + slot.config->name + "': the sketch touched the SD card " +
                                  std::to_string(calls) +
                                  " times from the frame or kilohertz interrupt (storage is loop-only)"});
  }
}

}  // namespace stepdance::sim
