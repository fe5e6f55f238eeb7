// Eibotboard at start: one steps/mm for the EBB path, taken from the channels its x and y reach.
#include <math.h>
#include <string.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance {

namespace {

constexpr double kSameRatio = 1e-6;  // relative: closer ratios are the same (set_ratio_xy takes floats)

/// The mm per step of the channels a port reaches, and whether they agree.
struct ChannelRatios {
  int found = 0;
  double mm_per_step = 0.0;
  bool disagree = false;
  void add(double ratio) {
    const double mm = fabs(ratio);
    if (found > 0 && fabs(mm - mm_per_step) > kSameRatio * mm_per_step) disagree = true;
    if (found == 0) mm_per_step = mm;
    ++found;
  }
};

bool is_channel(const BlockPort* port) {
  return port != nullptr && port->parent() != nullptr && strcmp(port->parent()->type_name(), "Channel") == 0;
}

// The channels `output` drives: mapped to one directly, through the block it is mapped to (a
// kinematics: that block's outputs mapped to channels), or a channel's input mapped to it.
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

}  // namespace

bool Eibotboard::accept_frame_period(uint32_t) {
  ChannelRatios ratios;
  collect_channel_ratios(output_x, ratios);
  collect_channel_ratios(output_y, ratios);
  if (ratios.found == 0) return true;  // no channel downstream: set_ratio_xy's (or 80 steps/mm)
  if (ratios.disagree) {
    fault(FaultReason::kBadConfiguration,
          "Eibotboard: the channels its x and y drive differ in steps/mm; EBB motor steps need one ratio");
    return false;
  }
  const double given = mm_per_sixteenth_;
  if (ratio_xy_given_ && fabs(given - ratios.mm_per_step) > kSameRatio * ratios.mm_per_step) {
    fault(FaultReason::kBadConfiguration,
          "Eibotboard: set_ratio_xy disagrees with the steps/mm of the channels it drives; "
          "leave it out (the channels' ratio is used) or make them equal");
    return false;
  }
  mm_per_sixteenth_ = ratios.mm_per_step;  // one EBB 1/16 step is one channel step
  return true;
}

}  // namespace stepdance
