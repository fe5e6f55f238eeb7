// QuadratureEncoder: turn schedule and count lookup with a forward-moving cursor.
#include "models/quadrature_encoder.hpp"

#include <algorithm>
#include <limits>

namespace stepdance::sim {

QuadratureEncoder::QuadratureEncoder(int32_t pulses_per_revolution, int64_t start_count)
    : pulses_per_revolution_(pulses_per_revolution), start_count_(start_count) {
  reset_cursor();
}

void QuadratureEncoder::turn(SimTime start, int64_t counts, SimTime span) {
  const Turn added{start, start + std::max<SimTime>(span, 0), counts};
  const auto position =
      std::upper_bound(turns_.begin(), turns_.end(), start, [](SimTime t, const Turn& turn) { return t < turn.start; });
  turns_.insert(position, added);
  reset_cursor();
}

void QuadratureEncoder::reset_cursor() const {
  cursor_time_ = std::numeric_limits<SimTime>::min();
  next_ = 0;
  settled_ = 0;
  active_.clear();
}

int64_t QuadratureEncoder::delivered(const Turn& turn, SimTime time) {
  if (time < turn.start) return 0;
  if (time >= turn.end) return turn.counts;
  const __int128 magnitude = turn.counts < 0 ? -static_cast<__int128>(turn.counts) : turn.counts;
  const __int128 done = magnitude * (time - turn.start) / (turn.end - turn.start);
  return turn.counts < 0 ? -static_cast<int64_t>(done) : static_cast<int64_t>(done);
}

int64_t QuadratureEncoder::count_at(SimTime time) const {
  if (time < cursor_time_) reset_cursor();
  cursor_time_ = time;
  while (next_ < turns_.size() && turns_[next_].start <= time) {
    active_.push_back(next_);
    ++next_;
  }
  int64_t in_progress = 0;
  size_t kept = 0;
  for (const size_t index : active_) {
    const Turn& turn = turns_[index];
    if (time >= turn.end) {
      settled_ += turn.counts;
    } else {
      in_progress += delivered(turn, time);
      active_[kept++] = index;
    }
  }
  active_.resize(kept);
  return start_count_ + settled_ + in_progress;
}

double QuadratureEncoder::revolutions_at(SimTime time) const {
  return static_cast<double>(count_at(time)) / static_cast<double>(counts_per_revolution());
}

}  // namespace stepdance::sim
