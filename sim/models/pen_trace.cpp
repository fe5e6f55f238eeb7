// PenTrace: stroke splitting and streaming polyline simplification within a tolerance.
#include "models/pen_trace.hpp"

#include <algorithm>
#include <cmath>

namespace stepdance::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;

double distance(const PenPoint& a, const PenPoint& b) { return std::hypot(b.x_mm - a.x_mm, b.y_mm - a.y_mm); }

double direction(const PenPoint& from, const PenPoint& to) {
  return std::atan2(to.y_mm - from.y_mm, to.x_mm - from.x_mm);
}

/// An angle brought into (−π, π].
double wrap(double angle) {
  while (angle > kPi) angle -= 2 * kPi;
  while (angle <= -kPi) angle += 2 * kPi;
  return angle;
}
}  // namespace

PenTrace::PenTrace(const PenTraceSettings& settings) : settings_(settings) {}

void PenTrace::record(const PenPoint& position, bool down, std::optional<double> shade) {
  ++samples_;
  if (!started_) {
    started_ = true;
    down_ = down;
    last_ = position;
    if (down) {
      start_stroke(position);
    } else if (settings_.record_pen_up) {
      start_polyline(pen_up_moves_, position);
    }
    if (down && shade) mark_shade(*shade);
    return;
  }
  if (position != last_) {
    ++moves_;
    const double length = distance(last_, position);
    if (down_) {
      pen_down_mm_ += length;
      extend(strokes_.back(), position);
    } else {
      pen_up_mm_ += length;
      if (settings_.record_pen_up) extend(pen_up_moves_.back(), position);
    }
    last_ = position;
  }
  if (down != down_) {
    down_ = down;
    if (down) {
      // A pen-up "move" that never moved is no move at all.
      if (settings_.record_pen_up && !pen_up_moves_.empty() && pen_up_moves_.back().size() == 1) {
        pen_up_moves_.pop_back();
      }
      start_stroke(position);
    } else if (settings_.record_pen_up) {
      start_polyline(pen_up_moves_, position);
    }
  }
  if (down_ && shade) mark_shade(*shade);
}

void PenTrace::start_stroke(const PenPoint& position) {
  start_polyline(strokes_, position);
  shade_marks_.emplace_back();
}

void PenTrace::mark_shade(double shade) {
  std::vector<ShadeMark>& marks = shade_marks_.back();
  if (marks.empty()) {
    marks.push_back({0, shade});  // the stroke so far takes its first measured shade
    return;
  }
  if (marks.back().shade == shade) return;
  const size_t here = strokes_.back().size() - 1;
  if (marks.back().from_point == here) {
    marks.back().shade = shade;  // two changes at one vertex: the later one holds
  } else {
    marks.push_back({here, shade});
  }
  pinned_ = true;
  segment_ = Segment{};
}

void PenTrace::start_polyline(std::vector<Polyline>& list, const PenPoint& position) {
  list.push_back(Polyline{position});
  segment_ = Segment{};
  pinned_ = false;
}

void PenTrace::extend(Polyline& line, const PenPoint& position) {
  if (line.size() < 2 || pinned_) {
    line.push_back(position);
    segment_ = Segment{};
    pinned_ = false;
    return;
  }
  const PenPoint& anchor = line[line.size() - 2];
  const PenPoint& end = line.back();
  const double tolerance = settings_.tolerance_mm;

  // Dropping `end` adds its own constraint: the segment from the anchor must pass within the
  // tolerance of it. Points within the tolerance of the anchor constrain nothing.
  Segment candidate = segment_;
  const double end_distance = distance(anchor, end);
  if (end_distance > tolerance) {
    const double half_width = std::asin(tolerance / end_distance);
    if (!candidate.constrained) {
      candidate.constrained = true;
      candidate.reference = direction(anchor, end);
      candidate.low = -half_width;
      candidate.high = half_width;
    } else {
      const double relative = wrap(direction(anchor, end) - candidate.reference);
      candidate.low = std::max(candidate.low, relative - half_width);
      candidate.high = std::min(candidate.high, relative + half_width);
    }
    candidate.farthest_mm = std::max(candidate.farthest_mm, end_distance);
  }

  bool merge = true;
  if (candidate.constrained) {
    const double relative = wrap(direction(anchor, position) - candidate.reference);
    merge =
        candidate.low <= relative && relative <= candidate.high && distance(anchor, position) >= candidate.farthest_mm;
  }
  if (merge) {
    line.back() = position;
    segment_ = candidate;
  } else {
    line.push_back(position);
    segment_ = Segment{};
  }
}

}  // namespace stepdance::sim
