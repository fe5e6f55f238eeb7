// [machine]: the board whose sockets drive it and its type, then its kind's own keys, read by the
// kind's row (kinds/machine_registry.hpp).
#include "kinds/machine_registry.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

void read_machine(TableReader& top, ParseContext& context) {
  const toml::table* table = top.table("machine");
  if (table == nullptr) return;
  TableReader reader(*table, "[machine]", context.reporter);
  MachineConfig machine;
  machine.line = reader.line();
  const BoardConfig* board = nullptr;
  if (const auto name = reader.string("board", Need::kRequired)) {
    board = context.scenario.board(*name);
    if (board == nullptr) {
      reader.error("board", "unknown board '" + *name + "'");
    } else if (!board->module->has_drivers) {
      reader.error("board", "board '" + *name + "' is a " + std::string(module_name(*board->module)) +
                                " module, which has no driver sockets");
      board = nullptr;
    } else {
      machine.board = *name;
    }
  }
  MachineSockets sockets(reader, board);
  const std::optional<std::string> type = reader.string("type", Need::kRequired);
  if (!type) return;
  machine.kind = find_machine_kind(*type);
  if (machine.kind == nullptr) {
    // Without a known type, the other keys cannot be judged: report only the type.
    reader.error("type", "'type' must be " + machine_kind_names() + ", got \"" + *type + "\"");
    return;
  }
  MachineReading reading{reader, sockets, context};
  machine.settings = machine.kind->read(reading);
  reader.finish();
  context.scenario.machine = std::move(machine);
}

}  // namespace stepdance::sim::scenario
