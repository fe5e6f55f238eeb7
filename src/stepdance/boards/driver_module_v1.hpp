// Stepdance Driver Module v1.0 (Teensy 4.1): four driver sockets, four input ports.
#pragma once

#include "stepdance/boards/board_definition.hpp"

namespace stepdance {

/// The Driver Module v1.0's table. Pins: output ports A–D STEP/DIR 23/22, 21/20, 37/36, 35/34;
/// ENABLE 14/13/39/33, VREF 15/41/40/38, LIMIT 29–32; input ports 4/6, 5/7, 8/10, 9/11.
inline constexpr BoardDefinition kDriverModuleV1 = {
    "Driver Module v1.0",
    "driver",
    "module_driver",
    &kTeensy41,
    &kTeensy41,  // the 4.1 only
    4,
    {{23, 22, 14, 15, 29}, {21, 20, 13, 41, 30}, {37, 36, 39, 40, 31}, {35, 34, 33, 38, 32}},
    4,
    {{4, 6}, {5, 7}, {8, 10}, {9, 11}},
    {{0, 1}, {2, 3}},
    {24, 26, 27, 25},
    {28, 12},
    true,
    {{18, 19}, {17, 16}},  // QWIIC1 shares 17/16 with Serial4 (TX4/RX4)
};

}  // namespace stepdance
