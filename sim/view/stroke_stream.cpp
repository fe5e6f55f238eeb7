// StrokeStream: per-stroke cursors over the machine's polylines, merging sub-resolution steps.
#include "view/stroke_stream.hpp"

#include <algorithm>
#include <cmath>

namespace stepdance::sim::view {
namespace {

bool closer_than_resolution(const PenPoint& a, const PenPoint& b) {
  return std::hypot(a.x_mm - b.x_mm, a.y_mm - b.y_mm) < kDisplayResolutionMm;
}

}  // namespace

void StrokeStream::keep_final_points(const Polyline& stroke, bool finished) {
  const size_t final_count = finished ? stroke.size() : (stroke.empty() ? 0 : stroke.size() - 1);
  for (; source_ < final_count; ++source_) {
    const PenPoint& point = stroke[source_];
    const bool last = finished && source_ + 1 == stroke.size();
    if (kept_.empty() || last || !closer_than_resolution(point, kept_.back())) {
      // The stroke's own last point replaces a kept neighbour closer than the resolution, so
      // the end is exact and no two kept points are that close (the first point stays).
      if (last && kept_.size() > 1 && closer_than_resolution(point, kept_.back()) && sent_ < kept_.size()) {
        kept_.back() = point;
      } else {
        kept_.push_back(point);
      }
    }
  }
}

std::vector<StrokePart> StrokeStream::take(const std::vector<Polyline>& strokes, size_t max_points) {
  std::vector<StrokePart> parts;
  behind_ = false;
  size_t budget = std::max<size_t>(max_points, 1);
  while (done_ < strokes.size() && budget > 0) {
    const Polyline& stroke = strokes[done_];
    const bool finished = done_ + 1 < strokes.size();
    keep_final_points(stroke, finished);
    StrokePart part{done_, sent_, {}};
    const size_t end = std::min(kept_.size(), sent_ + budget);
    part.points.assign(kept_.begin() + static_cast<std::ptrdiff_t>(sent_), kept_.begin() + static_cast<std::ptrdiff_t>(end));
    sent_ = end;
    budget -= part.points.size();
    const bool all_kept_sent = sent_ == kept_.size();
    if (!finished && all_kept_sent && !stroke.empty()) {
      part.points.push_back(stroke.back());  // the moving head, re-sent next time from `sent_`
      budget -= std::min<size_t>(budget, 1);
    }
    if (!part.points.empty()) parts.push_back(std::move(part));
    behind_ = !all_kept_sent || (budget == 0 && done_ + 1 < strokes.size());
    if (!finished || !all_kept_sent) break;
    ++done_;
    kept_.clear();
    source_ = 0;
    sent_ = 0;
  }
  return parts;
}

}  // namespace stepdance::sim::view
