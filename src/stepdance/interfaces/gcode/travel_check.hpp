// Soft limits: whether a planned motion stays inside the machine's travel.
#pragma once

#include "stepdance/interfaces/gcode/grbl_settings.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// True when `motion` stays inside the travel, or soft limits (`$20`) are off. Machine space is
/// [0, `$130`–`$132`] mm from the power-on (or homed) origin; a straight motion is checked at its
/// end, an arc by the box it sweeps. Context: loop (pure function).
bool within_travel(const GrblSettings& settings, const Motion& motion);

}  // namespace stepdance::gcode
