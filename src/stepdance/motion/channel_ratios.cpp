// ChannelRatios: the motor steps an output reaches, found through the ports it is mapped to.
#include "stepdance/motion/channel_ratios.hpp"

#include <math.h>

#include "stepdance/core/block.hpp"

namespace stepdance {
namespace {

// A port whose block says it turns that port into motor steps (Block::world_units_per_step).
bool steps_of(const BlockPort* port, double& world_units) {
  return port != nullptr && port->parent() != nullptr && port->parent()->world_units_per_step(*port, world_units);
}

// Adds `port`'s ratio when it is a stepping input; true when it was one.
bool add_if_steps(const BlockPort* port, ChannelRatios& ratios) {
  double world_units = 0.0;
  if (!steps_of(port, world_units)) return false;
  ratios.add(world_units);
  return true;
}

}  // namespace

// Records the mm per step of each channel found; channels that disagree beyond kSameRatio are
// flagged, since an interface that needs one steps-per-mm figure (G-code's $100…, the EBB's motor
// step) cannot then have one.
void ChannelRatios::add(double ratio) {
  const double mm = fabs(ratio);
  if (found > 0 && !agrees_with(mm)) disagree = true;
  if (found == 0) mm_per_step = mm;
  ++found;
}

bool ChannelRatios::agrees_with(double mm_per_step_given) const {
  return fabs(fabs(mm_per_step_given) - mm_per_step) <= kSameRatio * mm_per_step;
}

// Follows the sketch's map() calls from `output`, one block deep: its peer when that steps a motor;
// a stepping input mapped to it; else, through the block its peer belongs to (a kinematics), every
// output of that block whose peer steps a motor. Each block answers for its own ports, so any
// block that steps (a Channel today) is found without naming its class.
void collect_channel_ratios(const BlockPort& output, ChannelRatios& ratios) {
  const BlockPort* peer = output.peer();
  double unused = 0.0;
  const Block* between = (peer != nullptr && !steps_of(peer, unused)) ? peer->parent() : nullptr;
  for (const BlockPort* port = BlockPort::first_attached(); port != nullptr; port = port->next_attached()) {
    if (port->peer() == &output) add_if_steps(port, ratios);
    const bool feeds_on = between != nullptr && port->parent() == between && port->direction() == BLOCKPORT_OUTPUT;
    if (feeds_on) add_if_steps(port->peer(), ratios);
  }
  add_if_steps(peer, ratios);
}

}  // namespace stepdance
