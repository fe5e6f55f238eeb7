// ChannelRatios: the channels an output reaches, found through the port registry.
#include "stepdance/motion/channel_ratios.hpp"

#include <math.h>
#include <string.h>

#include "stepdance/core/block.hpp"

namespace stepdance {
namespace {

bool is_channel(const BlockPort* port) {
  return port != nullptr && port->parent() != nullptr && strcmp(port->parent()->type_name(), "Channel") == 0;
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

// Finds the channels an interface output drives, directly or through one block in between (a
// kinematics block): its peer, any channel mapped to this port, and the channels the peer's owner
// feeds. Channels are recognised by their type name.
void collect_channel_ratios(const BlockPort& output, ChannelRatios& ratios) {
  const BlockPort* peer = output.peer();
  for (const BlockPort* port = BlockPort::first_attached(); port != nullptr; port = port->next_attached()) {
    if (port->peer() == &output && is_channel(port)) ratios.add(port->ratio());
    const bool feeds_on = peer != nullptr && !is_channel(peer) && port->parent() == peer->parent() &&
                          port->direction() == BLOCKPORT_OUTPUT && is_channel(port->peer());
    if (feeds_on) ratios.add(port->peer()->ratio());
  }
  if (is_channel(peer)) ratios.add(peer->ratio());
}

}  // namespace stepdance
