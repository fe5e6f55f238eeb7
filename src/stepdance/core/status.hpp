// Result codes for recoverable errors: every fallible call returns one instead of throwing.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Outcome of a fallible call. kOk is zero so `if (status != Status::kOk)` reads naturally.
enum class Status : uint8_t {
  kOk = 0,
  kFull,         ///< a fixed-capacity container or registry has no room
  kEmpty,        ///< nothing to take from a queue
  kBadArgument,  ///< an argument is outside its documented range
  kNoSuchPin,    ///< the selected board has no such pin or peripheral
  kBusy,         ///< the resource is already in use
  kNotStarted,   ///< the call needs a begin() or dance_start() first
  kUnsupported,  ///< the backend cannot do this
  kIoError,      ///< storage or stream failure
};

/// A short, stable, human-readable name for a status (never null).
const char* to_string(Status status);

}  // namespace stepdance
