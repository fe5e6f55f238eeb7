// Arc centre, radius and sweep of G2/G3 in both forms (centre offset IJK, radius R).
#pragma once

#include "stepdance/interfaces/gcode/grbl_error.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// Completes an arc Motion whose start_mm, end_mm and plane axes are set.
/// IJK form: offset_0/1_mm is the centre relative to the start; the end must lie on the circle
/// (within 0.005 mm, or 0.1 % of the radius up to 0.5 mm, as Grbl allows) else kInvalidTarget.
/// R form: radius_mm > 0 takes the short way, < 0 the long way; an end point equal to the start is
/// kInvalidTarget and a radius shorter than half the chord is kArcRadiusError.
/// A start equal to the end in IJK form is a full circle. Context: loop (pure function).
GrblError complete_arc_ijk(Motion& arc, bool clockwise, double offset_0_mm, double offset_1_mm);
GrblError complete_arc_radius(Motion& arc, bool clockwise, double radius_mm);

/// The box an arc sweeps through, machine mm, every axis: in its plane the two ends and each
/// point of the circle at 0°, 90°, 180° or 270° round the centre that the sweep passes (all four
/// for a turn or more); along the plane's normal and E, which move in proportion, the two ends.
/// It holds every chord end an ArcSegmenter makes of the arc, whatever the tolerance.
/// Context: any (pure function).
void arc_bounds_mm(const Motion& arc, double (&low_mm)[kAxisCount], double (&high_mm)[kAxisCount]);

/// Splits an arc into chords that stay within tolerance_mm of the true arc (sagitta), the last
/// point exactly at the arc's end. The axis along the plane normal and E move in proportion.
/// Context: any (pure; no state beyond the arc it was given).
class ArcSegmenter {
 public:
  /// Tolerances below 1 µm are raised to 1 µm; at most kMaxSegments chords are made.
  ArcSegmenter(const Motion& arc, double tolerance_mm);

  static constexpr uint32_t kMaxSegments = 1000000;

  /// Number of chords (≥ 1).
  uint32_t segment_count() const { return count_; }
  /// End point of chord k (1 ≤ k ≤ segment_count()), machine mm.
  void point_mm(uint32_t k, double (&out)[kAxisCount]) const;

 private:
  Motion arc_;
  uint32_t count_ = 1;
};

}  // namespace stepdance::gcode
