// RPC subscriptions: change events for subscribed parameters and readers, and fault events.
#include "stepdance/hal/hal.hpp"
#include "stepdance/interfaces/rpc/rpc.hpp"

namespace stepdance {

RPC* RPC::fault_listener_ = nullptr;

namespace {

constexpr size_t kEventRoomNeeded = 320;  // an event is written only when it surely fits

}  // namespace

RPC::~RPC() {
  if (fault_listener_ == this) fault_listener_ = nullptr;
}

bool RPC::handle_subscription(const rpc::JsonRequest& request) {
  const bool adding = strcmp(request.name, "__subscribe__") == 0;
  if (!adding && strcmp(request.name, "__unsubscribe__") != 0) return false;
  if (!adding && request.arg_count == 0) {  // everything
    for (Subscription& subscription : subscriptions_) subscription = Subscription{};
    fault_events_ = false;
  } else if (request.arg_count != 1) {
    reply_error(11, "wrong number of arguments", request.id);
    return true;
  } else if (request.args[0].type != rpc::JsonValue::Type::kString) {
    reply_error(12, "wrong argument type", request.id);
    return true;
  } else if (adding) {
    const int code = subscribe(request.args[0].text);
    if (code != 0) {
      reply_error(code, code == 10 ? "Unknown Function or Parameter" : code == 15 ? "not a parameter or reader"
                                                                                 : "too many subscriptions",
                  request.id);
      return true;
    }
  } else if (strcmp(request.args[0].text, "__faults__") == 0) {
    fault_events_ = false;
  } else {
    for (Subscription& subscription : subscriptions_) {
      if (subscription.entry >= 0 && strcmp(entries_[subscription.entry].name, request.args[0].text) == 0) {
        subscription = Subscription{};
      }
    }
  }
  char storage[96];
  TextWriter reply(storage, sizeof(storage));
  reply.text("{\"result\":\"ok\"");
  if (request.id[0] != '\0') reply.text(",\"id\":").text(request.id);
  reply.character('}');
  send_line(reply);
  return true;
}

int RPC::subscribe(const char* name) {
  if (strcmp(name, "__faults__") == 0) {
    if (fault_listener_ != this) {
      if (fault_listener_ != nullptr || !on_fault(&RPC::on_fault_report)) return 16;
      fault_listener_ = this;
    }
    fault_events_ = true;
    return 0;
  }
  int entry = -1;
  for (size_t i = 0; i < entry_count_; ++i) {
    if (strcmp(entries_[i].name, name) == 0) entry = static_cast<int>(i);
  }
  if (entry < 0) return 10;
  if (!entries_[entry].watchable) return 15;
  Subscription* free_slot = nullptr;
  for (Subscription& subscription : subscriptions_) {
    if (subscription.entry == entry) return 0;  // already: nothing changes
    if (subscription.entry < 0 && free_slot == nullptr) free_slot = &subscription;
  }
  if (free_slot == nullptr) return 16;
  *free_slot = Subscription{};
  free_slot->entry = entry;
  return 0;
}

void RPC::on_fault_report(const FaultReport& report) {
  RPC* self = fault_listener_;
  if (self == nullptr || !self->fault_events_) return;
  if (self->pending_fault_count_ == kMaxPendingFaultEvents) {
    ++self->events_lost_;
    return;
  }
  self->pending_faults_[self->pending_fault_count_++] = report;
}

void RPC::send_events() {
  if (index_cursor_ >= 0) return;  // not in the middle of __index__'s line
  send_fault_events();
  const uint32_t now_us = hal::micros_now();
  for (Subscription& subscription : subscriptions_) {
    if (subscription.entry < 0) continue;
    if (subscription.sent && now_us - subscription.sent_us < kMinEventIntervalUs) continue;
    if (kReplyBufferBytes - reply_count_ < kEventRoomNeeded) return;
    Entry& entry = entries_[subscription.entry];
    char value_storage[64];
    TextWriter value(value_storage, sizeof(value_storage));
    const rpc::JsonRequest read;  // no arguments: a read
    if (!entry.invoke(entry, read, value)) continue;
    const char* text = value.c_str() + strlen(",\"return\":");
    if (subscription.sent && strcmp(text, subscription.last) == 0) continue;
    char storage[kMaxNameBytes + 128];
    TextWriter event(storage, sizeof(storage));
    event.text("{\"event\":\"changed\",\"name\":");
    write_string(event, entry.name);
    event.text(",\"value\":").text(text).character('}');
    send_line(event);
    strncpy(subscription.last, text, sizeof(subscription.last) - 1);
    subscription.sent = true;
    subscription.sent_us = now_us;
  }
}

void RPC::send_fault_events() {
  size_t sent = 0;
  while (sent < pending_fault_count_ && kReplyBufferBytes - reply_count_ >= kEventRoomNeeded) {
    const FaultReport& report = pending_faults_[sent++];
    char storage[256];
    TextWriter event(storage, sizeof(storage));
    event.text("{\"event\":\"fault\",\"level\":");
    write_string(event, to_string(report.level));
    event.text(",\"reason\":");
    write_string(event, to_string(report.reason));
    event.text(",\"source\":");
    write_string(event, report.source);
    event.text(",\"detail\":");
    write_string(event, report.detail);
    event.text(",\"sequence\":").unsigned_number(report.sequence).character('}');
    send_line(event);
  }
  for (size_t i = sent; i < pending_fault_count_; ++i) pending_faults_[i - sent] = pending_faults_[i];
  pending_fault_count_ -= sent;
}

}  // namespace stepdance
