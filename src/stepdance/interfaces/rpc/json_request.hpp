// One RPC request line as JSON: {"name": "...", "args": [...], "id": ...}, parsed without a heap.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance::rpc {

/// A JSON argument: null, true/false, a number (as double) or a string (in the caller's pool).
struct JsonValue {
  enum class Type : uint8_t { kNull, kBool, kNumber, kString } type = Type::kNull;
  bool boolean = false;
  double number = 0.0;
  const char* text = "";  ///< kString: NUL-terminated, escapes resolved
};

/// The request's parts. `id` keeps the id's JSON text as sent (a number or a quoted string).
struct JsonRequest {
  static constexpr int kMaxArgs = 8;  // tbi.add_move takes eight
  static constexpr size_t kMaxNameBytes = 63;
  static constexpr size_t kMaxIdBytes = 40;
  char name[kMaxNameBytes + 1] = {};
  JsonValue args[kMaxArgs];
  int arg_count = 0;
  bool has_args = false;
  char id[kMaxIdBytes + 1] = {};  ///< "" when absent
};

/// Why a line is not a request (the reply's error code is the enum's value).
enum class JsonError : uint8_t {
  kNone = 0,
  kSyntax = 1,       ///< not well-formed JSON, or not an object
  kMissingName = 2,  ///< no "name" string
  kTooManyArgs = 3,  ///< more than kMaxArgs arguments, or an argument that is an array/object
  kTooLong = 4,      ///< a name, id or the strings' total over their limit
};

/// Parses `line` (length bytes, no line ending). Strings go into `pool` (pool_size bytes).
/// Unknown keys are ignored. Context: loop (pure).
JsonError parse_request(const char* line, size_t length, JsonRequest& out, char* pool, size_t pool_size);

/// A short message for an error. Never null.
const char* to_string(JsonError error);

}  // namespace stepdance::rpc
