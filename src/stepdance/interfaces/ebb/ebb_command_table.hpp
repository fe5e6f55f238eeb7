// The EBB's command table: each command's name, handler and what the dispatcher checks first.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance::ebb {

/// What the dispatcher checks before a handler runs.
enum CommandFlags : uint8_t {
  kCommandPlain = 0,
  kCommandMovesMotors = 1,   ///< refused with !9 while an alarm is raised (the fault path)
  kCommandNoParameters = 2,  ///< any parameter is an error (the parser's reply), handler not called
};

/// One row of a command table: a one- or two-letter upper-case name, its handler, CommandFlags.
template <class Handler>
struct CommandEntry {
  const char* name;
  Handler handler;
  uint8_t flags;
};

/// True when two NUL-terminated names are equal. Context: any (pure, constexpr).
constexpr bool same_command_name(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

/// The row named `name` (upper case), or null. Context: any (pure, constexpr).
template <class Handler, size_t N>
constexpr const CommandEntry<Handler>* find_command(const CommandEntry<Handler> (&table)[N], const char* name) {
  for (size_t i = 0; i < N; ++i) {
    if (same_command_name(table[i].name, name)) return &table[i];
  }
  return nullptr;
}

/// True when no two rows share a name (checked at compile time by the tables). Context: any.
template <class Handler, size_t N>
constexpr bool command_names_unique(const CommandEntry<Handler> (&table)[N]) {
  for (size_t i = 0; i < N; ++i) {
    if (find_command(table, table[i].name) != &table[i]) return false;
  }
  return true;
}

}  // namespace stepdance::ebb
