// RPC subscriptions: which names and faults a host asked to be told about, and their events.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/rpc/rpc_registry.hpp"

namespace stepdance::rpc {

/// Up to kMaxSubscriptions watched names (parameters and readers) and the fault events. A
/// watched value's event line is made when it has changed since it was last sent, at most every
/// kMinEventIntervalUs per name; fault reports wait (up to kMaxPendingFaultEvents, more are
/// counted as lost) until there is room to send them. Only one Subscriptions at a time can take
/// fault events (the fault path gives its subscribers no context). No heap.
class Subscriptions {
 public:
  static constexpr size_t kMaxSubscriptions = 8;
  static constexpr uint32_t kMinEventIntervalUs = 20000;  // 50 change events per second per name
  static constexpr size_t kMaxPendingFaultEvents = 4;
  static constexpr const char* kFaults = "__faults__";

  Subscriptions() = default;
  ~Subscriptions();
  Subscriptions(const Subscriptions&) = delete;
  Subscriptions& operator=(const Subscriptions&) = delete;

  /// Watches `name` (an entry of `registry`, or kFaults). 0 when watched (already or now), else
  /// the error code: 10 unknown name, 15 neither a parameter nor a reader, 16 no room (or
  /// another RPC takes the fault events). Context: loop.
  int subscribe(const Registry& registry, const char* name);
  /// Stops watching `name` (kFaults: the fault events). Context: loop.
  void unsubscribe(const Registry& registry, const char* name);
  /// Stops everything. Context: loop.
  void unsubscribe_all();

  /// The change event of subscription `slot` when it is due and its value changed:
  /// {"event":"changed","name":…,"value":…} written to `event`, true. Context: loop.
  bool change_event(size_t slot, Registry& registry, uint32_t now_us, TextWriter& event);
  /// The oldest waiting fault report as {"event":"fault",…}, taken from the queue; false when
  /// none waits. Context: loop.
  bool fault_event(TextWriter& event);
  /// Fault events that did not fit kMaxPendingFaultEvents. Context: any.
  uint32_t events_lost() const { return events_lost_; }

 private:
  struct Slot {
    int entry = -1;  ///< -1: free
    bool sent = false;
    uint32_t sent_us = 0;
    char last[32] = {};  ///< the value as last sent, as JSON text
  };
  static void on_fault_report(const FaultReport& report);

  Slot slots_[kMaxSubscriptions];
  bool fault_events_ = false;
  FaultReport pending_faults_[kMaxPendingFaultEvents];
  size_t pending_fault_count_ = 0;
  uint32_t events_lost_ = 0;
  static Subscriptions* fault_listener_;  // the one whose host asked for fault events
};

}  // namespace stepdance::rpc
