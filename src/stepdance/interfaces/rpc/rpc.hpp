// RPC: the sketch's functions, parameters and blocks, called by name over a serial line as JSON.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <limits>
#include <type_traits>
#include <utility>

#include "stepdance/core/arduino_stream_adapter.hpp"
#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/interfaces/rpc/json_request.hpp"
#include "stepdance/core/text_writer.hpp"

namespace stepdance {

class Encoder;
class KinematicsCoreXY;
class PositionGenerator;
class TimeBasedInterpolator;

namespace rpc {
/// The __describe__ letter of an argument or return type. Context: compile time.
template <typename T>
constexpr char type_letter() {
  using U = std::remove_cv_t<std::remove_reference_t<T>>;
  if constexpr (std::is_void_v<U>) {
    return 'v';
  } else if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
    return 's';
  } else if constexpr (std::is_same_v<U, bool>) {
    return 'b';
  } else if constexpr (std::is_integral_v<U> || std::is_enum_v<U>) {
    return 'i';
  } else {
    return 'n';
  }
}
/// "<argument letters>:<return letter>", one static string per enrolled signature.
template <typename Ret, typename... Args>
struct FunctionSignature {
  static constexpr char text[sizeof...(Args) + 3] = {type_letter<Args>()..., ':', type_letter<Ret>(), '\0'};
};
/// "<type letter>" of a parameter.
template <typename T>
struct ParameterSignature {
  static constexpr char text[2] = {type_letter<T>(), '\0'};
};
}  // namespace rpc

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
class RPC : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "RPC"; }
  static constexpr size_t kMaxEntries = 96;
  static constexpr size_t kMaxNameBytes = 63;
  static constexpr size_t kMaxLineBytes = 512;
  static constexpr size_t kMaxSubscriptions = 8;
  static constexpr uint32_t kMinEventIntervalUs = 20000;  // 50 change events per second per name
  static constexpr size_t kMaxPendingFaultEvents = 4;

  RPC() = default;
  ~RPC();
  RPC(const RPC&) = delete;
  RPC& operator=(const RPC&) = delete;

  /// Serves the board's console (USB Serial). Context: loop.
  Status begin();
  /// Serves a port: `&Serial`, `&SerialUSB1`, any Arduino Stream. Context: loop.
  template <class Port>
  Status begin(Port* port) {
    return port == nullptr ? Status::kBadArgument : begin_stream(adapter_.attach(port));
  }
  /// Opens a UART at `baud` first. Context: loop.
  template <class Port>
  Status begin(Port* port, uint32_t baud, uint16_t format = 0) {
    if (port == nullptr) return Status::kBadArgument;
    open_port(port, baud, format);
    return begin(port);
  }

  /// A free function with up to eight numeric, boolean or string arguments, returning nothing, a
  /// number, a boolean or a string. Context: loop (setup).
  template <class Name, typename Ret, typename... Args>
  void enroll(const Name& name, Ret (*function)(Args...)) {
    static_assert(sizeof...(Args) <= rpc::JsonRequest::kMaxArgs, "RPC functions take at most eight arguments");
    Entry* entry = add(text_of(name), "", false);
    if (entry == nullptr) return;
    memcpy(entry->callable, &function, sizeof(function));
    entry->invoke = &invoke_function<Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
  }
  /// A method of an object, enrolled as "<instance_name>.<name>" (blocks use this in their
  /// enroll()). Context: loop.
  template <class Name1, class Name2, class Obj, typename Ret, typename... Args>
  void enroll(const Name1& instance_name, const Name2& name, Obj& instance, Ret (Obj::*method)(Args...)) {
    static_assert(sizeof(method) <= sizeof(Entry::callable), "member pointer too large");
    Entry* entry = add(text_of(instance_name), text_of(name), false);
    if (entry == nullptr) return;
    entry->object = &instance;
    memcpy(entry->callable, &method, sizeof(method));
    entry->invoke = &invoke_method<Obj, Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
  }
  /// A const method of an object (a reader such as encoder.read), as above.
  template <class Name1, class Name2, class Obj, typename Ret, typename... Args>
  void enroll(const Name1& instance_name, const Name2& name, Obj& instance, Ret (Obj::*method)(Args...) const) {
    static_assert(sizeof(method) <= sizeof(Entry::callable), "member pointer too large");
    Entry* entry = add(text_of(instance_name), text_of(name), false);
    if (entry == nullptr) return;
    entry->object = &instance;
    memcpy(entry->callable, &method, sizeof(method));
    entry->invoke = &invoke_const_method<Obj, Ret, Args...>;
    entry->signature = rpc::FunctionSignature<Ret, Args...>::text;
    entry->watchable = sizeof...(Args) == 0 && !std::is_void_v<Ret>;
  }
  /// A variable (int, float, double, bool, a ControlParameter …): read or written by name.
  template <class Name, typename T,
            typename = std::enable_if_t<std::is_arithmetic_v<std::remove_cv_t<T>>>>
  void enroll(const Name& name, T& parameter) {
    Entry* entry = add(text_of(name), "", true);
    if (entry == nullptr) return;
    entry->object = const_cast<std::remove_cv_t<T>*>(&parameter);
    entry->invoke = &invoke_parameter<std::remove_cv_t<T>>;
    entry->signature = rpc::ParameterSignature<std::remove_cv_t<T>>::text;
  }
  /// A block's variable as "<instance_name>.<name>". Context: loop.
  template <typename T, typename = std::enable_if_t<std::is_arithmetic_v<std::remove_cv_t<T>>>>
  void enroll_parameter(const char* instance_name, const char* name, T& parameter) {
    Entry* entry = add(instance_name, name, true);
    if (entry == nullptr) return;
    entry->object = const_cast<std::remove_cv_t<T>*>(&parameter);
    entry->invoke = &invoke_parameter<std::remove_cv_t<T>>;
    entry->signature = rpc::ParameterSignature<std::remove_cv_t<T>>::text;
  }
  /// A block's BlockPort as "<instance_name>.<name>.read" etc. Context: loop.
  void enroll_port(const char* instance_name, const char* name, BlockPort& port);
  /// A block: the names the original library gives its class, under "<name>." (docs/rpc.md;
  /// Encoder, TimeBasedInterpolator, PositionGenerator, KinematicsCoreXY). The block's own type
  /// picks them at compile time; a block of another class enrolls nothing. Context: loop (setup).
  template <class Name, class B, std::enable_if_t<std::is_base_of_v<Block, B>, int> = 0>
  void enroll(const Name& name, B& block) {
    enroll_block(text_of(name), block);
  }
  /// A BlockPort: "<name>.read" (absolute, world units), "<name>.read_deep", "<name>.reset_deep".
  template <class Name>
  void enroll(const Name& name, BlockPort& port) {
    enroll_port(text_of(name), port);
  }

  /// Names that did not fit the registry (or were too long). Context: any.
  uint32_t enroll_failures() const { return enroll_failures_; }
  size_t enrolled() const { return entry_count_; }
  /// Requests answered with an error since begin. Context: any.
  uint32_t errors_replied() const { return errors_replied_; }
  /// Fault events that did not fit kMaxPendingFaultEvents before they could be sent. Context: any.
  uint32_t events_lost() const { return events_lost_; }

  /// Reads requests and answers them. Context: loop (dance_loop).
  void loop() override;

 private:
  struct Entry {
    char name[kMaxNameBytes + 1] = {};
    bool parameter = false;
    void* object = nullptr;
    alignas(void*) unsigned char callable[2 * sizeof(void*)] = {};
    bool (*invoke)(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) = nullptr;
    const char* signature = "";  ///< static: "nnn:i" for a function, "n" for a parameter
    bool watchable = false;      ///< a parameter or a reader: may be subscribed to
  };
  struct Subscription {
    int entry = -1;  ///< -1: free
    bool sent = false;
    uint32_t sent_us = 0;
    char last[32] = {};  ///< the value as last sent, as JSON text
  };
  enum class ArgError : uint8_t { kNone, kType, kRange };

  static const char* text_of(const char* text) { return text; }
  template <class S>
  static auto text_of(const S& text) -> decltype(text.c_str()) {
    return text.c_str();
  }
  template <class Port>
  static auto open_port(Port* port, uint32_t baud, uint16_t format) -> decltype(port->begin(baud, format), void()) {
    port->begin(baud, format);
  }
  static void open_port(...) {}

  Status begin_stream(ByteStream& stream);
  // The names of each block class (rpc_enroll_blocks.cpp); other blocks have none.
  void enroll_block(const char* name, Encoder& encoder);
  void enroll_block(const char* name, KinematicsCoreXY& kinematics);
  void enroll_block(const char* name, PositionGenerator& generator);
  void enroll_block(const char* name, TimeBasedInterpolator& interpolator);
  void enroll_block(const char* name, Block& block) {
    (void)name;
    (void)block;
  }
  Entry* add(const char* prefix, const char* suffix, bool parameter);
  void continue_index();
  void enroll_port(const char* name, BlockPort& port);
  void handle_line();
  void reply_index(const rpc::JsonRequest& request, bool describe);
  bool handle_subscription(const rpc::JsonRequest& request);
  int subscribe(const char* name);
  void send_events();
  void send_fault_events();
  static void on_fault_report(const FaultReport& report);
  static void write_description(TextWriter& out, const Entry& entry);
  void reply_error(int code, const char* message, const char* id);
  void send_line(const TextWriter& line);
  void flush_replies();

  // ---- argument conversion and calls (templates: instantiated per enrolled signature) ----
  template <typename T>
  static ArgError check(const rpc::JsonValue& value) {
    using U = std::remove_cv_t<std::remove_reference_t<T>>;
    if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
      return value.type == rpc::JsonValue::Type::kString ? ArgError::kNone : ArgError::kType;
    } else if constexpr (std::is_same_v<U, bool>) {
      if (value.type == rpc::JsonValue::Type::kBool) return ArgError::kNone;
      return value.type == rpc::JsonValue::Type::kNumber ? ArgError::kNone : ArgError::kType;
    } else if constexpr (std::is_enum_v<U>) {
      return check<std::underlying_type_t<U>>(value);  // e.g. a PositionMode, as its number
    } else {
      static_assert(std::is_arithmetic_v<U>, "RPC arguments are numbers, booleans or strings");
      if (value.type == rpc::JsonValue::Type::kBool) return ArgError::kNone;
      if (value.type != rpc::JsonValue::Type::kNumber) return ArgError::kType;
      const double v = value.number;
      if (!(v == v) || v == std::numeric_limits<double>::infinity() || v == -std::numeric_limits<double>::infinity()) {
        return ArgError::kRange;
      }
      if constexpr (std::is_integral_v<U>) {
        if (v < static_cast<double>(std::numeric_limits<U>::min()) ||
            v > static_cast<double>(std::numeric_limits<U>::max())) {
          return ArgError::kRange;
        }
      } else if constexpr (std::is_same_v<U, float>) {
        if (v > std::numeric_limits<float>::max() || v < -std::numeric_limits<float>::max()) return ArgError::kRange;
      }
      return ArgError::kNone;
    }
  }
  template <typename T>
  static std::remove_cv_t<std::remove_reference_t<T>> as(const rpc::JsonValue& value) {
    using U = std::remove_cv_t<std::remove_reference_t<T>>;
    if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
      return const_cast<U>(value.text);
    } else if constexpr (std::is_same_v<U, bool>) {
      return value.type == rpc::JsonValue::Type::kBool ? value.boolean : value.number != 0.0;
    } else if constexpr (std::is_enum_v<U>) {
      return static_cast<U>(as<std::underlying_type_t<U>>(value));
    } else {
      const double v = value.type == rpc::JsonValue::Type::kBool ? (value.boolean ? 1.0 : 0.0) : value.number;
      return static_cast<U>(v);
    }
  }
  template <typename... Args, size_t... I>
  static bool check_all(const rpc::JsonRequest& request, TextWriter& reply, std::index_sequence<I...>) {
    if (request.arg_count != static_cast<int>(sizeof...(Args))) return reply_problem(reply, 11, "wrong number of arguments");
    ArgError errors[sizeof...(Args) + 1] = {check<Args>(request.args[I])..., ArgError::kNone};
    for (ArgError error : errors) {
      if (error == ArgError::kType) return reply_problem(reply, 12, "wrong argument type");
      if (error == ArgError::kRange) return reply_problem(reply, 13, "argument out of range");
    }
    return true;
  }
  template <typename Ret>
  static void write_return(TextWriter& reply, Ret value) {
    using U = std::remove_cv_t<Ret>;
    reply.text(",\"return\":");
    if constexpr (std::is_same_v<U, bool>) {
      reply.text(value ? "true" : "false");
    } else if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
      write_string(reply, value);
    } else {
      write_number(reply, static_cast<double>(value));
    }
  }
  template <typename Ret, typename... Args, size_t... I>
  static bool call_function(Ret (*function)(Args...), const rpc::JsonRequest& request, TextWriter& reply,
                            std::index_sequence<I...> indices) {
    if (!check_all<Args...>(request, reply, indices)) return false;
    if constexpr (std::is_void_v<Ret>) {
      function(as<Args>(request.args[I])...);
    } else {
      write_return<Ret>(reply, function(as<Args>(request.args[I])...));
    }
    return true;
  }
  template <typename Ret, typename... Args>
  static bool invoke_function(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) {
    Ret (*function)(Args...);
    memcpy(&function, entry.callable, sizeof(function));
    return call_function(function, request, reply, std::index_sequence_for<Args...>{});
  }
  template <class Obj, typename Ret, typename... Args, size_t... I>
  static bool call_method(Obj& instance, Ret (Obj::*method)(Args...), const rpc::JsonRequest& request,
                          TextWriter& reply, std::index_sequence<I...> indices) {
    if (!check_all<Args...>(request, reply, indices)) return false;
    if constexpr (std::is_void_v<Ret>) {
      (instance.*method)(as<Args>(request.args[I])...);
    } else {
      write_return<Ret>(reply, (instance.*method)(as<Args>(request.args[I])...));
    }
    return true;
  }
  template <class Obj, typename Ret, typename... Args>
  static bool invoke_method(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) {
    Ret (Obj::*method)(Args...);
    memcpy(&method, entry.callable, sizeof(method));
    return call_method(*static_cast<Obj*>(entry.object), method, request, reply, std::index_sequence_for<Args...>{});
  }
  template <class Obj, typename Ret, typename... Args, size_t... I>
  static bool call_const_method(const Obj& instance, Ret (Obj::*method)(Args...) const,
                                const rpc::JsonRequest& request, TextWriter& reply, std::index_sequence<I...> indices) {
    if (!check_all<Args...>(request, reply, indices)) return false;
    if constexpr (std::is_void_v<Ret>) {
      (instance.*method)(as<Args>(request.args[I])...);
    } else {
      write_return<Ret>(reply, (instance.*method)(as<Args>(request.args[I])...));
    }
    return true;
  }
  template <class Obj, typename Ret, typename... Args>
  static bool invoke_const_method(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) {
    Ret (Obj::*method)(Args...) const;
    memcpy(&method, entry.callable, sizeof(method));
    return call_const_method(*static_cast<const Obj*>(entry.object), method, request, reply,
                             std::index_sequence_for<Args...>{});
  }
  template <typename T>
  static bool invoke_parameter(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) {
    volatile T& parameter = *static_cast<volatile T*>(entry.object);
    if (request.arg_count == 0) {
      write_return<T>(reply, parameter);
      return true;
    }
    if (request.arg_count != 1) return reply_problem(reply, 11, "a parameter takes no argument (read) or one (write)");
    const ArgError error = check<T>(request.args[0]);
    if (error == ArgError::kType) return reply_problem(reply, 12, "wrong argument type");
    if (error == ArgError::kRange) return reply_problem(reply, 13, "argument out of range");
    parameter = as<T>(request.args[0]);
    return true;
  }
  static bool invoke_port(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply);
  /// Marks the reply as an error (the caller's builder restarts the line with it).
  static bool reply_problem(TextWriter& reply, int code, const char* message);
  static void write_number(TextWriter& out, double value);
  static void write_string(TextWriter& out, const char* text);

  ByteStream* stream_ = nullptr;
  ArduinoStreamAdapter adapter_;
  Entry entries_[kMaxEntries];
  size_t entry_count_ = 0;
  uint32_t enroll_failures_ = 0;
  uint32_t errors_replied_ = 0;
  char line_[kMaxLineBytes + 1] = {};
  size_t line_length_ = 0;
  bool line_overrun_ = false;
  char pool_[kMaxLineBytes] = {};
  static constexpr size_t kReplyBufferBytes = 2048;
  char replies_[kReplyBufferBytes] = {};
  size_t reply_head_ = 0;
  size_t reply_count_ = 0;
  int index_cursor_ = -1;  // __index__ being sent: next entry, or −1
  bool index_describes_ = false;  // sending __describe__ rather than __index__
  char index_id_[rpc::JsonRequest::kMaxIdBytes + 1] = {};
  Subscription subscriptions_[kMaxSubscriptions];
  bool fault_events_ = false;
  FaultReport pending_faults_[kMaxPendingFaultEvents];
  size_t pending_fault_count_ = 0;
  uint32_t events_lost_ = 0;
  static RPC* fault_listener_;  // the RPC whose host asked for fault events (on_fault takes no context)
  // An error found during a call: code and message, picked up by handle_line.
  static int pending_code_;
  static const char* pending_message_;
};

}  // namespace stepdance
