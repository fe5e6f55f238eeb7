// Machine: update loop shared by every machine model.
#include "models/machine.hpp"

namespace stepdance::sim {

Machine::Machine(const PenTraceSettings& trace, const std::optional<TravelArea>& travel) : trace_(trace) {
  if (travel) travel_.emplace(*travel);
}

void Machine::update(SimTime time) {
  const Sample now = sample(time);
  ++updates_;
  pen_ = now.pen;
  down_ = now.down;
  trace_.record(now.pen, now.down, now.shade);
  if (travel_) travel_->observe(time, now.pen);
}

std::optional<double> Machine::pen_axis_mm(MachineAxis axis) const {
  if (axis == MachineAxis::kX) return pen_.x_mm;
  if (axis == MachineAxis::kY) return pen_.y_mm;
  return std::nullopt;
}

MachineStats Machine::stats() const {
  MachineStats stats;
  stats.updates = updates_;
  stats.moves = trace_.moves();
  stats.strokes = trace_.strokes().size();
  stats.pen_down_mm = trace_.pen_down_mm();
  stats.pen_up_mm = trace_.pen_up_mm();
  stats.travel_excursions = travel_ ? travel_->excursion_count() : 0;
  return stats;
}

}  // namespace stepdance::sim
