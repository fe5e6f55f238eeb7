// TravelMonitor: excursion detection and bookkeeping.
#include "models/travel_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace stepdance::sim {

TravelMonitor::TravelMonitor(const TravelArea& area, size_t max_remembered)
    : area_(area), max_remembered_(max_remembered) {}

double TravelMonitor::overshoot_mm(const PenPoint& position) const {
  const double dx = std::max({area_.x_min_mm - position.x_mm, 0.0, position.x_mm - area_.x_max_mm});
  const double dy = std::max({area_.y_min_mm - position.y_mm, 0.0, position.y_mm - area_.y_max_mm});
  return std::hypot(dx, dy);
}

bool TravelMonitor::beyond_tolerance(const PenPoint& position) const {
  const double tolerance = area_.tolerance_mm;
  return position.x_mm < area_.x_min_mm - tolerance || position.x_mm > area_.x_max_mm + tolerance ||
         position.y_mm < area_.y_min_mm - tolerance || position.y_mm > area_.y_max_mm + tolerance;
}

void TravelMonitor::observe(SimTime time, const PenPoint& position) {
  const double overshoot = overshoot_mm(position);
  const bool outside = beyond_tolerance(position);
  const bool remembered = count_ > 0 && count_ <= max_remembered_;
  if (outside && !outside_) {
    ++count_;
    if (count_ <= max_remembered_) {
      excursions_.push_back(TravelExcursion{time, -1, position, position, overshoot});
    }
  } else if (outside && remembered && overshoot > excursions_.back().overshoot_mm) {
    excursions_.back().farthest = position;
    excursions_.back().overshoot_mm = overshoot;
  } else if (!outside && outside_ && remembered) {
    excursions_.back().end = time;
  }
  if (outside) max_overshoot_mm_ = std::max(max_overshoot_mm_, overshoot);
  outside_ = outside;
}

}  // namespace stepdance::sim
