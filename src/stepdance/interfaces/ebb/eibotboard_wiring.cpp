// Eibotboard at start: one steps/mm for the EBB path, taken from the channels its x and y are wired to.
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"
#include "stepdance/motion/channel_ratios.hpp"

namespace stepdance {

// At dance_start(): one EBB 1/16 step must be one channel step on both axes, or the AxiDraw software's
// step counts would draw at the wrong scale; a disagreement is refused (a configuration fault)
// rather than guessed.
bool Eibotboard::check_wiring() {
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
  if (ratio_xy_given_ && !ratios.agrees_with(given)) {
    fault(FaultReason::kBadConfiguration,
          "Eibotboard: set_ratio_xy disagrees with the steps/mm of the channels it drives; "
          "leave it out (the channels' ratio is used) or make them equal");
    return false;
  }
  mm_per_sixteenth_ = ratios.mm_per_step;  // one EBB 1/16 step is one channel step
  return true;
}

}  // namespace stepdance
