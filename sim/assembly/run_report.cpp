// Simulation results: the pen drawing (SVG; PNG through the picture writer) and the JSON summary.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <tuple>

#include "kinds/machine_kind.hpp"
#include "output/png_page.hpp"
#include "output/summary_writer.hpp"
#include "output/svg_writer.hpp"
#include "assembly/simulation.hpp"

namespace stepdance::sim {
namespace {

Stroke stroke_of(const Polyline& line, size_t from, size_t to, bool pen_down) {
  Stroke stroke;
  stroke.pen_down = pen_down;
  for (size_t i = from; i < to; ++i) stroke.points.push_back({line[i].x_mm, line[i].y_mm});
  return stroke;
}

// A pen-down polyline as one stroke per shade: each piece runs from its mark to the next one's
// point, so the pieces join.
void add_shaded(std::vector<Stroke>& strokes, const Polyline& line, const std::vector<ShadeMark>& marks) {
  if (marks.empty()) {
    strokes.push_back(stroke_of(line, 0, line.size(), true));
    return;
  }
  for (size_t i = 0; i < marks.size(); ++i) {
    const size_t end = i + 1 < marks.size() ? marks[i + 1].from_point + 1 : line.size();
    strokes.push_back(stroke_of(line, marks[i].from_point, end, true));
    strokes.back().shade = marks[i].shade;
  }
}

std::vector<Stroke> strokes_of(const Machine& machine) {
  std::vector<Stroke> strokes;
  for (const Polyline& line : machine.pen_up_moves()) strokes.push_back(stroke_of(line, 0, line.size(), false));
  const std::vector<Polyline>& lines = machine.strokes();
  const std::vector<std::vector<ShadeMark>>& marks = machine.shade_marks();
  for (size_t i = 0; i < lines.size(); ++i) add_shaded(strokes, lines[i], i < marks.size() ? marks[i] : std::vector<ShadeMark>{});
  return strokes;
}

// The colour scale spans the drawing's shades, and at least ±25 % around their middle, so the
// measuring noise of an even extrusion stays one colour.
void set_shade_scale(DrawingStyle& style, const std::vector<Stroke>& strokes) {
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const Stroke& stroke : strokes) {
    if (stroke.shade) low = std::min(low, *stroke.shade), high = std::max(high, *stroke.shade);
  }
  if (low > high) return;
  std::tie(style.shade_low, style.shade_high) = shade_scale_for(low, high);
}

// A machine with a fixed page (a CoreXY plotter's travel area) draws on it. Other machines have
// none: their page is the drawing's bounding box, moved so it starts at the page origin.
DrawingStyle page_for(const scenario::MachineConfig& machine, std::vector<Stroke>& strokes) {
  DrawingStyle style;
  if (const std::optional<TravelArea> area = machine.kind->page ? machine.kind->page(machine) : std::nullopt) {
    style.travel_width_mm = area->x_max_mm - area->x_min_mm;
    style.travel_height_mm = area->y_max_mm - area->y_min_mm;
    return style;
  }
  double min_x = std::numeric_limits<double>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (const Stroke& stroke : strokes) {
    for (const PointMm& point : stroke.points) {
      min_x = std::min(min_x, point.x), max_x = std::max(max_x, point.x);
      min_y = std::min(min_y, point.y), max_y = std::max(max_y, point.y);
    }
  }
  if (min_x > max_x) min_x = max_x = min_y = max_y = 0;
  for (Stroke& stroke : strokes) {
    for (PointMm& point : stroke.points) point = {point.x - min_x, point.y - min_y};
  }
  style.travel_width_mm = std::max(max_x - min_x, 10.0);
  style.travel_height_mm = std::max(max_y - min_y, 10.0);
  return style;
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

DrawingStyle Simulation::drawing_now(std::vector<Stroke>& strokes) const {
  strokes = strokes_of(*machine_);
  DrawingStyle style = page_for(*scenario_.machine, strokes);
  style.pen_up_travel = scenario_.output.pen_up_travel;
  set_shade_scale(style, strokes);
  style.shade_name = machine_->shade_name();
  return style;
}

std::string Simulation::drawing_svg() const {
  if (!machine_) return {};
  std::vector<Stroke> strokes;
  const DrawingStyle style = drawing_now(strokes);
  return svg_document(strokes, style);
}

void Simulation::write_drawings(SimulationReport& report) const {
  const std::string svg = output_path(scenario_.output.svg);
  const std::string png = options_.pictures ? output_path(scenario_.output.png) : std::string();
  if (!machine_ || (svg.empty() && png.empty())) return;
  std::vector<Stroke> strokes;
  const DrawingStyle style = drawing_now(strokes);
  for (const std::string& path : {svg, png}) {
    if (!path.empty()) std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  }
  if (!svg.empty()) {
    write_svg(svg, strokes, style);
    report.files.push_back(svg);
  }
  if (!png.empty()) {
    // A plotter's page was checked when the run was prepared; a page that is the drawing's
    // bounding box is only known now, so it is drawn at the resolution that fits, never refused.
    options_.pictures->write_drawing(png, strokes, style, fitting_px_per_mm(style, scenario_.output.png_px_per_mm));
    report.files.push_back(png);
  }
}

// Per board: frames run, faults and every block's named counters; per stepper socket: where
// the motor ended up.
void Simulation::add_board_extras(nlohmann::json& extra) const {
  nlohmann::json faults = nlohmann::json::object(), frames = nlohmann::json::object();
  nlohmann::json counters = nlohmann::json::object(), load = nlohmann::json::object();
  nlohmann::json motors = nlohmann::json::object(), i2c = nlohmann::json::object();
  nlohmann::json console = nlohmann::json::object(), warnings = nlohmann::json::object();
  for (const BoardSlot& slot : boards_) {
    // Each kind of warning the fault path tallied ("Eibotboard: overrun"), with its count.
    for (const SimBoard::BoardWarning& warning : slot.board->warnings()) {
      warnings[slot.config->name][warning.name] = warning.count;
    }
    // Console output that was dropped (nobody read a live terminal), when there was any.
    if (const uint64_t dropped = slot.board->console_dropped_bytes(); dropped > 0) {
      console[slot.config->name] = {{"dropped_unread_bytes", dropped}};
    }
    const StepdanceBoardStatsV1 stats = slot.board->stats();
    if (const SimBoard::I2cTiming& timing = slot.board->i2c_timing(); timing.transfers > 0) {
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
                                   {"count", stats.fault_count}, {"log", log}};
    }
    for (uint8_t port = 0; port < 4; ++port) {
      if (const StepperDriver* motor = slot.sockets[port].stepper.get()) {
        motors[slot.config->name + ":" + static_cast<char>('A' + port)] = {
            {"steps", motor->position_steps()}, {"forward", motor->forward_steps()},
            {"reverse", motor->reverse_steps()}, {"ignored_while_disabled", motor->ignored_steps()}};
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
  add_firmware_extras(extra);
}

// Per image board: its image and how it ran (instructions, the frame interrupt's cost).
void Simulation::add_firmware_extras(nlohmann::json& extra) const {
  nlohmann::json firmware = nlohmann::json::object();
  for (const BoardSlot& slot : boards_) {
    const BoardFirmware* program = slot.board->firmware();
    if (program == nullptr) continue;
    nlohmann::json& entry = firmware[slot.config->name] = {{"image", program->image_path()}};
    for (const auto& [name, value] : program->figures()) entry[name] = value;
  }
  if (!firmware.empty()) extra["firmware"] = firmware;
}

nlohmann::json Simulation::cable_extras() const {
  nlohmann::json cables = nlohmann::json::array();
  for (size_t i = 0; i < cables_.size(); ++i) {
    const scenario::CableConfig& config = scenario_.cables[i];
    const CableCounters& counters = cables_[i]->counters();
    cables.push_back({{"from", config.from.board + ":OUT_" + config.from.port},
                      {"to", config.to.board + ":IN_" + config.to.port},
                      {"pulses_in", counters.pulses_in},
                      {"pulses_passed", counters.pulses_passed},
                      {"pulses_removed", counters.pulses_removed},
                      {"pulses_merged", counters.pulses_merged},
                      {"glitches_injected", counters.glitches_injected},
                      {"glitches_skipped", counters.glitches_skipped}});
  }
  return cables;
}

nlohmann::json Simulation::machine_extra() const {
  const MachineStats stats = machine_->stats();
  return {{"pen_mm", {machine_->pen_position().x_mm, machine_->pen_position().y_mm}},
          {"pen_down", machine_->pen_down()},
          {"strokes", stats.strokes},
          {"pen_down_mm", stats.pen_down_mm},
          {"pen_up_mm", stats.pen_up_mm},
          {"travel_excursions", stats.travel_excursions}};
}

nlohmann::json Simulation::summary_extra() const {
  nlohmann::json extra = nlohmann::json::object();
  add_board_extras(extra);
  extra["cables"] = cable_extras();
  if (machine_) extra["machine"] = machine_extra();
  // A stopped run says so: its figures are those of the moment it stopped.
  if (sketch_stop_) {
    extra["stopped"] = {{"board", sketch_stop_->board},
                        {"entry", describe(sketch_stop_->entry)},
                        {"what", sketch_stop_->what},
                        {"time_s", to_seconds(sketch_stop_->time_ns)},
                        {"backtrace", sketch_stop_->backtrace}};
  } else if (interrupted_by_ != 0 && !options_.live) {
    extra["stopped"] = {{"what", interrupted_by_ == 15 ? "SIGTERM" : "SIGINT"}, {"time_s", to_seconds(scheduler_.now())}};
  }
  return extra;
}

std::vector<std::string> Simulation::warning_lines() const {
  std::vector<std::string> lines;
  for (const BoardSlot& slot : boards_) {
    for (const SimBoard::BoardWarning& warning : slot.board->warnings()) {
      std::string line = "[" + slot.config->name + "] warning ×" + std::to_string(warning.count) + ": " + warning.name;
      if (!warning.detail.empty()) line += " (first: " + warning.detail + ")";
      lines.push_back(line);
    }
  }
  return lines;
}

RunSummary Simulation::run_summary() const {
  RunSummary summary;
  summary.simulated_time = scheduler_.now();
  for (const BoardSlot& slot : boards_) {
    const StepdanceBoardStatsV1 stats = slot.board->stats();
    summary.boards[slot.config->name].frame_overruns = stats.frame_overruns;
    for (uint8_t port = 0; port < 4; ++port) {
      const std::string letter(1, static_cast<char>('A' + port));
      if (slot.board->output_claimed(port)) {
        PortSummary& out = summary.ports[slot.config->name + ":OUT_" + letter];
        out.pulses = slot.board->sent(port);
        out.carried = slot.board->port_counter("OutputPort", port, "carried");
      }
      if (slot.board->input_begun(port)) {
        PortSummary& in = summary.ports[slot.config->name + ":IN_" + letter];
        in.is_input = true;
        in.pulses = slot.board->received(port);
      }
    }
  }
  summary.extra = summary_extra();
  return summary;
}

std::string Simulation::summary_text() const { return sim::summary_text(run_summary()); }

void Simulation::write_summary_file(const SimulationReport& report) const {
  RunSummary summary = run_summary();
  summary.wall_time_s = report.wall_s;
  const std::string path = output_path(scenario_.output.summary);
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  write_summary(path, summary);
}

}  // namespace stepdance::sim
