// Pen trace: the pen's path split into pen-down strokes (and optional pen-up moves) as compact polylines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace stepdance::sim {

/// A point on the paper, in mm.
struct PenPoint {
  double x_mm = 0;
  double y_mm = 0;
};

inline bool operator==(const PenPoint& a, const PenPoint& b) { return a.x_mm == b.x_mm && a.y_mm == b.y_mm; }
inline bool operator!=(const PenPoint& a, const PenPoint& b) { return !(a == b); }

/// Points joined by straight segments.
using Polyline = std::vector<PenPoint>;

/// From point `from_point` of a stroke on (to the next mark or the stroke's end) the stroke has
/// this shade: a value the machine measures along its path, in the machine's own unit (a
/// printer: mm of filament per mm of toolpath).
struct ShadeMark {
  size_t from_point = 0;
  double shade = 0;
};

/// How closely the stored polylines follow the pen.
struct PenTraceSettings {
  /// Every sampled pen position lies within this distance (mm) of the stored polyline. The default
  /// absorbs CoreXY stair-stepping (0.00625 mm at 80 steps/mm) and is far below a pen line's width.
  double tolerance_mm = 0.01;
  /// Also keep the pen-up moves.
  bool record_pen_up = false;
};

/// Records pen samples. A stroke starts whenever the pen goes down, at the pen's position then;
/// it ends when the pen lifts. Each new position extends the current polyline: its last point
/// always is the latest position, and a point is dropped when every sample it stood for stays
/// within the tolerance of the straight segment that replaces it (so collinear runs and tiny
/// moves collapse). Unchanged positions add nothing.
class PenTrace {
 public:
  explicit PenTrace(const PenTraceSettings& settings = {});

  /// Records the pen at `position` with the pen `down`. The move from the previous sample to
  /// `position` belongs to the previous pen state; the new state starts at `position`.
  /// `shade`, when given, is the machine's measure along the path from here on: a change keeps
  /// `position` as a vertex and marks it. A stroke's part before its first shade takes that shade.
  void record(const PenPoint& position, bool down, std::optional<double> shade = std::nullopt);

  /// Pen-down strokes, in drawing order. A stroke with one point is a dot.
  const std::vector<Polyline>& strokes() const { return strokes_; }
  /// Pen-up moves (empty unless record_pen_up), each from a pen lift to the next pen drop; a
  /// lift and drop at the same place leave no move.
  const std::vector<Polyline>& pen_up_moves() const { return pen_up_moves_; }
  /// Shade marks of each pen-down stroke (parallel to strokes(); empty lists when unshaded).
  const std::vector<std::vector<ShadeMark>>& shade_marks() const { return shade_marks_; }
  /// Path length drawn with the pen down / travelled with the pen up, from every sample (mm).
  double pen_down_mm() const { return pen_down_mm_; }
  double pen_up_mm() const { return pen_up_mm_; }
  /// Samples recorded, and samples whose position differed from the previous one.
  uint64_t samples() const { return samples_; }
  uint64_t moves() const { return moves_; }

 private:
  /// Growing-polyline state: the angular wedge (around the direction `reference_`) in which the
  /// endpoint may move while every dropped sample stays within tolerance of the last segment.
  struct Segment {
    bool constrained = false;
    double reference = 0;
    double low = 0;
    double high = 0;
    double farthest_mm = 0;
  };
  void start_polyline(std::vector<Polyline>& list, const PenPoint& position);
  void start_stroke(const PenPoint& position);
  void extend(Polyline& line, const PenPoint& position);
  void mark_shade(double shade);

  PenTraceSettings settings_;
  std::vector<Polyline> strokes_;
  std::vector<Polyline> pen_up_moves_;
  std::vector<std::vector<ShadeMark>> shade_marks_;
  Segment segment_;
  /// The polyline's last point is a shade mark: the next move appends instead of merging.
  bool pinned_ = false;
  bool started_ = false;
  bool down_ = false;
  PenPoint last_{};
  double pen_down_mm_ = 0;
  double pen_up_mm_ = 0;
  uint64_t samples_ = 0;
  uint64_t moves_ = 0;
};

}  // namespace stepdance::sim
