// RPC: the sketch's functions, parameters and blocks, called by name over a serial line as JSON.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <type_traits>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/link/line_reader.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"
#include "stepdance/interfaces/link/serial_link.hpp"
#include "stepdance/interfaces/rpc/json_request.hpp"
#include "stepdance/interfaces/rpc/rpc_arguments.hpp"
#include "stepdance/interfaces/rpc/rpc_registry.hpp"
#include "stepdance/interfaces/rpc/rpc_subscriptions.hpp"

namespace stepdance {

class Channel;
class Encoder;
class KinematicsCoreXY;
class PositionGenerator;
class TimeBasedInterpolator;

/// Remote procedure calls over a serial line, compatible with the original library's format:
/// a request is one line `{"name": "<path>", "args": [...], "id": <any>}` ("args" and "id"
/// optional); the reply is one line `{"result":"ok"[,"return":<value>][,"id":<id>]}` or
/// `{"result":"error","error":"…","code":<n>[,"id":<id>]}` (the original's "error" key and
/// text, plus a code). `__index__` returns every enrolled
/// name with "function" or "parameter". A parameter is read with no arguments and written with
/// one. `__describe__` returns every name with its signature: "function <args> <return>" or
/// "parameter <type>", one letter per type (n number, i integer, b boolean, s string, v nothing;
/// "-" for no arguments), e.g. "function nnn i" — so a host can build a form for each name.
/// A host that wants to be told of changes subscribes: `__subscribe__` with a parameter's or a
/// reader's name (a port's read, a const method without arguments) gets
/// `{"event":"changed","name":…,"value":…}` now and whenever the value changes (at most every
/// kMinEventIntervalUs per name); `__subscribe__` with "__faults__" gets
/// `{"event":"fault","level":…,"reason":…,"source":…,"detail":…,"sequence":…}` for every
/// report on the fault path. `__unsubscribe__` with the name (or no argument: everything) stops
/// them. Nothing is ever sent unasked, so a client of the original library sees no events.
/// Error codes: 1 malformed JSON, 2 no name, 3 too many / nested arguments, 4 too long,
/// 10 unknown name, 11 wrong argument count, 12 wrong argument type, 13 value out of range,
/// 14 line over kMaxLineBytes, 15 not a parameter or reader (cannot subscribe), 16 no room for
/// another subscription (kMaxSubscriptions).
///
/// Enrolled names live in a fixed registry of kMaxEntries (names up to kMaxNameBytes); an enroll
/// that does not fit is refused, counted (enroll_failures()) and reported as a warning. No heap,
/// no exceptions. Calls run in the loop, where the sketch's own code runs.
///
/// begin() serves the board's console (USB Serial), begin(&port) any Arduino Stream (`&Serial`,
/// `&SerialUSB1`), begin(&port, baud) a UART it opens first (link::LinkedProtocol). Context: loop.
class RPC : public Block, public link::LinkedProtocol<RPC> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "RPC"; }
  static constexpr size_t kMaxEntries = rpc::Registry::kMaxEntries;
  static constexpr size_t kMaxNameBytes = rpc::Registry::kMaxNameBytes;
  static constexpr size_t kMaxLineBytes = 512;
  static constexpr size_t kMaxSubscriptions = rpc::Subscriptions::kMaxSubscriptions;
  static constexpr uint32_t kMinEventIntervalUs = rpc::Subscriptions::kMinEventIntervalUs;
  static constexpr size_t kMaxPendingFaultEvents = rpc::Subscriptions::kMaxPendingFaultEvents;

  RPC() = default;
  RPC(const RPC&) = delete;
  RPC& operator=(const RPC&) = delete;

  /// A free function with up to eight numeric, boolean or string arguments, returning nothing, a
  /// number, a boolean or a string. Context: loop (setup).
  template <class Name, typename Ret, typename... Args>
  void enroll(const Name& name, Ret (*function)(Args...)) {
    static_assert(sizeof...(Args) <= rpc::JsonRequest::kMaxArgs, "RPC functions take at most eight arguments");
    rpc::Entry* entry = registry_.add(text_of(name), "", false);
    if (entry == nullptr) return;
    memcpy(entry->callable, &function, sizeof(function));
    entry->invoke = &rpc::invoke_function<Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
  }
  /// A method of an object, enrolled as "<instance_name>.<name>" (the blocks' names use this).
  /// Context: loop (setup).
  template <class Name1, class Name2, class Obj, typename Ret, typename... Args>
  void enroll(const Name1& instance_name, const Name2& name, Obj& instance, Ret (Obj::*method)(Args...)) {
    static_assert(sizeof(method) <= sizeof(rpc::Entry::callable), "member pointer too large");
    rpc::Entry* entry = add_method(text_of(instance_name), text_of(name), &instance, &method, sizeof(method));
    if (entry == nullptr) return;
    entry->invoke = &rpc::invoke_method<Obj, Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
  }
  /// A const method of an object (a reader such as encoder.read), as above.
  template <class Name1, class Name2, class Obj, typename Ret, typename... Args>
  void enroll(const Name1& instance_name, const Name2& name, Obj& instance, Ret (Obj::*method)(Args...) const) {
    static_assert(sizeof(method) <= sizeof(rpc::Entry::callable), "member pointer too large");
    rpc::Entry* entry = add_method(text_of(instance_name), text_of(name), &instance, &method, sizeof(method));
    if (entry == nullptr) return;
    entry->invoke = &rpc::invoke_const_method<Obj, Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
    entry->watchable = sizeof...(Args) == 0 && !std::is_void_v<Ret>;
  }
  /// A variable (int, float, double, bool, a ControlParameter …): read or written by name.
  /// Context: loop (setup).
  template <class Name, typename T, typename = std::enable_if_t<std::is_arithmetic_v<std::remove_cv_t<T>>>>
  void enroll(const Name& name, T& parameter) {
    enroll_parameter(text_of(name), "", parameter);
  }
  /// A block's variable as "<instance_name>.<name>". Context: loop (setup).
  template <typename T, typename = std::enable_if_t<std::is_arithmetic_v<std::remove_cv_t<T>>>>
  void enroll_parameter(const char* instance_name, const char* name, T& parameter) {
    rpc::Entry* entry = registry_.add(instance_name, name, true);
    if (entry == nullptr) return;
    entry->object = const_cast<std::remove_cv_t<T>*>(&parameter);
    entry->invoke = &rpc::invoke_parameter<std::remove_cv_t<T>>;
    entry->signature = rpc::ParameterSignature<std::remove_cv_t<T>>::text;
  }
  /// A block's BlockPort as "<instance_name>.<name>.read" etc. Context: loop (setup).
  void enroll_port(const char* instance_name, const char* name, BlockPort& port);
  /// A block: the names the original library gives its class, under "<name>." (docs/rpc.md;
  /// Channel, Encoder, TimeBasedInterpolator, PositionGenerator, KinematicsCoreXY). Its own type
  /// picks them at compile time; a block of another class enrolls nothing. Context: loop (setup).
  template <class Name, class B, std::enable_if_t<std::is_base_of_v<Block, B>, int> = 0>
  void enroll(const Name& name, B& block) {
    enroll_block(text_of(name), block);
  }
  /// A BlockPort: "<name>.read" (absolute, world units), "<name>.read_deep", "<name>.reset_deep".
  /// Context: loop (setup).
  template <class Name>
  void enroll(const Name& name, BlockPort& port) {
    registry_.add_port(text_of(name), port);
  }

  /// Names that did not fit the registry (or were too long). Context: any.
  uint32_t enroll_failures() const { return registry_.failures(); }
  size_t enrolled() const { return registry_.count(); }
  /// Requests answered with an error since begin. Context: any.
  uint32_t errors_replied() const { return errors_replied_; }
  /// Fault events that did not fit kMaxPendingFaultEvents before they could be sent. Context: any.
  uint32_t events_lost() const { return subscriptions_.events_lost(); }

  /// Reads requests and answers them. Context: loop (dance_loop).
  void loop() override;

 private:
  friend class link::LinkedProtocol<RPC>;

  static const char* text_of(const char* text) { return text; }
  template <class S>
  static auto text_of(const S& text) -> decltype(text.c_str()) {
    return text.c_str();
  }
  Status begin_stream(ByteStream& stream);
  rpc::Entry* add_method(const char* instance_name, const char* name, void* instance, const void* method,
                         size_t method_bytes);
  // The names of each block class (rpc_enroll_blocks.cpp); other blocks have none.
  void enroll_block(const char* name, Channel& channel);
  void enroll_block(const char* name, Encoder& encoder);
  void enroll_block(const char* name, KinematicsCoreXY& kinematics);
  void enroll_block(const char* name, PositionGenerator& generator);
  void enroll_block(const char* name, TimeBasedInterpolator& interpolator);
  void enroll_block(const char* name, Block& block) {
    (void)name;
    (void)block;
  }

  void handle_line();
  void call(rpc::Entry& entry, const rpc::JsonRequest& request);
  void reply_index(const rpc::JsonRequest& request, bool describe);
  void continue_index();
  static void write_description(TextWriter& out, const rpc::Entry& entry);
  bool handle_subscription(const rpc::JsonRequest& request);
  void send_events();
  void send_fault_events();
  void reply_ok(const char* id);
  void reply_error(int code, const char* message, const char* id);
  void flush_replies();

  static constexpr size_t kReplyBufferBytes = 2048;
  rpc::Registry registry_;
  rpc::Subscriptions subscriptions_;
  uint32_t errors_replied_ = 0;
  // Lines end with LF; a CR before it is dropped; blank lines are passed over.
  link::LineReader<kMaxLineBytes> lines_{link::LineRules{false, true, true, false}};
  char pool_[kMaxLineBytes] = {};
  link::ReplyRing<kReplyBufferBytes> replies_;
  int index_cursor_ = -1;         // __index__ being sent: next entry, or −1
  bool index_describes_ = false;  // sending __describe__ rather than __index__
  char index_id_[rpc::JsonRequest::kMaxIdBytes + 1] = {};
};

}  // namespace stepdance
