// The RPC's registry: every enrolled name with what to call, in a fixed table.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/rpc/json_request.hpp"

namespace stepdance {

class BlockPort;

namespace rpc {

/// Why a call was refused: the reply's error code (docs/rpc.md) and message; code 0: no problem.
struct Problem {
  int code = 0;
  const char* message = "";
  bool ok() const { return code == 0; }
};

struct Entry;
/// Calls an entry with a request's arguments, appending `,"return":<value>` to `reply` when
/// there is one. Context: loop.
using Invoke = Problem (*)(Entry& entry, const JsonRequest& request, TextWriter& reply);

/// One enrolled name: a function, a method of an object, a variable or a port operation.
struct Entry {
  static constexpr size_t kMaxNameBytes = 63;
  char name[kMaxNameBytes + 1] = {};
  bool parameter = false;
  void* object = nullptr;  ///< the instance, variable or port; nullptr for a free function
  alignas(void*) unsigned char callable[2 * sizeof(void*)] = {};  ///< function or member pointer
  Invoke invoke = nullptr;
  const char* signature = "";  ///< static: "nnn:i" for a function, "n" for a parameter
  bool watchable = false;      ///< a parameter or a reader: may be subscribed to
};

/// The enrolled names, in enrollment order (the order __index__ lists them). A name enrolled
/// again replaces the first. No heap: kMaxEntries entries, names up to kMaxNameBytes.
class Registry {
 public:
  static constexpr size_t kMaxEntries = 96;
  static constexpr size_t kMaxNameBytes = Entry::kMaxNameBytes;

  /// A cleared entry named "<prefix>.<suffix>" ("<prefix>" when the suffix is empty), or
  /// nullptr when the table is full, the name too long or the prefix empty: counted in
  /// failures() and reported as a warning on the fault path. Context: loop (setup).
  Entry* add(const char* prefix, const char* suffix, bool parameter);
  /// The three entries of a BlockPort: "<name>.read", "<name>.read_deep", "<name>.reset_deep".
  /// Context: loop (setup).
  void add_port(const char* name, BlockPort& port);
  /// The index of the entry called `name`, or −1. Context: loop.
  int find(const char* name) const;

  Entry& at(size_t index) { return entries_[index]; }
  const Entry& at(size_t index) const { return entries_[index]; }
  /// Entries enrolled. Context: any.
  size_t count() const { return count_; }
  /// Names refused (table full or name too long). Context: any.
  uint32_t failures() const { return failures_; }

 private:
  Entry entries_[kMaxEntries];
  size_t count_ = 0;
  uint32_t failures_ = 0;
};

}  // namespace rpc
}  // namespace stepdance
