// The drawing as a stream of incremental stroke updates, thinned to the page's display resolution.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "models/pen_trace.hpp"

namespace stepdance::sim::view {

/// Consecutive points of a stroke closer than this (mm) are merged for the page; a stroke's
/// first and last points are always kept.
constexpr double kDisplayResolutionMm = 0.05;

/// From point `point` of a stroke (the page's numbering) on, the stroke has shade `shade`.
struct ShadeStart {
  size_t point = 0;
  double shade = 0;
};

/// One stroke's new part: the page keeps the first `from` points it has of stroke `index` and
/// appends `points`. The last point of the last stroke may still move (the pen is drawing it);
/// the next update then re-sends it. `shades`: where the stroke's shade changes among the new
/// points (a shaded machine's marks, ShadeMark, renumbered for the page's points).
struct StrokePart {
  size_t index = 0;
  size_t from = 0;
  std::vector<PenPoint> points;
  std::vector<ShadeStart> shades;
};

/// Follows a machine's growing list of pen-down strokes (PenTrace: only a stroke's last point
/// ever changes, and only the newest stroke grows) and hands out what is new since the last
/// call. A point is left out only when it lies closer than kDisplayResolutionMm to the point
/// kept before it; no stroke is ever left out, nor its first or last point. The newest stroke's
/// moving head is sent again only when it moved (or its shade changed) since it was last sent.
/// Context: the thread running the simulation, between run_until() calls.
class StrokeStream {
 public:
  /// What changed in `strokes` since the last call: at most about `max_points` points (a
  /// stroke's part is cut there and continued next call; at least one point is always sent).
  std::vector<StrokePart> take(const std::vector<Polyline>& strokes, size_t max_points) {
    return take(strokes, {}, max_points);
  }
  /// The same, for a machine that shades its strokes: `marks` parallel to `strokes` (PenTrace).
  /// A marked point is always kept (it ends one shaded piece and starts the next, as in the
  /// SVG) and its mark is sent with it in the part's `shades`.
  std::vector<StrokePart> take(const std::vector<Polyline>& strokes, const std::vector<std::vector<ShadeMark>>& marks,
                               size_t max_points);
  /// Strokes whose every point has been sent (their last point included).
  size_t strokes_done() const { return done_; }
  /// Whether the last take() stopped at `max_points` with points left to send.
  bool behind() const { return behind_; }

 private:
  /// Appends to `kept_` the final points of `stroke` from source index `source_` on (all of
  /// them if the stroke is finished, all but its moving last point if not).
  void keep_final_points(const Polyline& stroke, const std::vector<ShadeMark>& marks, bool finished);
  /// Whether kept_'s last point starts a shade (it is then never replaced).
  bool last_kept_is_marked() const { return !kept_marks_.empty() && kept_marks_.back().point + 1 == kept_.size(); }

  /// The newest stroke's moving head as last sent: stroke, the part's `from`, the point, and
  /// the part's shade starts (their count and the last one's shade).
  struct Head {
    size_t index = 0;
    size_t from = 0;
    PenPoint point;
    size_t shades = 0;
    double last_shade = 0;
    bool operator==(const Head& other) const {
      return index == other.index && from == other.from && point == other.point && shades == other.shades &&
             last_shade == other.last_shade;
    }
  };

  std::optional<Head> head_sent_;
  size_t done_ = 0;                     ///< strokes complete on the page
  std::vector<PenPoint> kept_;          ///< the current stroke's final kept points (decimated)
  size_t source_ = 0;                   ///< source points of the current stroke already looked at
  size_t sent_ = 0;                     ///< kept_ points the page has
  bool behind_ = false;                 ///< the last take() ran out of budget
  size_t mark_ = 0;                     ///< the current stroke's marks already kept
  std::vector<ShadeStart> kept_marks_;  ///< the current stroke's marks, on kept_ points
  size_t marks_sent_ = 0;               ///< kept_marks_ the page has
};

}  // namespace stepdance::sim::view
