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

void StrokeStream::keep_final_points(const Polyline& stroke, const std::vector<ShadeMark>& marks, bool finished) {
  const size_t final_count = finished ? stroke.size() : (stroke.empty() ? 0 : stroke.size() - 1);
  // PenTrace marks the stroke's newest point, except its first shade, which it gives the whole
  // stroke so far (a mark at point 0) once measured: a mark behind `source_` is that one.
  for (; mark_ < marks.size() && marks[mark_].from_point < source_ && !kept_.empty(); ++mark_) {
    kept_marks_.push_back({marks[mark_].from_point == 0 ? 0 : kept_.size() - 1, marks[mark_].shade});
  }
  for (; source_ < final_count; ++source_) {
    const PenPoint& point = stroke[source_];
    const bool last = finished && source_ + 1 == stroke.size();
    const bool marked = mark_ < marks.size() && marks[mark_].from_point == source_;
    if (kept_.empty() || last || marked || !closer_than_resolution(point, kept_.back())) {
      // The stroke's own last point replaces a kept neighbour closer than the resolution, so
      // the end is exact and no two kept points are that close (the first point stays, and
      // so does a point where a shade starts).
      if (last && !marked && kept_.size() > 1 && closer_than_resolution(point, kept_.back()) && sent_ < kept_.size() &&
          !last_kept_is_marked()) {
        kept_.back() = point;
      } else {
        kept_.push_back(point);
      }
    }
    if (marked) kept_marks_.push_back({kept_.size() - 1, marks[mark_++].shade});
  }
}

std::vector<StrokePart> StrokeStream::take(const std::vector<Polyline>& strokes,
                                           const std::vector<std::vector<ShadeMark>>& marks, size_t max_points) {
  static const std::vector<ShadeMark> kNoMarks;
  std::vector<StrokePart> parts;
  behind_ = false;
  size_t budget = std::max<size_t>(max_points, 1);
  while (done_ < strokes.size() && budget > 0) {
    const Polyline& stroke = strokes[done_];
    const bool finished = done_ + 1 < strokes.size();
    keep_final_points(stroke, done_ < marks.size() ? marks[done_] : kNoMarks, finished);
    StrokePart part{done_, sent_, {}, {}};
    const size_t end = std::min(kept_.size(), sent_ + budget);
    part.points.assign(kept_.begin() + static_cast<std::ptrdiff_t>(sent_),
                       kept_.begin() + static_cast<std::ptrdiff_t>(end));
    sent_ = end;
    for (; marks_sent_ < kept_marks_.size() && kept_marks_[marks_sent_].point < sent_; ++marks_sent_) {
      part.shades.push_back(kept_marks_[marks_sent_]);
    }
    budget -= part.points.size();
    const bool all_kept_sent = sent_ == kept_.size();
    if (!finished && all_kept_sent && !stroke.empty()) {
      part.points.push_back(stroke.back());  // the moving head, re-sent next time from `sent_`
      const std::vector<ShadeMark>& own = done_ < marks.size() ? marks[done_] : kNoMarks;
      if (mark_ < own.size() && own[mark_].from_point + 1 == stroke.size()) {
        part.shades.push_back({part.from + part.points.size() - 1, own[mark_].shade});  // re-sent with the head
      }
      budget -= std::min<size_t>(budget, 1);
      // A head that has not moved since it was sent (the pen down and still) is not sent again.
      const Head head{done_, part.from, stroke.back(), part.shades.size(),
                      part.shades.empty() ? 0.0 : part.shades.back().shade};
      if (part.points.size() == 1 && head_sent_ && *head_sent_ == head) part.points.clear(), part.shades.clear();
      head_sent_ = head;
    }
    if (!part.points.empty()) parts.push_back(std::move(part));
    behind_ = !all_kept_sent || (budget == 0 && done_ + 1 < strokes.size());
    if (!finished || !all_kept_sent) break;
    ++done_;
    kept_.clear();
    source_ = 0;
    sent_ = 0;
    mark_ = 0;
    kept_marks_.clear();
    marks_sent_ = 0;
  }
  return parts;
}

}  // namespace stepdance::sim::view
