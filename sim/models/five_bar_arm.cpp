// Five-bar arm: forward geometry from the linkage's construction; the joints follow the hand from
// pose to pose (the linkage's own closed-form poses), inside their stops.
#include "models/five_bar_arm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepdance::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
constexpr double kDegreeRad = kPi / 180;
constexpr double kHopMm = 0.5;                      // the hand's path is followed in hops this long
constexpr double kMaxTurnRad = 2 * kDegreeRad;      // a continuous hop turns no joint further
constexpr double kDeadPointRad = 0.1 * kDegreeRad;  // two poses this close: the arm is at a dead point
constexpr double kClearlyNearer = 2;                // the nearest pose, this many times nearer than the next
constexpr int kMaxHalvings = 30;                    // a hop halved down to 0.5 mm / 2³⁰ ≈ 5·10⁻¹⁰ mm
constexpr double kFollowedMm = 0.001;               // the stylus this close to the hand follows it
constexpr double kPoseCheckMm = 1e-6;               // a pose must put the stylus this close to its point
constexpr double kStopSlackRad = 1e-9;              // rounding at a stop

struct Vec {
  double x, y;
};
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator*(double k, Vec a) { return {k * a.x, k * a.y}; }
double length(Vec a) { return std::hypot(a.x, a.y); }
/// a / b as complex numbers.
Vec divide(Vec a, Vec b) {
  const double norm = b.x * b.x + b.y * b.y;
  return {(a.x * b.x + a.y * b.y) / norm, (a.y * b.x - a.x * b.y) / norm};
}

/// Where circles (a, ra) and (b, rb) meet: false when they do not (touching circles give the
/// same point twice).
bool meet(Vec a, double ra, Vec b, double rb, Vec (&points)[2]) {
  const Vec ab = b - a;
  const double span = length(ab);
  if (span <= 0 || span > ra + rb || span < std::fabs(ra - rb)) return false;
  const double from_a = (ra * ra - rb * rb + span * span) / (2 * span);
  const double h = std::sqrt(std::max(ra * ra - from_a * from_a, 0.0));
  const Vec along = (1.0 / span) * ab;
  const Vec across{-along.y, along.x};
  const Vec foot = a + from_a * along;
  points[0] = foot + h * across;
  points[1] = foot - h * across;
  return true;
}

/// The joint angle of an arm from `pivot` to `end` (the arm points along (cos A, −sin A)).
double angle_about(Vec pivot, Vec end) { return std::atan2(pivot.y - end.y, end.x - pivot.x); }

/// `angle` plus whole turns, within half a turn of `near`.
double turned_near(double angle, double near) { return angle + kTwoPi * std::round((near - angle) / kTwoPi); }

double distance_mm(const PenPoint& a, const PenPoint& b) { return std::hypot(b.x_mm - a.x_mm, b.y_mm - a.y_mm); }

}  // namespace

FiveBarArm::FiveBarArm(const FiveBarArmSettings& settings) : settings_(settings) {
  Angles home{settings.home_right_rad, settings.home_left_rad};
  if (!inside_stops(home)) throw std::invalid_argument("the arm's home angles lie past its stops");
  PenPoint home_point;
  if (!stylus_for(home.right, home.left, home_point)) {
    throw std::invalid_argument("the arm cannot close at its home angles");
  }
  waypoints_.push_back(home_point);
  arrival_s_.push_back(0);
  leave_s_.push_back(0);
  for (size_t i = 0; i < settings.path_mm.size(); ++i) {
    const PenPoint& point = settings.path_mm[i];
    arrival_s_.push_back(leave_s_.back() + distance_mm(waypoints_.back(), point) / settings.speed_mm_per_s);
    leave_s_.push_back(arrival_s_.back() + (i < settings.dwell_s.size() ? settings.dwell_s[i] : 0.0));
    waypoints_.push_back(point);
  }
  pose_ = home;
  stylus_ = home_point;
  solved_time_ = 0;
}

bool FiveBarArm::stylus_for(double right_rad, double left_rad, PenPoint& stylus) const {
  Linkage linkage;
  if (!linkage_for(right_rad, left_rad, linkage)) return false;
  stylus = linkage.t;
  return true;
}

