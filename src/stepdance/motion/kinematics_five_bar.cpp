// KinematicsFiveBarForward / Inverse: geometry per frame, unreachable poses held and reported.
#include "stepdance/motion/kinematics_five_bar.hpp"

#include "stepdance/core/fault.hpp"

namespace stepdance {
namespace {

FiveBarGeometry make_geometry(float s, float l1, float l2, float l3, float l4, float l5, float a6) {
  return FiveBarGeometry{s, l1, l2, l3, l4, l5, a6};
}

void pull_both(BlockPort& a, BlockPort& b) {
  a.pull();
  a.update();
  b.pull();
  b.update();
}

void set_both(BlockPort& a, double va, BlockPort& b, double vb) {
  a.set(a.convert_world_to_block_units(va), ABSOLUTE);
  b.set(b.convert_world_to_block_units(vb), ABSOLUTE);
  a.push();
  b.push();
}

}  // namespace

Status KinematicsFiveBarForward::begin(float s, float l1, float l2, float l3, float l4, float l5, float a6) {
  geometry_ = make_geometry(s, l1, l2, l3, l4, l5, a6);
  input_r.begin(&r_, BLOCKPORT_INPUT, this);
  input_l.begin(&l_, BLOCKPORT_INPUT, this);
  output_x.begin(&x_, BLOCKPORT_OUTPUT, this);
  output_y.begin(&y_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. Where the links cannot close (the original's acos had no range check and produced
// NaN), the outputs hold the last reachable pose and a warning is counted.
void KinematicsFiveBarForward::run() {
  pull_both(input_r, input_l);
  double x, y;
  if (!geometry_.forward(input_r.read(ABSOLUTE), input_l.read(ABSOLUTE), x, y)) {
    unreachable_ = unreachable_ + 1;
    report_fault(FaultLevel::kWarning, FaultReason::kUnreachable, "five-bar forward", "links cannot close");
    return;  // the outputs keep their last reachable pose
  }
  set_both(output_x, x, output_y, y);
}

Status KinematicsFiveBarInverse::begin(float s, float l1, float l2, float l3, float l4, float l5, float a6) {
  geometry_ = make_geometry(s, l1, l2, l3, l4, l5, a6);
  input_x.begin(&x_, BLOCKPORT_INPUT, this);
  input_y.begin(&y_, BLOCKPORT_INPUT, this);
  output_r.begin(&r_, BLOCKPORT_OUTPUT, this);
  output_l.begin(&l_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. A point out of reach holds the last pose instead of moving the motors to NaN.
void KinematicsFiveBarInverse::run() {
  pull_both(input_x, input_y);
  double a1, a2;
  if (!geometry_.inverse(input_x.read(ABSOLUTE), input_y.read(ABSOLUTE), a1, a2)) {
    unreachable_ = unreachable_ + 1;
    report_fault(FaultLevel::kWarning, FaultReason::kUnreachable, "five-bar inverse", "point out of reach");
    return;
  }
  set_both(output_r, a1, output_l, a2);
}

}  // namespace stepdance
