// Board definitions: which pins and ports a Stepdance module has, and which board is running.
#pragma once

#include "stepdance/boards/board_definition.hpp"
#include "stepdance/boards/board_registry.hpp"

namespace stepdance {

/// The board the core is running on. Defaults to the Driver Module. Context: any.
const BoardDefinition& active_board();
/// Chooses the board; called by the umbrella header from the sketch's module macro, before
/// setup(). Context: loop, before any begin().
void select_board(const BoardDefinition& board);

}  // namespace stepdance
