// The single fault path's state and the hand-off to the backend's safe state.
#include "stepdance/core/fault.hpp"

#include "stepdance/core/engine.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {
volatile FaultReason first_reason = FaultReason::kNone;
const char* volatile first_detail = "";
volatile uint32_t count = 0;
volatile uint32_t warnings = 0;
volatile bool alarm_raised = false;

// Report history: a ring written under a critical section from any context, read in the loop.
FaultReport history[kFaultReportHistory];
volatile uint32_t reports_made = 0;  // sequence number of the newest report
uint32_t reports_delivered = 0;      // loop only: newest sequence handed to subscribers
volatile uint32_t reports_lost = 0;
FaultSubscriber subscribers[kMaxFaultSubscribers] = {};
WarningTally tallies[kWarningKinds];
uint32_t tally_count = 0;

// Sources are usually string literals, so the pointer test decides most calls; the loop covers the
// same text from two translation units.
bool same_source(const char* a, const char* b) {
  if (a == b) return true;
  while (*a != '\0' && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

// Adds one to the kind's tally (a new kind keeps `detail`). Call inside a critical section.
// Warnings can repeat at frame rate (a refused pulse, an underrun), so they are tallied per
// (reason, source) instead of stored one by one; a full tally table still counts in `warnings`.
void tally_warning(FaultReason reason, const char* source, const char* detail) {
  warnings = warnings + 1;
  for (uint32_t i = 0; i < tally_count; ++i) {
    if (tallies[i].reason == reason && same_source(tallies[i].source, source)) {
      ++tallies[i].count;
      return;
    }
  }
  if (tally_count == kWarningKinds) return;
  tallies[tally_count++] = WarningTally{source, reason, detail, 1};
}

void fault_without_report(FaultReason reason, const char* detail);

// Any context, frame ISR included: a fixed ring, no allocation, no I/O. When the loop falls behind,
// the oldest reports are overwritten and counted as lost at delivery.
void record(FaultLevel level, FaultReason reason, const char* source, const char* detail) {
  hal::CriticalSection guard;
  const uint32_t sequence = reports_made + 1;
  FaultReport& slot = history[(sequence - 1) % kFaultReportHistory];
  slot.level = level;
  slot.reason = reason;
  slot.source = source != nullptr ? source : "";
  slot.detail = detail != nullptr ? detail : "";
  slot.time_us = hal::micros_now();
  slot.sequence = sequence;
  reports_made = sequence;
}
}  // namespace

const char* to_string(FaultReason reason) {
  switch (reason) {
    case FaultReason::kNone: return "none";
    case FaultReason::kRegistryFull: return "registry full";
    case FaultReason::kQueueFull: return "queue full";
    case FaultReason::kInvariant: return "invariant broken";
    case FaultReason::kHardware: return "hardware error";
    case FaultReason::kBadConfiguration: return "bad configuration";
    case FaultReason::kUnreachable: return "unreachable";
    case FaultReason::kOverrun: return "overrun";
    case FaultReason::kRefused: return "refused";
    case FaultReason::kLimitHit: return "limit hit";
    case FaultReason::kTimeout: return "timeout";
    case FaultReason::kPlanner: return "planner";
  }
  return "unknown";
}

const char* to_string(FaultLevel level) {
  switch (level) {
    case FaultLevel::kWarning: return "warning";
    case FaultLevel::kAlarm: return "alarm";
    case FaultLevel::kFatal: return "fatal";
  }
  return "unknown";
}

// Three levels: a warning counts and goes on; an alarm stays raised until clear_alarm() (interfaces
// map it to their own alarm state, e.g. Grbl's); fatal stops the machine at once.
void report_fault(FaultLevel level, FaultReason reason, const char* source, const char* detail) {
  record(level, reason, source, detail);
  if (level == FaultLevel::kFatal) {
    fault_without_report(reason, detail);
    return;
  }
  hal::CriticalSection guard;
  if (level == FaultLevel::kAlarm)
    alarm_raised = true;
  else
    tally_warning(reason, source != nullptr ? source : "", detail != nullptr ? detail : "");
}

void count_warning(FaultReason reason, const char* source) {
  hal::CriticalSection guard;
  tally_warning(reason, source != nullptr ? source : "", "");
}

bool warning_tally(uint32_t index, WarningTally& out) {
  hal::CriticalSection guard;
  if (index >= tally_count) return false;
  out = tallies[index];
  return true;
}

bool on_fault(FaultSubscriber subscriber) {
  if (subscriber == nullptr) return false;
  for (FaultSubscriber& slot : subscribers) {
    if (slot != nullptr) continue;
    slot = subscriber;
    return true;
  }
  return false;
}

void clear_fault_subscribers() {
  for (FaultSubscriber& slot : subscribers) slot = nullptr;
}

// Loop context. Copies each report out under a critical section (an ISR may be writing the ring) and
// calls the subscribers outside it, so a slow subscriber never holds interrupts off.
void deliver_fault_reports() {
  const uint32_t newest = reports_made;
  if (newest - reports_delivered > kFaultReportHistory) {
    hal::CriticalSection guard;
    reports_lost = reports_lost + (newest - reports_delivered - kFaultReportHistory);
    reports_delivered = newest - kFaultReportHistory;
  }
  while (reports_delivered != newest) {
    FaultReport report;
    {
      hal::CriticalSection guard;
      report = history[reports_delivered % kFaultReportHistory];
    }
    ++reports_delivered;
    for (FaultSubscriber subscriber : subscribers) {
      if (subscriber != nullptr) subscriber(report);
    }
  }
}

// The highest level in force: fatal, then alarm, then warning, 0 for none.
uint8_t fault_level() {
  if (first_reason != FaultReason::kNone) return static_cast<uint8_t>(FaultLevel::kFatal);
  if (alarm_raised) return static_cast<uint8_t>(FaultLevel::kAlarm);
  return warnings > 0 ? static_cast<uint8_t>(FaultLevel::kWarning) : 0;
}

bool recent_fault_report(uint32_t age, FaultReport& out) {
  hal::CriticalSection guard;
  if (age >= kFaultReportHistory || age >= reports_made) return false;
  out = history[(reports_made - 1 - age) % kFaultReportHistory];
  return true;
}

uint32_t fault_reports_lost() { return reports_lost; }

uint32_t warning_count() { return warnings; }
bool alarm_active() { return alarm_raised; }
void clear_alarm() { alarm_raised = false; }

// The fatal path for the core's own broken invariants; the source is "core".
void fault(FaultReason reason, const char* detail) {
  record(FaultLevel::kFatal, reason, "core", detail);
  fault_without_report(reason, detail);
}

namespace {
// Only the first fatal fault is kept (later ones are usually consequences); all are counted. The
// safe state is entered once, by the first, outside the critical section.
void fault_without_report(FaultReason reason, const char* detail) {
  {
    hal::CriticalSection guard;
    count = count + 1;
    if (first_reason != FaultReason::kNone) return;
    first_reason = reason;
    first_detail = detail != nullptr ? detail : "";
  }
  hal::enter_safe_state();
  // The safe state stopped the timers: the engine must know, or a dance_start() after
  // clear_fault() would report kOk without restarting the frames.
  engine().stop();
  hal::log_fault(to_string(reason), first_detail);
}
}  // namespace

FaultReason fault_reason() { return first_reason; }
const char* fault_detail() { return first_detail; }
uint32_t fault_count() { return count; }

// Clears the record only: the engine stays stopped until dance_start() is called again.
void clear_fault() {
  hal::CriticalSection guard;
  first_reason = FaultReason::kNone;
  first_detail = "";
  count = 0;
  warnings = 0;
  tally_count = 0;
  alarm_raised = false;
  reports_made = 0;
  reports_delivered = 0;
  reports_lost = 0;
}

}  // namespace stepdance
