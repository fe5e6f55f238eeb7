// The single fault path: a broken invariant or overflow is recorded and the outputs go safe.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Why the system faulted. Stable numbering: it is reported over serial and in simulator summaries.
enum class FaultReason : uint8_t {
  kNone = 0,
  kRegistryFull,      ///< a block, channel or port did not fit its fixed registry
  kQueueFull,         ///< a queue that must never fill did
  kInvariant,         ///< an internal consistency check failed
  kHardware,          ///< the backend reported a hardware error
  kBadConfiguration,  ///< an impossible configuration (wrong pin, missing peripheral)
};

/// A short name for a fault reason (never null).
const char* to_string(FaultReason reason);

/// Records the first fault, tells the backend to put every output in its safe state
/// (frames stop, drivers disabled) and logs `detail`. Later faults are counted, not recorded.
/// Context: any (frame ISR included); never returns an error and never allocates.
/// @param detail static string naming what failed, for example "pre-channel blocks".
void fault(FaultReason reason, const char* detail);

/// The first fault since start or since clear_fault(); kNone if healthy. Context: any.
FaultReason fault_reason();
/// The detail text of the first fault ("" if none). Context: any.
const char* fault_detail();
/// Number of fault() calls since start or clear_fault(). Context: any.
uint32_t fault_count();
/// Forgets the recorded fault (tests, or a user-acknowledged restart). Context: loop.
void clear_fault();

}  // namespace stepdance
