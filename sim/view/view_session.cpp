// ViewSession: the view protocol's messages (hello, update, error, drawing) and its inputs.
#include "view/view_session.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinds/device_kind.hpp"
#include "kinds/machine_kind.hpp"
#include "output/drawing.hpp"
#include "scenario/names.hpp"
#include "scenario/value_range.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;

/// The longest turn span and click hold a page may ask for (ms).
constexpr double kMaxInputSpanMs = 60000;

json error_message(const std::string& text) { return json{{"type", "error"}, {"message", text}}; }

const char* control_name(PageControl::Type type) {
  switch (type) {
    case PageControl::Type::kKnob: return "knob";
    case PageControl::Type::kSlider: return "slider";
    case PageControl::Type::kButton: return "button";
    case PageControl::Type::kKnobWithButton: return "knob_with_button";
    case PageControl::Type::kScreen: return "screen";
    case PageControl::Type::kNone: break;
  }
  return "none";
}

json point_json(const PenPoint& point) { return json::array({point.x_mm, point.y_mm}); }

/// `hello`'s "parts" of a device or machine: the update fields its kind gives (none: no key).
void add_declared_parts(json& entry, const std::vector<std::string_view>& parts) {
  if (parts.empty()) return;
  json fields = json::array();
  for (std::string_view part : parts) fields.push_back(std::string(part));
  entry["parts"] = std::move(fields);
}

/// The number at `key` if it is one, else nothing.
std::optional<double> number_at(const json& message, const char* key) {
  const auto found = message.find(key);
  if (found == message.end() || !found->is_number()) return std::nullopt;
  return found->get<double>();
}

std::optional<std::string> string_at(const json& message, const char* key) {
  const auto found = message.find(key);
  if (found == message.end() || !found->is_string()) return std::nullopt;
  return found->get<std::string>();
}

std::optional<scenario::ActionType> action_named(const std::string& name) {
  using scenario::ActionType;
  if (name == "turn") return ActionType::kTurn;
  if (name == "press") return ActionType::kPress;
  if (name == "release") return ActionType::kRelease;
  if (name == "click") return ActionType::kClick;
  if (name == "set") return ActionType::kSet;
  return std::nullopt;
}

/// The SVG's colour scale for the machine's shades so far, if it has any.
std::optional<std::pair<double, double>> shade_scale(const Machine& machine) {
  if (machine.shade_name()[0] == '\0') return std::nullopt;
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const std::vector<ShadeMark>& marks : machine.shade_marks()) {
    for (const ShadeMark& mark : marks) low = std::min(low, mark.shade), high = std::max(high, mark.shade);
  }
  if (low > high) return std::nullopt;
  return shade_scale_for(low, high);
}

}  // namespace

ViewSession::ViewSession(Simulation& simulation, RunControl& control) : simulation_(simulation), control_(control) {
  for (const scenario::BoardConfig& board : simulation_.scenario().boards) {
    for (const scenario::SocketConfig& socket : board.sockets) {
      if (const StepperDriver* stepper = simulation_.stepper(board.name, socket.port)) {
        motors_.push_back({board.name, socket.port, stepper->position_steps()});
      }
    }
  }
  last_update_sim_ = simulation_.now();
}

