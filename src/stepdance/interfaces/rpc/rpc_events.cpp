// RPC subscriptions as requests (__subscribe__, __unsubscribe__) and their events in the replies.
#include "stepdance/hal/hal.hpp"
#include "stepdance/interfaces/rpc/rpc.hpp"

namespace stepdance {

namespace {

constexpr size_t kEventRoomNeeded = 320;  // an event is written only when it surely fits

const char* subscribe_error_text(int code) {
  if (code == 10) return "Unknown Function or Parameter";
  return code == 15 ? "not a parameter or reader" : "too many subscriptions";
}

}  // namespace

// __subscribe__(name) and __unsubscribe__(name), or __unsubscribe__() for everything. Subscribing twice
// is not an error; codes 10, 15 and 16 as docs/rpc.md lists them.
bool RPC::handle_subscription(const rpc::JsonRequest& request) {
  const bool adding = strcmp(request.name, "__subscribe__") == 0;
  if (!adding && strcmp(request.name, "__unsubscribe__") != 0) return false;
  if (!adding && request.arg_count == 0) {  // everything
    subscriptions_.unsubscribe_all();
    reply_ok(request.id);
  } else if (request.arg_count != 1) {
    reply_error(11, "wrong number of arguments", request.id);
  } else if (request.args[0].type != rpc::JsonValue::Type::kString) {
    reply_error(12, "wrong argument type", request.id);
  } else if (adding) {
    const int code = subscriptions_.subscribe(registry_, request.args[0].text);
    if (code != 0) {
      reply_error(code, subscribe_error_text(code), request.id);
    } else {
      reply_ok(request.id);
    }
  } else {
    subscriptions_.unsubscribe(registry_, request.args[0].text);
    reply_ok(request.id);
  }
  return true;
}

// Loop context. Events go out only between whole reply lines (never inside an __index__ line) and
// only when one surely fits, so a slow host delays events instead of receiving a cut line.
void RPC::send_events() {
  if (index_cursor_ >= 0) return;  // not in the middle of __index__'s line
  send_fault_events();
  const uint32_t now_us = hal::micros_now();
  for (size_t slot = 0; slot < kMaxSubscriptions; ++slot) {
    if (!replies_.reserve(kEventRoomNeeded)) return;
    char storage[kMaxNameBytes + 128];
    TextWriter event(storage, sizeof(storage));
    if (subscriptions_.change_event(slot, registry_, now_us, event)) replies_.send_line(event);
  }
}

// Fault events first, all that fit: they are rarer and matter more than value changes.
void RPC::send_fault_events() {
  while (replies_.reserve(kEventRoomNeeded)) {
    char storage[256];
    TextWriter event(storage, sizeof(storage));
    if (!subscriptions_.fault_event(event)) return;
    replies_.send_line(event);
  }
}

}  // namespace stepdance
