// Part of the HAL facade (see hal.hpp): the board's non-volatile byte store, which a backend defines.
#pragma once

#include "stepdance/core/nonvolatile_store.hpp"

namespace stepdance::hal {

/// The board's non-volatile store (EEPROM emulation on a Teensy 4.x, a file of the board's storage
/// folder in the simulator, memory on the manual backend). Context: loop.
NonvolatileStore& nonvolatile_store();

}  // namespace stepdance::hal
