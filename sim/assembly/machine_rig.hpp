// The scenario's machine, built by its kind's row (kinds/) from one board's socket models, re-read
// as the motors step, and what it drew.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/board_set.hpp"
#include "assembly/simulation_options.hpp"
#include "models/machine.hpp"
#include "output/picture_writer.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Owns the machine (if the scenario has one) and decides when it is re-read: after every frame
/// in which a socket's model stepped, and at least every few frames when none did. Context:
/// host; build() before the run, update() from the run's events and at its end.
class MachineRig {
 public:
  /// The flag the socket feeders set when their model was fed pulses (BoardSet's `motion`).
  bool* motion_flag() { return &moved_; }
  /// Builds the machine `scenario` names on its board's sockets and listens to that board's
  /// frames; true without a machine. False (kBadInput) when its motor sockets lack steppers.
  bool build(const scenario::Scenario& scenario, BoardSet& boards, SimulationError& error);
  /// Brings the machine up to `time_ns` (never back in time). Context: a machine exists.
  void update(SimTime time_ns);
  /// The machine, or null.
  const Machine* machine() const { return machine_.get(); }

  /// The SVG document of the drawing as it stands now; "" without a machine.
  std::string drawing_svg() const;
  /// Writes the drawing to `svg_path` and, with `pictures`, to `png_path` ("" = not that one) at
  /// most `png_px_per_mm`; appends the paths written to `files`. Throws on a failed write.
  void write_drawings(const std::string& svg_path, const std::string& png_path, const PictureWriter* pictures,
                      double png_px_per_mm, std::vector<std::string>& files) const;
  /// The summary's "machine" entry: pen position and state, strokes, distances, excursions.
  nlohmann::json summary() const;

 private:
  void after_frames(SimTime frame_start_ns);
  /// The machine's strokes as drawn (shaded pieces, on the page's coordinates) and their style.
  DrawingStyle drawing_now(std::vector<Stroke>& strokes) const;

  const scenario::MachineConfig* config_ = nullptr;
  bool pen_up_travel_ = false;
  std::unique_ptr<Machine> machine_;
  bool moved_ = false;
  uint32_t ticks_since_update_ = 0;
  SimTime time_ns_ = 0;
};

}  // namespace stepdance::sim