std::string ViewSession::hello() const {
  const scenario::Scenario& scenario = simulation_.scenario();
  json boards = json::array();
  for (const scenario::BoardConfig& board : scenario.boards) {
    json devices = json::array();
    for (const scenario::DeviceConfig& device : scenario.devices) {
      if (device.board != board.name) continue;
      const PageControl& control = device.kind->control;
      json entry = {{"name", device.name},
                    {"kind", std::string(device.kind->name)},
                    {"connector", scenario::connector_name(device.connector)},
                    {"control",
                     {{"type", control_name(control.type)},
                      {"low", control.low},
                      {"high", control.high},
                      {"step", control.step},
                      {"unit", control.unit}}}};
      if (const SimDevice* model = simulation_.device(device.name)) model->describe_page_control(entry["control"]);
      add_declared_parts(entry, device.kind->page_parts);
      devices.push_back(std::move(entry));
    }
    json motors = json::array();
    for (const MotorState& motor : motors_) {
      if (motor.board == board.name) motors.push_back(std::string(1, motor.port));
    }
    boards.push_back(
        {{"name", board.name}, {"module", board.module->scenario_name}, {"motors", motors}, {"devices", devices}});
  }
  json machine = nullptr;
  if (scenario.machine && simulation_.machine() != nullptr) {
    const DrawingStyle style;
    machine = {{"kind", std::string(scenario.machine->kind->name)},
               {"margin_mm", style.margin_mm},
               {"pen_width_mm", style.pen_width_mm},
               {"page_mm", nullptr},
               {"travel_mm", nullptr},
               {"shade_name", simulation_.machine()->shade_name()}};
    const MachineKind& kind = *scenario.machine->kind;
    add_declared_parts(machine, kind.page_parts);
    if (const auto page = kind.page ? kind.page(*scenario.machine) : std::nullopt) {
      machine["page_mm"] = {page->x_min_mm, page->x_max_mm, page->y_min_mm, page->y_max_mm};
    }
    if (const TravelMonitor* travel = simulation_.machine()->travel()) {
      const TravelArea& area = travel->area();
      machine["travel_mm"] = {area.x_min_mm, area.x_max_mm, area.y_min_mm, area.y_max_mm};
    }
  }
  return json{{"type", "hello"},
              {"version", kProtocolVersion},
              {"t_s", to_seconds(simulation_.now())},
              {"duration_s", to_seconds(simulation_.duration())},
              {"machine", machine},
              {"boards", boards},
              {"run", {{"paused", control_.paused}, {"speed", control_.speed}}},
              {"limits",
               {{"max_input_bytes", kMaxInputBytes},
                {"updates_per_s", kMaxUpdatesPerSecond},
                {"resolution_mm", kDisplayResolutionMm}}}}
      .dump();
}

bool ViewSession::due(double wall_s) const {
  return !last_update_wall_s_ || wall_s - *last_update_wall_s_ >= 1.0 / kMaxUpdatesPerSecond;
}

void ViewSession::hold_back(double wall_s) {
  ++held_back_;
  last_update_wall_s_ = wall_s;
}

std::optional<std::string> ViewSession::update(double wall_s) {
  if (!due(wall_s)) return std::nullopt;
  last_update_wall_s_ = wall_s;
  std::string message = make_update(false);
  if (message.empty()) return std::nullopt;
  return message;
}

std::string ViewSession::update_now() { return make_update(true); }

void ViewSession::start_over() {
  sent_.forget();
  strokes_ = StrokeStream();
}

void ViewSession::end_run() { run_ended_ = true; }

bool ViewSession::add_if_changed(json& message, const char* field, const std::string& key, json value) {
  if (!sent_.changed(key, value)) return false;
  if (!message.contains(field)) message[field] = json::array();
  message[field].push_back(std::move(value));
  return true;
}

bool ViewSession::add_run_parts(json& message) {
  const bool ended = run_ended_ || simulation_.stopped() || simulation_.now() >= simulation_.duration();
  json run = {
      {"paused", control_.paused}, {"speed", control_.speed}, {"stopped", simulation_.stopped()}, {"ended", ended}};
  if (!sent_.changed("run", run)) return false;
  message["run"] = std::move(run);
  return true;
}

