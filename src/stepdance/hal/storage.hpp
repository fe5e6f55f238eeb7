// Part of the HAL facade (see hal.hpp): the board's file storage, which a backend defines.
#pragma once

#include "stepdance/core/file_storage.hpp"

namespace stepdance::hal {

/// The board's file storage (an SD card on a Teensy 4.1, a folder in the simulator, memory on the
/// manual backend); open() fails with kUnsupported where there is none. Context: loop.
FileStorage& storage();

}  // namespace stepdance::hal
