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
  kUnreachable,       ///< a kinematics pose outside the machine's workspace (held at the last valid one)
  kOverrun,           ///< a buffer or deadline was overrun (recorder, frame budget)
  kRefused,           ///< a host or user command was refused
  kLimitHit,          ///< a limit switch or soft limit was hit
  kTimeout,           ///< an operation did not finish in time (homing)
  kPlanner,           ///< the motion planner could not keep its guarantees
};

/// How serious a report is. The levels are ordered: a higher one implies the lower ones' effects.
///  - kWarning: counted and reported; motion goes on.
///  - kAlarm:   planned motion stops within its acceleration limit and queues are flushed; live
///              inputs keep working; cleared explicitly by the sketch or the host.
///  - kFatal:   outputs stop at once and drivers are disabled; cleared only by a restart.
enum class FaultLevel : uint8_t {
  kWarning = 1,
  kAlarm = 2,
  kFatal = 3,
};

/// A short name for a fault level (never null).
const char* to_string(FaultLevel level);

/// A short name for a fault reason (never null).
const char* to_string(FaultReason reason);

/// Records the first fault, tells the backend to put every output in its safe state
/// (frames stop, drivers disabled) and logs `detail`. Later faults are counted, not recorded.
/// Context: any (frame ISR included); never returns an error and never allocates.
/// @param detail static string naming what failed, for example "pre-channel blocks".
void fault(FaultReason reason, const char* detail);

/// Reports a problem at a level, naming its source (a block or interface, e.g. "tbi") and a
/// reason. kFatal behaves as fault(reason, detail). Strings must be static (they are kept).
/// Context: any (frame ISR included); never allocates, never blocks.
void report_fault(FaultLevel level, FaultReason reason, const char* source, const char* detail = "");

/// Warnings reported since start or clear_fault(). Context: any.
uint32_t warning_count();
/// True while an alarm is raised and not yet cleared. Context: any.
bool alarm_active();
/// Clears a raised alarm (the sketch's or host's explicit acknowledgement). Context: loop.
void clear_alarm();

/// The first fault since start or since clear_fault(); kNone if healthy. Context: any.
FaultReason fault_reason();
/// The detail text of the first fault ("" if none). Context: any.
const char* fault_detail();
/// Number of fault() calls since start or clear_fault(). Context: any.
uint32_t fault_count();
/// Forgets the recorded fault (tests, or a user-acknowledged restart). Context: loop.
void clear_fault();

}  // namespace stepdance
