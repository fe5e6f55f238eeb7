// Device kind "five_bar_arm": the digital pantograph's arm, two joint encoders on ENC1 and ENC2.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// A five-bar arm's settings. The device's `connector` is the right joint's encoder,
/// left_connector the left's; the stylus leaves home at start_s and visits path_mm ([x, y] or
/// [x, y, dwell_s]) at speed_mm_per_s. The joints' stops (degrees): the right joint stays at or
/// above right_min_deg, the left at or below left_max_deg (the original pantograph's, where its
/// arms rest at power-on).
struct FiveBarArmConfig {
  int32_t pulses_per_revolution = 10000;  // 40,000 counts a turn, as on the original's pantograph
  scenario::Connector left_connector = scenario::Connector::kEnc2;
  std::vector<std::pair<double, double>> path_mm;
  std::vector<double> dwell_s;  ///< per path point: [x, y, dwell_s] rests there (0 if omitted)
  double speed_mm_per_s = 20;
  double start_s = 0;
  double right_min_deg = -60;
  double left_max_deg = 240;
};

const DeviceKind& five_bar_arm_kind();

}  // namespace stepdance::sim
