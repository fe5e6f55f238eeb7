// RPC argument conversion: a request's JSON values checked and converted to a C++ signature's
// arguments, the call made, its return value written as JSON. Templates, instantiated once per
// enrolled signature.
#pragma once

#include <stddef.h>
#include <string.h>

#include <limits>
#include <type_traits>
#include <utility>

#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/rpc/json_request.hpp"
#include "stepdance/interfaces/rpc/json_text.hpp"
#include "stepdance/interfaces/rpc/rpc_registry.hpp"

namespace stepdance::rpc {

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

constexpr Problem kWrongCount{11, "wrong number of arguments"};
constexpr Problem kWrongType{12, "wrong argument type"};
constexpr Problem kOutOfRange{13, "argument out of range"};

/// A JSON number's fit for a numeric type: finite, and within an integer type's range or a
/// float's magnitude. Context: loop.
template <typename U>
Problem check_number(double value) {
  if (!(value == value) || value == std::numeric_limits<double>::infinity() ||
      value == -std::numeric_limits<double>::infinity()) {
    return kOutOfRange;
  }
  if constexpr (std::is_integral_v<U>) {
    if (value < static_cast<double>(std::numeric_limits<U>::min()) ||
        value > static_cast<double>(std::numeric_limits<U>::max())) {
      return kOutOfRange;
    }
  } else if constexpr (std::is_same_v<U, float>) {
    if (value > std::numeric_limits<float>::max() || value < -std::numeric_limits<float>::max()) return kOutOfRange;
  }
  return {};
}

/// Whether `value` can be an argument of type T: a string for a string, a boolean or number
/// for a boolean or number (an enum as its number). Context: loop.
template <typename T>
Problem check(const JsonValue& value) {
  using U = std::remove_cv_t<std::remove_reference_t<T>>;
  if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
    return value.type == JsonValue::Type::kString ? Problem{} : kWrongType;
  } else if constexpr (std::is_enum_v<U>) {
    return check<std::underlying_type_t<U>>(value);  // e.g. a PositionMode, as its number
  } else {
    static_assert(std::is_arithmetic_v<U>, "RPC arguments are numbers, booleans or strings");
    if (value.type == JsonValue::Type::kBool) return {};
    if (value.type != JsonValue::Type::kNumber) return kWrongType;
    if constexpr (std::is_same_v<U, bool>) return {};
    return check_number<U>(value.number);
  }
}

/// The argument of type T a checked value stands for (true is 1, a number is true unless 0).
/// Context: loop.
template <typename T>
std::remove_cv_t<std::remove_reference_t<T>> as(const JsonValue& value) {
  using U = std::remove_cv_t<std::remove_reference_t<T>>;
  if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
    return const_cast<U>(value.text);
  } else if constexpr (std::is_same_v<U, bool>) {
    return value.type == JsonValue::Type::kBool ? value.boolean : value.number != 0.0;
  } else if constexpr (std::is_enum_v<U>) {
    return static_cast<U>(as<std::underlying_type_t<U>>(value));
  } else {
    const double v = value.type == JsonValue::Type::kBool ? (value.boolean ? 1.0 : 0.0) : value.number;
    return static_cast<U>(v);
  }
}

/// The argument count, then each argument in order: the first that does not fit. Context: loop.
template <typename... Args, size_t... I>
Problem check_all(const JsonRequest& request, std::index_sequence<I...>) {
  if (request.arg_count != static_cast<int>(sizeof...(Args))) return kWrongCount;
  const Problem problems[sizeof...(Args) + 1] = {check<Args>(request.args[I])..., Problem{}};
  for (const Problem& problem : problems) {
    if (!problem.ok()) return problem;
  }
  return {};
}

/// Appends `,"return":<value>`: true/false, a JSON string or a number. Context: loop.
template <typename Ret>
void write_return(TextWriter& reply, Ret value) {
  using U = std::remove_cv_t<Ret>;
  reply.text(",\"return\":");
  if constexpr (std::is_same_v<U, bool>) {
    reply.text(value ? "true" : "false");
  } else if constexpr (std::is_same_v<U, const char*> || std::is_same_v<U, char*>) {
    write_json_string(reply, value);
  } else {
    write_json_number(reply, static_cast<double>(value));
  }
}

/// Checks the arguments, calls `call` with them converted, writes what it returns. Context: loop.
template <typename Ret, typename... Args, class Call, size_t... I>
Problem call_with(const Call& call, const JsonRequest& request, TextWriter& reply, std::index_sequence<I...> indices) {
  const Problem problem = check_all<Args...>(request, indices);
  if (!problem.ok()) return problem;
  if constexpr (std::is_void_v<Ret>) {
    call(as<Args>(request.args[I])...);
  } else {
    write_return<Ret>(reply, call(as<Args>(request.args[I])...));
  }
  return {};
}

/// Invoke of a free function (its pointer in entry.callable). Context: loop.
template <typename Ret, typename... Args>
Problem invoke_function(Entry& entry, const JsonRequest& request, TextWriter& reply) {
  Ret (*function)(Args...);
  memcpy(&function, entry.callable, sizeof(function));
  const auto call = [function](auto... arguments) -> Ret { return function(arguments...); };
  return call_with<Ret, Args...>(call, request, reply, std::index_sequence_for<Args...>{});
}

/// Invoke of a method of entry.object (the member pointer in entry.callable). Context: loop.
template <class Obj, typename Ret, typename... Args>
Problem invoke_method(Entry& entry, const JsonRequest& request, TextWriter& reply) {
  Ret (Obj::*method)(Args...);
  memcpy(&method, entry.callable, sizeof(method));
  Obj& instance = *static_cast<Obj*>(entry.object);
  const auto call = [&instance, method](auto... arguments) -> Ret { return (instance.*method)(arguments...); };
  return call_with<Ret, Args...>(call, request, reply, std::index_sequence_for<Args...>{});
}

/// Invoke of a const method (a reader). Context: loop.
template <class Obj, typename Ret, typename... Args>
Problem invoke_const_method(Entry& entry, const JsonRequest& request, TextWriter& reply) {
  Ret (Obj::*method)(Args...) const;
  memcpy(&method, entry.callable, sizeof(method));
  const Obj& instance = *static_cast<const Obj*>(entry.object);
  const auto call = [&instance, method](auto... arguments) -> Ret { return (instance.*method)(arguments...); };
  return call_with<Ret, Args...>(call, request, reply, std::index_sequence_for<Args...>{});
}

/// Invoke of a variable: read with no argument, written with one. Context: loop.
template <typename T>
Problem invoke_parameter(Entry& entry, const JsonRequest& request, TextWriter& reply) {
  volatile T& parameter = *static_cast<volatile T*>(entry.object);
  if (request.arg_count == 0) {
    write_return<T>(reply, parameter);
    return {};
  }
  if (request.arg_count != 1) return {11, "a parameter takes no argument (read) or one (write)"};
  const Problem problem = check<T>(request.args[0]);
  if (!problem.ok()) return problem;
  parameter = as<T>(request.args[0]);
  return {};
}

/// Invoke of a BlockPort operation (entry.callable[0]: 0 read, 1 read_deep, 2 reset_deep).
/// Context: loop.
Problem invoke_port(Entry& entry, const JsonRequest& request, TextWriter& reply);

}  // namespace stepdance::rpc