bool ViewSession::add_machine_parts(json& message) {
  const Machine* machine = simulation_.machine();
  if (machine == nullptr) return false;
  bool changed = false;
  json pen = {
      {"x_mm", machine->pen_position().x_mm}, {"y_mm", machine->pen_position().y_mm}, {"down", machine->pen_down()}};
  if (sent_.changed("pen", pen)) message["pen"] = std::move(pen), changed = true;
  json parts = json::array();
  for (const StrokePart& part : strokes_.take(machine->strokes(), machine->shade_marks(), kMaxPointsPerUpdate)) {
    json points = json::array();
    for (const PenPoint& point : part.points) points.push_back(point_json(point));
    json entry = {{"i", part.index}, {"from", part.from}, {"points", std::move(points)}};
    if (!part.shades.empty()) {
      json shades = json::array();
      for (const ShadeStart& start : part.shades) shades.push_back(json::array({start.point, start.shade}));
      entry["shades"] = std::move(shades);
    }
    parts.push_back(std::move(entry));
  }
  if (!parts.empty()) message["strokes"] = std::move(parts), changed = true;
  PageParts own;
  const auto& config = simulation_.scenario().machine;
  if (config && config->kind->add_page_parts != nullptr) config->kind->add_page_parts(*machine, simulation_.now(), own);
  for (PagePart& part : own) {
    if (sent_.changed("machine " + part.field, part.value)) message[part.field] = std::move(part.value), changed = true;
  }
  if (const auto scale = shade_scale(*machine)) {
    json pair = json::array({scale->first, scale->second});
    if (sent_.changed("shade_scale", pair)) message["shade_scale"] = std::move(pair), changed = true;
  }
  return changed;
}

bool ViewSession::add_travel_part(json& message) {
  const Machine* machine = simulation_.machine();
  const TravelMonitor* travel = machine != nullptr ? machine->travel() : nullptr;
  if (travel == nullptr) return false;
  json first_points = json::array();
  for (const TravelExcursion& excursion : travel->excursions()) {
    first_points.push_back(
        {{"t_s", to_seconds(excursion.start)}, {"x_mm", excursion.first.x_mm}, {"y_mm", excursion.first.y_mm}});
  }
  json part = {{"outside", travel->outside()},
               {"excursions", travel->excursion_count()},
               {"first_points", std::move(first_points)}};
  if (!sent_.changed("travel", part)) return false;
  message["travel"] = std::move(part);
  return true;
}

void ViewSession::update_motor_rates(double dt_s) {
  for (MotorState& motor : motors_) {
    const int64_t steps = simulation_.stepper(motor.board, motor.port)->position_steps();
    // No simulated time since the last update (paused, or twice at one instant): the rate stands.
    if (dt_s > 0) motor.rate_steps_per_s = static_cast<double>(steps - motor.last_steps) / dt_s;
    motor.last_steps = steps;
  }
}

json ViewSession::board_state_json(const std::string& name) const {
  const SimBoard* board = simulation_.board(name);
  const StepdanceBoardStatsV1 stats = board->stats();
  json entry = {{"name", name},
                {"frames", stats.frames},
                {"load_average_percent", nullptr},
                {"load_peak_percent", nullptr},
                {"fault", nullptr}};
  if (stats.load_frames > 0 && stats.load_budget_cycles > 0) {
    const double budget = stats.load_budget_cycles;
    entry["load_average_percent"] =
        100.0 * static_cast<double>(stats.load_total_cycles) / static_cast<double>(stats.load_frames) / budget;
    entry["load_peak_percent"] = 100.0 * stats.load_peak_cycles / budget;
  }
  if (stats.fault_reason != 0) {
    entry["fault"] = {{"reason", stats.fault_name ? stats.fault_name : ""},
                      {"count", stats.fault_count},
                      {"detail", stats.fault_detail ? stats.fault_detail : ""}};
  }
  json warnings = json::array();
  for (const SimBoard::BoardWarning& warning : board->warnings()) {
    warnings.push_back({{"name", warning.name}, {"count", warning.count}, {"detail", warning.detail}});
  }
  entry["warnings"] = std::move(warnings);
  return entry;
}

