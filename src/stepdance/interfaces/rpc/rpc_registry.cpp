// The RPC's registry: adding names (refused and reported when they do not fit), finding them.
#include "stepdance/interfaces/rpc/rpc_registry.hpp"

#include <string.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/rpc/rpc_arguments.hpp"

namespace stepdance::rpc {

// Loop context (setup). A name that does not fit is refused and reported on the fault path, never
// truncated: a truncated name could collide with another. Enrolling a name again replaces the entry,
// so a sketch can re-enroll after changing a block.
Entry* Registry::add(const char* prefix, const char* suffix, bool parameter) {
  const size_t prefix_length = strlen(prefix);
  const size_t suffix_length = strlen(suffix);
  const size_t length = prefix_length + (suffix_length > 0 ? 1 + suffix_length : 0);
  if (count_ == kMaxEntries || length > kMaxNameBytes || prefix_length == 0) {
    ++failures_;
    report_fault(FaultLevel::kWarning, FaultReason::kRegistryFull, "rpc",
                 "enroll refused: registry full or name too long");
    return nullptr;
  }
  char name[kMaxNameBytes + 1];
  memcpy(name, prefix, prefix_length);
  if (suffix_length > 0) {
    name[prefix_length] = '.';
    memcpy(name + prefix_length + 1, suffix, suffix_length);
  }
  name[length] = '\0';
  const int existing = find(name);  // enrolled again: replaced
  Entry* entry = existing >= 0 ? &entries_[existing] : &entries_[count_++];
  *entry = Entry{};
  memcpy(entry->name, name, length + 1);
  entry->parameter = parameter;
  entry->watchable = parameter;
  return entry;
}

// A port is three entries: "<port>.read", ".read_deep" (both watchable) and ".reset_deep(position)".
void Registry::add_port(const char* name, BlockPort& port) {
  static const char* const kOperations[] = {"read", "read_deep", "reset_deep"};
  for (uint8_t operation = 0; operation < 3; ++operation) {
    Entry* entry = add(name, kOperations[operation], false);
    if (entry == nullptr) return;
    entry->object = &port;
    entry->callable[0] = operation;
    entry->invoke = &invoke_port;
    entry->signature = operation == 2 ? "n:v" : ":n";
    entry->watchable = operation != 2;
  }
}

int Registry::find(const char* name) const {
  for (size_t i = 0; i < count_; ++i) {
    if (strcmp(entries_[i].name, name) == 0) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace stepdance::rpc