bool FiveBarArm::linkage_for(double right_rad, double left_rad, Linkage& linkage) const {
  const FiveBarArmSettings& g = settings_;
  const Vec c{g.s_mm / 2 + g.l1_mm * std::cos(right_rad), -g.l1_mm * std::sin(right_rad)};
  const Vec d{-g.s_mm / 2 + g.l2_mm * std::cos(left_rad), -g.l2_mm * std::sin(left_rad)};
  Vec elbows[2];
  if (!meet(c, g.l3_mm, d, g.l4_mm, elbows)) return false;
  const Vec e = elbows[0].y < elbows[1].y ? elbows[0] : elbows[1];  // the drawing side: away from the pivots
  // The stylus: from E towards C, turned clockwise by A6, L5 long.
  const Vec toward_c = (1.0 / g.l3_mm) * (c - e);
  const double cs = std::cos(-g.a6_rad), sn = std::sin(-g.a6_rad);
  const Vec offset{cs * toward_c.x - sn * toward_c.y, sn * toward_c.x + cs * toward_c.y};
  const Vec t = e + g.l5_mm * offset;
  const auto reported = [](Vec v) { return PenPoint{v.x, -v.y}; };  // y mirrored: drawing side positive
  linkage = {reported({g.s_mm / 2, 0}), reported({-g.s_mm / 2, 0}), reported(c), reported(d), reported(e), reported(t)};
  return true;
}

double FiveBarArm::since_start_s(SimTime time) const {
  return time <= settings_.start ? 0.0 : to_seconds(time - settings_.start);
}

