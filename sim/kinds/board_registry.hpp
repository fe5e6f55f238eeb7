// The simulator's board registry: the library's built-in boards, then any registered at run time.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kinds/scoped_kind.hpp"
#include "stepdance/boards/board_definition.hpp"

namespace stepdance::sim {

/// Every board the simulator knows: stepdance::kBoards (boards/board_registry.hpp) in order,
/// then any a test added. Context: host, single thread.
const std::vector<const BoardDefinition*>& boards();
/// The board whose scenario name (`module = "driver"`) is `scenario_name`, or null.
const BoardDefinition* find_board(std::string_view scenario_name);
/// The board whose table name (what a sketch reports: "Driver Module v1.0") is `name`, or null.
const BoardDefinition* find_board_named(std::string_view name);
/// "\"driver\" or \"basic\"", for the message of an unknown module.
std::string board_names();

/// The run-time side of the list: a test adds its own board (the table must outlive it) with a
/// ScopedKind<BoardRegistry>.
struct BoardRegistry {
  using Kind = BoardDefinition;
  static void add(const BoardDefinition& board);
  static void remove(const BoardDefinition& board);
};

}  // namespace stepdance::sim
