// Travel monitor: counts and remembers the times a machine leaves its usable area.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"
#include "models/pen_trace.hpp"

namespace stepdance::sim {

/// A rectangle of allowed positions, in mm (bounds included).
struct TravelArea {
  double x_min_mm = 0;
  double x_max_mm = 0;
  double y_min_mm = 0;
  double y_max_mm = 0;
  /// How far past a bound an axis may be before it counts as an excursion: the machine's
  /// resolution (one microstep), so a motor stepping on its own past the edge is not one (mm, ≥ 0).
  double tolerance_mm = 0;
};

/// One stretch of time spent outside the area.
struct TravelExcursion {
  /// First sample outside (ns).
  SimTime start = 0;
  /// First sample back inside (ns), or −1 while still outside.
  SimTime end = -1;
  /// Position at the first sample outside.
  PenPoint first{};
  /// Position farthest from the area.
  PenPoint farthest{};
  /// Distance from `farthest` to the area (mm).
  double overshoot_mm = 0;
};

/// Watches positions sample by sample. Every move from inside to outside (more than the area's
/// tolerance past a bound on either axis) starts an excursion; the first `max_remembered`
/// excursions are kept in detail and all are counted. Overshoots are measured from the area itself.
class TravelMonitor {
 public:
  explicit TravelMonitor(const TravelArea& area, size_t max_remembered = 64);

  /// Checks the position at `time`.
  void observe(SimTime time, const PenPoint& position);

  const TravelArea& area() const { return area_; }
  /// Whether the last observed position was outside.
  bool outside() const { return outside_; }
  /// Number of excursions so far (including one in progress).
  uint64_t excursion_count() const { return count_; }
  /// The first excursions, in order.
  const std::vector<TravelExcursion>& excursions() const { return excursions_; }
  /// Largest distance outside the area seen so far in an excursion (mm).
  double max_overshoot_mm() const { return max_overshoot_mm_; }

  /// Distance (mm) from `position` to the area; 0 inside or on the edge.
  double overshoot_mm(const PenPoint& position) const;
  /// Whether `position` is more than the tolerance past a bound on either axis.
  bool beyond_tolerance(const PenPoint& position) const;

 private:
  TravelArea area_;
  size_t max_remembered_;
  bool outside_ = false;
  uint64_t count_ = 0;
  double max_overshoot_mm_ = 0;
  std::vector<TravelExcursion> excursions_;
};

}  // namespace stepdance::sim
