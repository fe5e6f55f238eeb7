// The board registry: every board the library knows, one registration line each.
#pragma once

#include <stddef.h>

#include "stepdance/boards/basic_module_v1.hpp"
#include "stepdance/boards/board_checks.hpp"
#include "stepdance/boards/board_definition.hpp"
#include "stepdance/boards/driver_module_v1.hpp"

namespace stepdance {

/// The built-in boards. A new board is its table (boards/<board>.hpp), its #include above and
/// its line here; docs/architecture.md, "Where things go", lists the rest.
inline constexpr const BoardDefinition* kBoards[] = {
    &kDriverModuleV1,
    &kBasicModuleV1,
};

/// How many built-in boards there are.
constexpr size_t kBoardCount = sizeof(kBoards) / sizeof(kBoards[0]);

/// Whether every built-in board's table is valid and no two share a name, scenario name or macro.
constexpr bool builtin_boards_are_valid() {
  for (size_t i = 0; i < kBoardCount; ++i) {
    if (!board_is_valid(*kBoards[i])) return false;
    for (size_t j = i + 1; j < kBoardCount; ++j) {
      if (same_text(kBoards[i]->name, kBoards[j]->name) ||
          same_text(kBoards[i]->scenario_name, kBoards[j]->scenario_name) ||
          same_text(kBoards[i]->sketch_macro, kBoards[j]->sketch_macro)) {
        return false;
      }
    }
  }
  return true;
}
static_assert(builtin_boards_are_valid(), "a board table has a pin its Teensy lacks, or two boards share a name");

}  // namespace stepdance
