// RPC subscriptions: watched names, change events, and fault reports queued as events.
#include "stepdance/interfaces/rpc/rpc_subscriptions.hpp"

#include <string.h>

#include "stepdance/interfaces/rpc/json_text.hpp"

namespace stepdance::rpc {

Subscriptions* Subscriptions::fault_listener_ = nullptr;

Subscriptions::~Subscriptions() {
  if (fault_listener_ == this) fault_listener_ = nullptr;
}

// Only readers and parameters can be watched (code 15): watching calls them repeatedly, so a function
// with side effects must not be. on_fault() takes a plain function with no context pointer, so the
// listener is found through a static: one Subscriptions object listens at a time (code 16 for another).
int Subscriptions::subscribe(const Registry& registry, const char* name) {
  if (strcmp(name, kFaults) == 0) {
    if (fault_listener_ != this) {
      if (fault_listener_ != nullptr || !on_fault(&Subscriptions::on_fault_report)) return 16;
      fault_listener_ = this;
    }
    fault_events_ = true;
    return 0;
  }
  const int entry = registry.find(name);
  if (entry < 0) return 10;
  if (!registry.at(entry).watchable) return 15;
  Slot* free_slot = nullptr;
  for (Slot& slot : slots_) {
    if (slot.entry == entry) return 0;  // already: nothing changes
    if (slot.entry < 0 && free_slot == nullptr) free_slot = &slot;
  }
  if (free_slot == nullptr) return 16;
  *free_slot = Slot{};
  free_slot->entry = entry;
  return 0;
}

void Subscriptions::unsubscribe(const Registry& registry, const char* name) {
  if (strcmp(name, kFaults) == 0) {
    fault_events_ = false;
    return;
  }
  for (Slot& slot : slots_) {
    if (slot.entry >= 0 && strcmp(registry.at(slot.entry).name, name) == 0) slot = Slot{};
  }
}

void Subscriptions::unsubscribe_all() {
  for (Slot& slot : slots_) slot = Slot{};
  fault_events_ = false;
}

// Loop context. The value is compared as its JSON text, so only a change that shows in the reply
// makes an event, and each name sends at most one event per kMinEventIntervalUs (20 ms, 50/s).
// The unsigned subtraction is correct across the 32-bit microsecond wrap (~71 minutes).
bool Subscriptions::change_event(size_t slot_index, Registry& registry, uint32_t now_us, TextWriter& event) {
  Slot& slot = slots_[slot_index];
  if (slot.entry < 0) return false;
  if (slot.sent && now_us - slot.sent_us < kMinEventIntervalUs) return false;
  Entry& entry = registry.at(slot.entry);
  char value_storage[64];
  TextWriter value(value_storage, sizeof(value_storage));
  const JsonRequest read;  // no arguments: a read
  if (!entry.invoke(entry, read, value).ok()) return false;
  const char* text = value.c_str() + strlen(",\"return\":");
  if (slot.sent && strcmp(text, slot.last) == 0) return false;
  event.text("{\"event\":\"changed\",\"name\":");
  write_json_string(event, entry.name);
  event.text(",\"value\":").text(text).character('}');
  strncpy(slot.last, text, sizeof(slot.last) - 1);
  slot.sent = true;
  slot.sent_us = now_us;
  return true;
}

// Called by the fault path in loop context (on_fault, core/fault.hpp), so no locking is needed. A full
// queue counts the loss instead of overwriting an older report.
void Subscriptions::on_fault_report(const FaultReport& report) {
  Subscriptions* self = fault_listener_;
  if (self == nullptr || !self->fault_events_) return;
  if (self->pending_fault_count_ == kMaxPendingFaultEvents) {
    ++self->events_lost_;
    return;
  }
  self->pending_faults_[self->pending_fault_count_++] = report;
}

// Oldest first; the queue is small (kMaxPendingFaultEvents), so shifting it down is cheap.
bool Subscriptions::fault_event(TextWriter& event) {
  if (pending_fault_count_ == 0) return false;
  const FaultReport report = pending_faults_[0];
  for (size_t i = 1; i < pending_fault_count_; ++i) pending_faults_[i - 1] = pending_faults_[i];
  --pending_fault_count_;
  event.text("{\"event\":\"fault\",\"level\":");
  write_json_string(event, to_string(report.level));
  event.text(",\"reason\":");
  write_json_string(event, to_string(report.reason));
  event.text(",\"source\":");
  write_json_string(event, report.source);
  event.text(",\"detail\":");
  write_json_string(event, report.detail);
  event.text(",\"sequence\":").unsigned_number(report.sequence).character('}');
  return true;
}

}  // namespace stepdance::rpc
