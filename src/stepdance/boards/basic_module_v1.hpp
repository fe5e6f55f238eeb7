// Stepdance Basic Module v1.0 (Teensy 4.0 or 4.1): one input and one output port, no drivers.
#pragma once

#include "stepdance/boards/board_definition.hpp"

namespace stepdance {

/// The Basic Module v1.0's table: the Driver Module's port A pins and encoders, its own A1–A4
/// and D1, no driver sockets, ENABLE, VREF or limit headers.
inline constexpr BoardDefinition kBasicModuleV1 = {
    "Basic Module v1.0",
    "basic",
    "module_basic",
    &kTeensy41,
    &kTeensy40,
    1,
    {{23, 22, kNoPin, kNoPin, kNoPin}, {}, {}, {}},
    1,
    {{4, 6}, {}, {}, {}},
    {{0, 1}, {2, 3}},
    {14, 15, 20, 21},
    {13, 12},
    false,
    {{18, 19}, {17, 16}},
};

}  // namespace stepdance
