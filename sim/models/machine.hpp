// Machine: the common interface of the simulated machines (motor positions in, pen on paper out).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/sim_time.hpp"
#include "models/pen_trace.hpp"
#include "models/travel_monitor.hpp"

namespace stepdance::sim {

/// Machine axes (limit switches watch x, y and z; kE is a printer's extruder, mm of filament).
enum class MachineAxis { kX, kY, kZ, kE };

/// Totals of a machine run.
struct MachineStats {
  /// update() calls, and how many of them found the pen somewhere new.
  uint64_t updates = 0;
  uint64_t moves = 0;
  /// Pen-down strokes started.
  uint64_t strokes = 0;
  /// Path length with the pen down / up (mm).
  double pen_down_mm = 0;
  double pen_up_mm = 0;
  /// Times the machine left its travel area (0 when it has none).
  uint64_t travel_excursions = 0;
};

/// A machine bound to the driver models that move it. The owner calls update(t) whenever the
/// motors may have moved (e.g. after each frame's edges): the machine reads the models at t,
/// computes the pen, records strokes and checks the travel area. Bound models must outlive it.
class Machine {
 public:
  virtual ~Machine() = default;
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  /// Reads the bound models at `time` (ns) and records the pen there.
  void update(SimTime time);

  /// Pen position on the paper (mm) and pen state at the last update.
  PenPoint pen_position() const { return pen_; }
  bool pen_down() const { return down_; }
  /// Position (mm) along a machine axis at the last update, or nothing if the machine lacks it.
  virtual std::optional<double> axis_mm(MachineAxis axis) const = 0;

  /// Pen-down strokes and (if enabled) pen-up moves so far.
  const std::vector<Polyline>& strokes() const { return trace_.strokes(); }
  const std::vector<Polyline>& pen_up_moves() const { return trace_.pen_up_moves(); }
  /// Shade marks of each pen-down stroke (see PenTrace::record); what a shade measures is the
  /// machine's: shade_name() says it, empty when the machine shades nothing.
  const std::vector<std::vector<ShadeMark>>& shade_marks() const { return trace_.shade_marks(); }
  virtual const char* shade_name() const { return ""; }
  const PenTrace& trace() const { return trace_; }
  /// The travel area monitor, or null if the machine has no travel area.
  const TravelMonitor* travel() const { return travel_ ? &*travel_ : nullptr; }
  MachineStats stats() const;

 protected:
  /// What a machine reads from its models at one instant.
  struct Sample {
    PenPoint pen;
    bool down = false;
    /// The machine's measure along the path from here on, if it has one (see shade_name()).
    std::optional<double> shade;
  };
  Machine(const PenTraceSettings& trace, const std::optional<TravelArea>& travel);
  /// Reads the bound models at `time`; also updates the machine's own axis state.
  virtual Sample sample(SimTime time) = 0;
  /// Where the pen is before the first update (limit switches read it from power-on).
  void set_power_on_pen(PenPoint pen) { pen_ = pen; }
  /// x and y: the pen's position at the last update; any other axis: none. For machines whose
  /// x and y are the pen's (axis_mm() adds the axes a machine has besides).
  std::optional<double> pen_axis_mm(MachineAxis axis) const;

 private:
  PenTrace trace_;
  std::optional<TravelMonitor> travel_;
  PenPoint pen_{};
  bool down_ = false;
  uint64_t updates_ = 0;
};

}  // namespace stepdance::sim