bool ViewSession::add_board_parts(json& message) {
  const SimTime now = simulation_.now();
  update_motor_rates(to_seconds(now - last_update_sim_));
  last_update_sim_ = now;
  bool changed = false;
  for (const MotorState& motor : motors_) {
    const std::string port(1, motor.port);
    changed |= add_if_changed(message, "motors", "motor " + motor.board + " " + port,
                              {{"board", motor.board},
                               {"port", port},
                               {"steps", motor.last_steps},
                               {"rate_steps_per_s", motor.rate_steps_per_s}});
  }
  for (const scenario::BoardConfig& config : simulation_.scenario().boards) {
    changed |= add_if_changed(message, "boards", "board " + config.name, board_state_json(config.name));
  }
  return changed;
}

bool ViewSession::add_device_parts(json& message) {
  bool changed = false;
  for (const scenario::DeviceConfig& device : simulation_.scenario().devices) {
    const SimDevice* model = simulation_.device(device.name);
    if (model == nullptr) continue;
    PageParts parts;
    model->add_page_parts(device.name, simulation_.now(), parts);
    // Each part is sent on its own when it changes: keyed by the device, its field and its place.
    for (size_t k = 0; k < parts.size(); ++k) {
      const std::string key = "device " + device.name + " " + parts[k].field + " " + std::to_string(k);
      changed |= add_if_changed(message, parts[k].field.c_str(), key, std::move(parts[k].value));
    }
  }
  return changed;
}

bool ViewSession::add_console_part(json& message) {
  json console = json::array();
  for (auto& [board, text] : console_) {
    if (text.empty()) continue;
    console.push_back({{"board", board}, {"text", text}, {"dropped_bytes", console_dropped_[board]}});
    text.clear();
  }
  if (console.empty()) return false;
  message["console"] = std::move(console);
  return true;
}

std::string ViewSession::make_update(bool always) {
  const double t_s = to_seconds(simulation_.now());
  json message = {{"type", "update"}, {"t_s", t_s}};
  bool changed = sent_.changed("t_s", t_s);
  changed |= add_run_parts(message);
  changed |= add_machine_parts(message);
  changed |= add_travel_part(message);
  changed |= add_board_parts(message);
  changed |= add_device_parts(message);
  changed |= add_console_part(message);
  if (!changed && !always) return {};
  ++updates_made_;
  return message.dump(-1, ' ', false, json::error_handler_t::replace);
}

void ViewSession::console_output(const std::string& board, const uint8_t* data, size_t length) {
  std::string& text = console_[board];
  text.append(reinterpret_cast<const char*>(data), length);
  if (text.size() > kMaxConsoleBytesPerUpdate) {
    console_dropped_[board] += text.size() - kMaxConsoleBytesPerUpdate;
    text.erase(0, text.size() - kMaxConsoleBytesPerUpdate);
  }
}

uint64_t ViewSession::console_dropped_bytes() const {
  uint64_t total = 0;
  for (const auto& [board, dropped] : console_dropped_) total += dropped;
  return total;
}

std::vector<std::string> ViewSession::receive(std::string_view text) {
  if (text.size() > kMaxInputBytes) {
    return {error_message("message of " + std::to_string(text.size()) + " bytes refused: at most " +
                          std::to_string(kMaxInputBytes))
                .dump()};
  }
  const json message = json::parse(text, nullptr, false);
  if (message.is_discarded() || !message.is_object()) {
    return {error_message("not a JSON object").dump()};
  }
  const std::optional<std::string> type = string_at(message, "type");
  if (!type) return {error_message("no \"type\"").dump()};
  if (*type == "save") {
    return {
        json{{"type", "drawing"}, {"t_s", to_seconds(simulation_.now())}, {"svg", simulation_.drawing_svg()}}.dump()};
  }
  if (*type == "hello") {
    start_over();  // the page starts its drawing afresh from a hello
    return {hello()};
  }
  std::string problem;
  if (*type == "input") {
    problem = apply_input(message);
  } else if (*type == "console") {
    problem = apply_console(message);
  } else if (*type == "run") {
    problem = apply_run(message);
  } else {
    problem = "unknown message type \"" + *type + "\"";
  }
  if (problem.empty()) return {};
  return {error_message(problem).dump(-1, ' ', false, json::error_handler_t::replace)};
}

