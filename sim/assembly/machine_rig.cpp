// MachineRig: the machine built from its board's socket models, when it is re-read as the motors
// step, and its drawing and summary.
#include "assembly/machine_rig.hpp"

#include <algorithm>
#include <filesystem>

#include "assembly/machine_drawing.hpp"
#include "kinds/machine_kind.hpp"
#include "output/png_page.hpp"
#include "output/svg_writer.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {
namespace {

/// The machine is re-read at least every this many frames even when no motor stepped, so the
/// pen follows the servo board (whose pulse changes every 24.85 ms).
constexpr uint32_t kIdleFramesPerMachineUpdate = 25;
/// A frame's last possible edge, after its start.
constexpr SimTime kFrameWireNs = SimTime{protocol::kFrameBitsUs} * kMicrosecond;

}  // namespace

bool MachineRig::build(const scenario::Scenario& scenario, BoardSet& boards, SimulationError& error) {
  if (!scenario.machine) return true;
  const scenario::MachineConfig& config = *scenario.machine;
  config_ = &config;
  pen_up_travel_ = scenario.output.pen_up_travel;
  BoardSlot& owner = boards.slot(config.board);
  const SocketModels sockets{[&owner](char port) { return owner.sockets[port - 'A'].stepper.get(); },
                             [&owner](char port) { return owner.sockets[port - 'A'].servo.get(); }};
  PenTraceSettings trace;
  trace.record_pen_up = scenario.output.pen_up_travel;
  machine_ = config.kind->build(config, sockets, trace);
  if (!machine_) {
    error = {SimulationError::kBadInput,
             scenario_place(scenario, config.line) + "the machine's motor sockets must hold steppers"};
    return false;
  }
  owner.board->on_frames_played([this](SimTime time) { after_frames(time); });
  return true;
}

void MachineRig::after_frames(SimTime frame_start_ns) {
  ++ticks_since_update_;
  if (!moved_ && ticks_since_update_ < kIdleFramesPerMachineUpdate) return;
  update(frame_start_ns + kFrameWireNs);
}

void MachineRig::update(SimTime time_ns) {
  time_ns_ = std::max(time_ns_, time_ns);
  machine_->update(time_ns_);
  moved_ = false;
  ticks_since_update_ = 0;
}

DrawingStyle MachineRig::drawing_now(std::vector<Stroke>& strokes) const {
  return machine_drawing(*machine_, *config_, pen_up_travel_, strokes);
}

std::string MachineRig::drawing_svg() const {
  if (!machine_) return {};
  std::vector<Stroke> strokes;
  const DrawingStyle style = drawing_now(strokes);
  return svg_document(strokes, style);
}

void MachineRig::write_drawings(const std::string& svg_path, const std::string& png_path, const PictureWriter* pictures,
                                double png_px_per_mm, std::vector<std::string>& files) const {
  const std::string png = pictures != nullptr ? png_path : std::string();
  if (!machine_ || (svg_path.empty() && png.empty())) return;
  std::vector<Stroke> strokes;
  const DrawingStyle style = drawing_now(strokes);
  for (const std::string& path : {svg_path, png}) {
    if (!path.empty()) std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  }
  if (!svg_path.empty()) {
    write_svg(svg_path, strokes, style);
    files.push_back(svg_path);
  }
  if (!png.empty()) {
    // A plotter's page was checked when the run was prepared; a page that is the drawing's
    // bounding box is only known now, so it is drawn at the resolution that fits, never refused.
    pictures->write_drawing(png, strokes, style, fitting_px_per_mm(style, png_px_per_mm));
    files.push_back(png);
  }
}

nlohmann::json MachineRig::summary() const {
  const MachineStats stats = machine_->stats();
  return {{"pen_mm", {machine_->pen_position().x_mm, machine_->pen_position().y_mm}},
          {"pen_down", machine_->pen_down()},
          {"strokes", stats.strokes},
          {"pen_down_mm", stats.pen_down_mm},
          {"pen_up_mm", stats.pen_up_mm},
          {"travel_excursions", stats.travel_excursions}};
}

}  // namespace stepdance::sim
