// A protocol's commands by name, fixed at compile time.
#pragma once

#include <stddef.h>

namespace stepdance::link {

/// One named command and what handles it (a function or member-function pointer, or a small
/// struct of them when a command has several parts).
template <class Handler>
struct Command {
  const char* name = nullptr;
  Handler handler{};
};

/// True when two NUL-terminated names are the same bytes. Context: any.
constexpr bool same_name(const char* a, const char* b) {
  for (; *a == *b; ++a, ++b) {
    if (*a == '\0') return true;
  }
  return false;
}

/// The commands of one protocol: each name once (checked at compile time with
/// `static_assert(table.names_unique())`), looked up by exact name; a protocol whose names ignore
/// case (EBB) folds the name before the lookup. Context: any.
template <class Handler, size_t N>
struct CommandTable {
  Command<Handler> commands[N];

  /// The command named `name`, or null when there is none.
  constexpr const Command<Handler>* find(const char* name) const {
    for (const Command<Handler>& command : commands) {
      if (same_name(command.name, name)) return &command;
    }
    return nullptr;
  }
  /// True when no two commands share a name.
  constexpr bool names_unique() const {
    for (size_t i = 0; i < N; ++i) {
      for (size_t j = i + 1; j < N; ++j) {
        if (same_name(commands[i].name, commands[j].name)) return false;
      }
    }
    return true;
  }
  /// Number of commands.
  static constexpr size_t size() { return N; }
};

/// Builds a table from a braced list: `make_command_table<H>({{"SM", &X::sm}, …})`.
template <class Handler, size_t N>
constexpr CommandTable<Handler, N> make_command_table(const Command<Handler> (&commands)[N]) {
  CommandTable<Handler, N> table{};
  for (size_t i = 0; i < N; ++i) table.commands[i] = commands[i];
  return table;
}

}  // namespace stepdance::link
