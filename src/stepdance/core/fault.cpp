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

void report_fault(FaultLevel level, FaultReason reason, const char* /*source*/, const char* detail) {
  if (level == FaultLevel::kFatal) {
    fault(reason, detail);
    return;
  }
  hal::CriticalSection guard;
  if (level == FaultLevel::kAlarm) alarm_raised = true;
  else warnings = warnings + 1;
}

uint32_t warning_count() { return warnings; }
bool alarm_active() { return alarm_raised; }
void clear_alarm() { alarm_raised = false; }

void fault(FaultReason reason, const char* detail) {
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

FaultReason fault_reason() { return first_reason; }
const char* fault_detail() { return first_detail; }
uint32_t fault_count() { return count; }

void clear_fault() {
  hal::CriticalSection guard;
  first_reason = FaultReason::kNone;
  first_detail = "";
  count = 0;
  warnings = 0;
  alarm_raised = false;
}

}  // namespace stepdance
