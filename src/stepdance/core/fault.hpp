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

/// One report on the fault path, as subscribers and readers see it. Strings are static.
struct FaultReport {
  FaultLevel level = FaultLevel::kWarning;
  FaultReason reason = FaultReason::kNone;
  const char* source = "";  ///< the block or interface that reported, e.g. "tbi", "gcode"
  const char* detail = "";
  uint32_t time_us = 0;   ///< hal::micros_now() when reported
  uint32_t sequence = 0;  ///< 1 for the first report since start or clear_fault(), then +1
};

/// Reports kept for reading and for subscribers (the newest; older ones are overwritten and
/// counted in fault_reports_lost()).
constexpr uint32_t kFaultReportHistory = 16;
/// Subscribers on_fault() accepts.
constexpr uint32_t kMaxFaultSubscribers = 4;

/// Calls `subscriber` with every report from now on, in the loop (from dance_loop), never in the
/// frame, in report order. Returns false (nothing changes) when kMaxFaultSubscribers are taken
/// or `subscriber` is null. Context: loop.
using FaultSubscriber = void (*)(const FaultReport& report);
bool on_fault(FaultSubscriber subscriber);
/// Removes every subscriber. Context: loop.
void clear_fault_subscribers();
/// Hands reports made since the last call to the subscribers; dance_loop calls it. Context: loop.
void deliver_fault_reports();

/// The most serious condition in force: kFatal after fault() (until restart), kAlarm while an
/// alarm is raised, else kWarning if any warning was reported since start, else 0 (healthy).
/// Context: any.
uint8_t fault_level();
/// The `age`-th newest report (0 = newest); false if there is no such report kept. Context: loop.
bool recent_fault_report(uint32_t age, FaultReport& out);
/// Reports dropped from the history before subscribers saw them (more than kFaultReportHistory
/// between two dance_loop passes). Context: any.
uint32_t fault_reports_lost();

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

/// One kind of warning (a source and a reason) and how often it came since start or
/// clear_fault(). Strings are static.
struct WarningTally {
  const char* source = "";
  FaultReason reason = FaultReason::kNone;
  const char* detail = "";  ///< the first report's detail ("" if the kind was only counted)
  uint32_t count = 0;
};
/// Kinds of warning tallied; further kinds count in warning_count() only.
constexpr uint32_t kWarningKinds = 8;
/// Counts one more warning of a kind without a report of its own (a repeat whose first instance
/// was reported with its detail): no history entry, no subscriber call. Context: any (frame ISR
/// included); never allocates, never blocks.
void count_warning(FaultReason reason, const char* source);
/// The `index`-th kind of warning seen (0 = the first), with its count; false past the last.
/// Context: any.
bool warning_tally(uint32_t index, WarningTally& out);
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
