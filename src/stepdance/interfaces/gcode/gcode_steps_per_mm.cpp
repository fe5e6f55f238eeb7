// GCodeInterface at start: $100–$102 (steps/mm) taken from the channels its X, Y and Z drive.
#include "stepdance/core/fault.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"
#include "stepdance/motion/channel_ratios.hpp"

namespace stepdance {

namespace {
constexpr int kStepAxes = 3;  // $100–$102: X, Y, Z (Grbl 1.1 has no steps/mm setting beyond them)
constexpr char kAxisNames[kStepAxes] = {'X', 'Y', 'Z'};
constexpr double kChannelsDisagree = -1.0;  // no setting holds a negative value
}  // namespace

// One steps/mm a G-code axis: the channels it reaches give it; a sketch value beside them must
// agree. An axis that reaches no channel keeps the sketch's value (or 0).
bool GCodeInterface::check_wiring() {
  BlockPort* outputs[kStepAxes] = {&output_x, &output_y, &output_z};
  for (int axis = 0; axis < kStepAxes; ++axis) {
    ChannelRatios ratios;
    collect_channel_ratios(*outputs[axis], ratios);
    if (ratios.found == 0 || ratios.mm_per_step <= 0.0) continue;
    const uint32_t number = 100 + static_cast<uint32_t>(axis);
    if (ratios.disagree) {
      describe_steps_fault(number, kAxisNames[axis], kChannelsDisagree, 0.0);
      fault(FaultReason::kBadConfiguration, steps_fault_text_);
      return false;
    }
    const double channel_steps_per_mm = 1.0 / ratios.mm_per_step;
    const gcode::GrblSetting* setting = settings().find(number);
    if (setting->sketch_set && !ratios.agrees_with(1.0 / setting->value)) {
      describe_steps_fault(number, kAxisNames[axis], setting->value, channel_steps_per_mm);
      fault(FaultReason::kBadConfiguration, steps_fault_text_);
      return false;
    }
    settings().set_from_machine(number, channel_steps_per_mm);
  }
  return true;
}

// The fault's text, naming the setting and both values (kept: the fault path holds the pointer).
// `sketch` kChannelsDisagree: the axis's channels disagree among themselves.
// Context: loop (dance_start); the text is written once into a member buffer, no heap.
void GCodeInterface::describe_steps_fault(uint32_t number, char axis, double sketch, double channels) {
  TextWriter text(steps_fault_text_, sizeof(steps_fault_text_));
  text.text("GCodeInterface: $").unsigned_number(number);
  if (sketch == kChannelsDisagree) {
    text.text(": the channels G-code ").character(axis).text(" drives differ in steps/mm; it needs one ratio");
    return;
  }
  text.text(" is ").significant(sketch, 6).text(" steps/mm in the sketch (set_from_sketch) but the channels G-code ");
  text.character(axis).text(" drives take ").significant(channels, 6);
  text.text("; leave it out (the channels' value is used) or make them equal");
}

}  // namespace stepdance
