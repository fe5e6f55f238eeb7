// The active board selection.
#include "stepdance/boards/board.hpp"

namespace stepdance {
namespace {
const BoardDefinition* selected = &kDriverModuleV1;
}  // namespace

const BoardDefinition& active_board() { return *selected; }
void select_board(const BoardDefinition& board) { selected = &board; }

}  // namespace stepdance
