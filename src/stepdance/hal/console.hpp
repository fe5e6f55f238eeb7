// Part of the HAL facade (see hal.hpp): the board's console stream, which a backend defines.
#pragma once

#include "stepdance/core/byte_stream.hpp"

namespace stepdance::hal {

/// The board's console stream (USB serial on a Teensy, the simulator's console log, a buffer on
/// the manual backend). Bytes pass unchanged and in order both ways. Context: loop.
ByteStream& console();

}  // namespace stepdance::hal