PenPoint FiveBarArm::stylus_at(SimTime time) const {
  const double since_s = since_start_s(time);
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

// Inside [right_min, right_min + 2π] and [left_max − 2π, left_max], rounding at a stop clamped.
bool FiveBarArm::inside_stops(Angles& angles) const {
  const double right_min = settings_.right_min_rad, left_max = settings_.left_max_rad;
  if (angles.right < right_min - kStopSlackRad || angles.right > right_min + kTwoPi + kStopSlackRad) return false;
  if (angles.left > left_max + kStopSlackRad || angles.left < left_max - kTwoPi - kStopSlackRad) return false;
  angles.right = std::clamp(angles.right, right_min, right_min + kTwoPi);
  angles.left = std::clamp(angles.left, left_max - kTwoPi, left_max);
  return true;
}

// The rigid link C–E–T: T − C = (L5·e^(−i·A6) − L3)·u with u = (C − E)/L3, so |T − C| is fixed and C
// lies where that circle round T meets the right arm's; u and then E follow, and D lies where the
// left arm's circle meets (E, L4). Each pose is checked with the forward map (its elbow must be
// the one stylus_for takes) and kept only inside the stops, its angles within half a turn of `near`.
FiveBarArm::Poses FiveBarArm::poses_for(const PenPoint& target, const Angles& near) const {
  const FiveBarArmSettings& g = settings_;
  const Vec t{target.x_mm, -target.y_mm};
  const Vec right_pivot{g.s_mm / 2, 0}, left_pivot{-g.s_mm / 2, 0};
  const Vec link{g.l5_mm * std::cos(g.a6_rad) - g.l3_mm, -g.l5_mm * std::sin(g.a6_rad)};
  Poses poses;
  Vec arm_ends[2];
  if (!meet(right_pivot, g.l1_mm, t, length(link), arm_ends)) return poses;
  for (const Vec& c : arm_ends) {
    const Vec e = c - g.l3_mm * divide(t - c, link);
    Vec left_ends[2];
    if (!meet(left_pivot, g.l2_mm, e, g.l4_mm, left_ends)) continue;
    for (const Vec& d : left_ends) {
      Angles pose{turned_near(angle_about(right_pivot, c), near.right),
                  turned_near(angle_about(left_pivot, d), near.left)};
      PenPoint check;
      if (!stylus_for(pose.right, pose.left, check) || distance_mm(check, target) > kPoseCheckMm) continue;
      if (inside_stops(pose)) poses.pose[poses.count++] = pose;
    }
  }
  return poses;
}

// The pose that continues the arm's motion, −1 for none (halve the hop): at most kMaxTurnRad from
// where the joints are; at a dead point the one turning most nearly the way the joints were
// turning, else the nearest, once it is clearly nearer than the next (or the hop is as short as
// it gets).
int FiveBarArm::choose(const Poses& poses, bool shortest_hop) const {
  int nearest = -1, onward = -1;
  double nearest_turn = 0, next_turn = kMaxTurnRad * 2, onward_cosine = -2;
  for (int i = 0; i < poses.count; ++i) {
    const double dr = poses.pose[i].right - pose_.right, dl = poses.pose[i].left - pose_.left;
    const double turn = std::max(std::fabs(dr), std::fabs(dl));
    if (turn > kMaxTurnRad) continue;
    if (nearest < 0 || turn < nearest_turn) {
      next_turn = nearest < 0 ? next_turn : nearest_turn;
      nearest = i;
      nearest_turn = turn;
    } else {
      next_turn = std::min(next_turn, turn);
    }
    const double norms = std::hypot(dr, dl) * std::hypot(last_turn_.right, last_turn_.left);
    const double cosine = norms > 0 ? (dr * last_turn_.right + dl * last_turn_.left) / norms : -1.0;
    if (cosine > onward_cosine) {
      onward = i;
      onward_cosine = cosine;
    }
  }
  const bool alone = next_turn > kMaxTurnRad;
  if (nearest < 0 || alone) return nearest;
  if (at_dead_point_) return onward;
  return shortest_hop || next_turn >= kClearlyNearer * nearest_turn ? nearest : -1;
}

// One hop of the stylus to `to`; a hop with no continuous pose is halved, down to kMaxHalvings.
bool FiveBarArm::advance(const PenPoint& to, int depth) const {
  const Poses poses = poses_for(to, pose_);
  const int chosen = choose(poses, depth >= kMaxHalvings);
  if (chosen < 0) {
    if (depth >= kMaxHalvings) return false;
    const PenPoint middle{(stylus_.x_mm + to.x_mm) / 2, (stylus_.y_mm + to.y_mm) / 2};
    return advance(middle, depth + 1) && advance(to, depth + 1);
  }
  const Angles& next = poses.pose[chosen];
  // The way the joints were turning as they came to a dead point: hops at the dead point itself
  // (where the poses meet and rounding decides between them) do not change it.
  if (!at_dead_point_) last_turn_ = {next.right - pose_.right, next.left - pose_.left};
  at_dead_point_ = false;
  for (int i = 0; i < poses.count; ++i) {
    const Angles& other = poses.pose[i];
    const double apart = std::max(std::fabs(other.right - next.right), std::fabs(other.left - next.left));
    if (i != chosen && apart <= kDeadPointRad) at_dead_point_ = true;
  }
  pose_ = next;
  stylus_ = to;
  return true;
}

// From where the stylus is, along the straight line to `target`; it stays where it gets stuck.
void FiveBarArm::walk_to(const PenPoint& target) const {
  const PenPoint from = stylus_;
  const double distance = distance_mm(from, target);
  if (distance == 0) return;
  const int hops = std::max(1, static_cast<int>(std::ceil(distance / kHopMm)));
  for (int hop = 1; hop <= hops; ++hop) {
    const double k = static_cast<double>(hop) / hops;
    const PenPoint step{from.x_mm + k * (target.x_mm - from.x_mm), from.y_mm + k * (target.y_mm - from.y_mm)};
    if (!advance(step, 0)) return;
  }
}

// The arm follows the hand's path: through every corner the hand passed since the last moment
// asked (a straight line from there would cut the corner), then to where the hand is.
FiveBarArm::Angles FiveBarArm::angles_at(SimTime time) const {
  if (time == solved_time_) return pose_;
  if (time > solved_time_) {
    const double from_s = since_start_s(solved_time_), to_s = since_start_s(time);
    for (size_t i = 1; i < waypoints_.size(); ++i) {
      if (arrival_s_[i] > from_s && arrival_s_[i] <= to_s) walk_to(waypoints_[i]);
    }
  }
  const PenPoint target = stylus_at(time);
  walk_to(target);
  if (distance_mm(stylus_, target) > kFollowedMm) ++unsolved_;
  solved_time_ = time;
  return pose_;
}

int64_t FiveBarArm::edges(double angle_rad) const {
  const double counts_per_rev = 4.0 * settings_.pulses_per_revolution;
  return static_cast<int64_t>(std::floor(angle_rad * counts_per_rev / kTwoPi));
}

int64_t FiveBarArm::right_count_at(SimTime time) const {
  return edges(settings_.home_right_rad) - edges(angles_at(time).right);
}

int64_t FiveBarArm::left_count_at(SimTime time) const {
  return edges(settings_.home_left_rad) - edges(angles_at(time).left);
}

}  // namespace stepdance::sim