std::string ViewSession::apply_input(const json& message) {
  const auto name = string_at(message, "device");
  const auto action_text = string_at(message, "action");
  if (!name || !action_text) return "input: needs \"device\" and \"action\" strings";
  const scenario::DeviceConfig* config = nullptr;
  for (const scenario::DeviceConfig& device : simulation_.scenario().devices) {
    if (device.name == *name) config = &device;
  }
  SimDevice* device = simulation_.device(*name);
  if (config == nullptr || device == nullptr) return "input: no device named \"" + *name + "\"";
  const auto type = action_named(*action_text);
  if (!type || !config->kind->takes(*type)) {
    return "input: " + std::string(config->kind->with_article) + " does not take \"" + *action_text + "\"";
  }
  scenario::Action action;
  action.type = *type;
  action.target = *name;
  action.time = simulation_.now();
  if (*type == scenario::ActionType::kTurn) {
    const auto counts = number_at(message, "counts");
    const double limit = static_cast<double>(scenario::ranges::kEncoderCounts.high);
    if (!counts || *counts != std::floor(*counts) || std::fabs(*counts) > limit) {
      return "input: turn needs \"counts\", a whole number in [-" +
             std::to_string(scenario::ranges::kEncoderCounts.high) + ", " +
             std::to_string(scenario::ranges::kEncoderCounts.high) + "]";
    }
    action.counts = static_cast<int64_t>(*counts);
    const double over_ms = number_at(message, "over_ms").value_or(0);
    if (!(over_ms >= 0 && over_ms <= kMaxInputSpanMs)) return "input: \"over_ms\" must be in [0, 60000]";
    action.over = static_cast<SimTime>(over_ms * 1e6 + 0.5);
  } else if (*type == scenario::ActionType::kClick) {
    const double hold_ms = number_at(message, "hold_ms").value_or(100);
    if (!(hold_ms > 0 && hold_ms <= kMaxInputSpanMs)) return "input: \"hold_ms\" must be in (0, 60000]";
    action.hold = static_cast<SimTime>(hold_ms * 1e6 + 0.5);
  } else if (*type == scenario::ActionType::kSet) {
    const auto position = number_at(message, "position");
    const PageControl& control = config->kind->control;
    if (!position || !(*position >= control.low && *position <= control.high)) {
      return "input: set needs \"position\" in [" + std::to_string(control.low) + ", " + std::to_string(control.high) +
             "]";
    }
    action.position = *position;
  }
  device->schedule(action);
  return {};
}

std::string ViewSession::apply_console(const json& message) {
  const auto board_name = string_at(message, "board");
  const auto text = string_at(message, "text");
  if (!board_name || !text) return "console: needs \"board\" and \"text\" strings";
  SimBoard* board = simulation_.board(*board_name);
  if (board == nullptr) return "console: no board named \"" + *board_name + "\"";
  if (text->size() > board->console().input_room()) return "console: the board's input buffer is full; try again";
  board->console().send(*text);
  return {};
}

std::string ViewSession::apply_run(const json& message) {
  const auto action = string_at(message, "action");
  if (action == std::optional<std::string>("pause")) {
    control_.paused = true;
  } else if (action == std::optional<std::string>("resume")) {
    control_.paused = false;
  } else if (action == std::optional<std::string>("speed")) {
    const auto found = message.find("speed");
    if (found != message.end() && found->is_string() && *found == "max") {
      control_.speed = 0;
    } else if (found != message.end() && found->is_number() && (*found == 1 || *found == 10)) {
      control_.speed = found->get<double>();
    } else {
      return "run: \"speed\" must be 1, 10 or \"max\"";
    }
  } else {
    return "run: \"action\" must be \"pause\", \"resume\" or \"speed\"";
  }
  return {};
}

}  // namespace stepdance::sim::view
