// Five-bar arm: forward geometry from the linkage's construction, angles by Newton's method.
#include "models/five_bar_arm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepdance::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec {
  double x, y;
};
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y}; }
double length(Vec a) { return std::hypot(a.x, a.y); }

}  // namespace

FiveBarArm::FiveBarArm(const FiveBarArmSettings& settings) : settings_(settings) {
  PenPoint home;
  if (!stylus_for(settings.home_right_rad, settings.home_left_rad, home)) {
    throw std::invalid_argument("the arm cannot close at its home angles");
  }
  waypoints_.push_back(home);
  arrival_s_.push_back(0);
  leave_s_.push_back(0);
  for (size_t i = 0; i < settings.path_mm.size(); ++i) {
    const PenPoint& point = settings.path_mm[i];
    const PenPoint& last = waypoints_.back();
    arrival_s_.push_back(leave_s_.back() + std::hypot(point.x_mm - last.x_mm, point.y_mm - last.y_mm) /
                                               settings.speed_mm_per_s);
    leave_s_.push_back(arrival_s_.back() + (i < settings.dwell_s.size() ? settings.dwell_s[i] : 0.0));
    waypoints_.push_back(point);
  }
  solved_ = {settings.home_right_rad, settings.home_left_rad};
  solved_point_ = home;
  solved_time_ = 0;
}

bool FiveBarArm::stylus_for(double right_rad, double left_rad, PenPoint& stylus) const {
  const FiveBarArmSettings& g = settings_;
  const Vec c{g.s_mm / 2 + g.l1_mm * std::cos(right_rad), -g.l1_mm * std::sin(right_rad)};
  const Vec d{-g.s_mm / 2 + g.l2_mm * std::cos(left_rad), -g.l2_mm * std::sin(left_rad)};
  // The elbow: circles (C, L3) and (D, L4) meet at the foot F of the chord on CD, ± h across it.
  const Vec cd = d - c;
  const double span = length(cd);
  if (span <= 0 || span > g.l3_mm + g.l4_mm || span < std::fabs(g.l3_mm - g.l4_mm)) return false;
  const double from_c = (g.l3_mm * g.l3_mm - g.l4_mm * g.l4_mm + span * span) / (2 * span);
  const double h = std::sqrt(std::max(g.l3_mm * g.l3_mm - from_c * from_c, 0.0));
  const Vec along = (1.0 / span) * cd;
  const Vec across{-along.y, along.x};
  const Vec foot = c + from_c * along;
  const Vec e1 = foot + h * across, e2 = foot - h * across;
  const Vec e = e1.y < e2.y ? e1 : e2;  // the drawing side: away from the pivots
  // The stylus: from E towards C, turned clockwise by A6, L5 long.
  const Vec toward_c = (1.0 / g.l3_mm) * (c - e);
  const double cs = std::cos(-g.a6_rad), sn = std::sin(-g.a6_rad);
  const Vec offset{cs * toward_c.x - sn * toward_c.y, sn * toward_c.x + cs * toward_c.y};
  const Vec t = e + g.l5_mm * offset;
  stylus = {t.x, -t.y};
  return true;
}

PenPoint FiveBarArm::stylus_at(SimTime time) const {
  const double since_s = time <= settings_.start ? 0.0 : to_seconds(time - settings_.start);
  for (size_t i = 1; i < waypoints_.size(); ++i) {
    if (since_s >= arrival_s_[i]) continue;
    if (since_s <= leave_s_[i - 1]) return waypoints_[i - 1];  // resting there
    const double span = arrival_s_[i] - leave_s_[i - 1];
    const double k = span > 0 ? (since_s - leave_s_[i - 1]) / span : 1.0;
    const PenPoint& a = waypoints_[i - 1];
    const PenPoint& b = waypoints_[i];
    return {a.x_mm + k * (b.x_mm - a.x_mm), a.y_mm + k * (b.y_mm - a.y_mm)};
  }
  return waypoints_.back();
}

// Newton's method on the forward map with a finite-difference Jacobian, from `angles`.
bool FiveBarArm::solve(const PenPoint& target, Angles& angles) const {
  constexpr double kStep = 1e-7;
  for (int iteration = 0; iteration < 50; ++iteration) {
    PenPoint at, at_r, at_l;
    if (!stylus_for(angles.right, angles.left, at) || !stylus_for(angles.right + kStep, angles.left, at_r) ||
        !stylus_for(angles.right, angles.left + kStep, at_l)) {
      return false;
    }
    const double ex = target.x_mm - at.x_mm, ey = target.y_mm - at.y_mm;
    if (std::hypot(ex, ey) < 1e-9) return true;
    const double j11 = (at_r.x_mm - at.x_mm) / kStep, j12 = (at_l.x_mm - at.x_mm) / kStep;
    const double j21 = (at_r.y_mm - at.y_mm) / kStep, j22 = (at_l.y_mm - at.y_mm) / kStep;
    const double det = j11 * j22 - j12 * j21;
    if (std::fabs(det) < 1e-12) return false;  // a singular pose
    angles.right += (j22 * ex - j12 * ey) / det;
    angles.left += (-j21 * ex + j11 * ey) / det;
  }
  return false;
}

FiveBarArm::Angles FiveBarArm::angles_at(SimTime time) const {
  if (time == solved_time_) return solved_;
  // Newton converges from a nearby answer: walk from the last solved point in hops of ≤ 0.5 mm.
  const PenPoint target = stylus_at(time);
  const double distance = std::hypot(target.x_mm - solved_point_.x_mm, target.y_mm - solved_point_.y_mm);
  const int hops = std::max(1, static_cast<int>(std::ceil(distance / 0.5)));
  Angles angles = solved_;
  for (int hop = 1; hop <= hops; ++hop) {
    const double k = static_cast<double>(hop) / hops;
    const PenPoint step{solved_point_.x_mm + k * (target.x_mm - solved_point_.x_mm),
                        solved_point_.y_mm + k * (target.y_mm - solved_point_.y_mm)};
    if (!solve(step, angles)) {
      ++unsolved_;
      return solved_;
    }
  }
  solved_ = angles;
  solved_point_ = target;
  solved_time_ = time;
  return angles;
}

int64_t FiveBarArm::edges(double angle_rad) const {
  const double counts_per_rev = 4.0 * settings_.pulses_per_revolution;
  return static_cast<int64_t>(std::floor(angle_rad * counts_per_rev / (2 * kPi)));
}

int64_t FiveBarArm::right_count_at(SimTime time) const {
  return edges(settings_.home_right_rad) - edges(angles_at(time).right);
}

int64_t FiveBarArm::left_count_at(SimTime time) const {
  return edges(settings_.home_left_rad) - edges(angles_at(time).left);
}

}  // namespace stepdance::sim
