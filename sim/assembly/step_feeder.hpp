// Feeds the STEP rising edges an output port plays into a device model (stepper driver, servo board).
#pragma once

#include "assembly/frame_waveform.hpp"
#include "board/host/wire.hpp"

namespace stepdance::sim {

/// A WireListener that calls model.on_step_rising(time, dir_high) for every STEP pulse the port
/// plays, as a driver wired to the socket sees them. Model is StepperDriver or ServoBoard.
/// If `activity` is given, it is set to true whenever a frame with pulses was fed.
template <typename Model>
class StepFeeder final : public WireListener {
 public:
  explicit StepFeeder(Model& model, bool* activity = nullptr) : model_(model), activity_(activity) {}
  void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime /*frame_ns*/) override {
    for_each_step_rise(start_ns, words, [this](SimTime time, bool dir_high) { model_.on_step_rising(time, dir_high); });
    if (activity_ != nullptr && words.step_bits != 0) *activity_ = true;
  }

 private:
  Model& model_;
  bool* activity_;
};

}  // namespace stepdance::sim
