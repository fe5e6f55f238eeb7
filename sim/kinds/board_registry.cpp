// The simulator's board registry: stepdance::kBoards plus boards registered at run time.
#include "kinds/board_registry.hpp"

#include <algorithm>

#include "stepdance/boards/board_registry.hpp"

namespace stepdance::sim {
namespace {

std::vector<const BoardDefinition*>& registry() {
  static std::vector<const BoardDefinition*> all(std::begin(kBoards), std::end(kBoards));
  return all;
}

}  // namespace

const std::vector<const BoardDefinition*>& boards() { return registry(); }

const BoardDefinition* find_board(std::string_view scenario_name) {
  for (const BoardDefinition* board : registry()) {
    if (board->scenario_name == scenario_name) return board;
  }
  return nullptr;
}

const BoardDefinition* find_board_named(std::string_view name) {
  for (const BoardDefinition* board : registry()) {
    if (board->name == name) return board;
  }
  return nullptr;
}

std::string board_names() {
  const std::vector<const BoardDefinition*>& all = registry();
  std::string text;
  for (size_t i = 0; i < all.size(); ++i) {
    if (i > 0) text += i + 1 == all.size() ? " or " : ", ";
    text += "\"" + std::string(all[i]->scenario_name) + "\"";
  }
  return text;
}

void BoardRegistry::add(const BoardDefinition& board) { registry().push_back(&board); }

void BoardRegistry::remove(const BoardDefinition& board) {
  std::vector<const BoardDefinition*>& all = registry();
  all.erase(std::remove(all.begin(), all.end(), &board), all.end());
}

}  // namespace stepdance::sim
