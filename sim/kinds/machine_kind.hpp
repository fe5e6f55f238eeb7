// One row per machine kind: its name, how its [machine] keys are read, which axes a limit switch
// can watch, its page, and how its model is built on the sockets' drivers.
#pragma once

#include <any>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "kinds/page_part.hpp"
#include "models/machine.hpp"
#include "models/servo_board.hpp"
#include "models/stepper_driver.hpp"
#include "scenario/parse_context.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Reads the sockets a machine uses: each must hold the right device, and none may serve two
/// roles (kinds/machine_sockets.cpp).
class MachineSockets {
 public:
  MachineSockets(scenario::TableReader& reader, const scenario::BoardConfig* board) : reader_(reader), board_(board) {}
  /// Reads `key` as a socket letter (default `fallback`, if any) that must hold `device`.
  std::optional<char> take(std::string_view key, scenario::SocketDevice device, std::optional<char> fallback);

 private:
  scenario::TableReader& reader_;
  const scenario::BoardConfig* board_;
  std::map<char, std::string> users_;
};

/// What a machine kind's reader works on: the [machine] table, its sockets and the scenario so far.
struct MachineReading {
  scenario::TableReader& reader;
  MachineSockets& sockets;
  const scenario::ParseContext& context;
};

/// The driver models in the machine board's sockets, by port letter (null where there is none).
struct SocketModels {
  std::function<StepperDriver*(char)> stepper;
  std::function<ServoBoard*(char)> servo;
};

/// A machine kind. Register it with one line in kinds/builtin_machine_kinds.cpp (or, in a test,
/// with a ScopedKind<MachineRegistry>: kinds/machine_registry.hpp); docs/architecture.md has the
/// map.
struct MachineKind {
  std::string_view name;  ///< the `type` value in the file, e.g. "corexy_plotter"
  /// The axes a limit switch may watch, e.g. "xy".
  std::string_view limit_axes;
  /// Reads the kind's keys and returns its settings (its config struct, e.g. CorexyConfig).
  std::any (*read)(MachineReading& reading);
  /// Builds the model on the sockets' drivers; null if a motor socket holds no stepper.
  std::unique_ptr<Machine> (*build)(const scenario::MachineConfig& machine, const SocketModels& sockets,
                                    const PenTraceSettings& trace);
  /// The page the drawing goes on, if the machine has a fixed one (its travel area, mm); without
  /// one the page is the drawing's bounding box, known only at the end.
  std::optional<TravelArea> (*page)(const scenario::MachineConfig& machine) = nullptr;
  /// The live view's page: appends the machine's own state parts at `now` (ns) for an `update`,
  /// each an object under its field (kinds/page_part.hpp; a turntable's "table"), beside the pen
  /// and strokes every machine has. `machine` is the model `build` made. Null for a kind with
  /// none. Context: the simulation's thread, between run_until() calls.
  void (*add_page_parts)(const Machine& machine, SimTime now, PageParts& parts) = nullptr;
  /// The fields add_page_parts gives, e.g. "table": declared in `hello` as the machine's "parts".
  std::vector<std::string_view> page_parts = {};
};

}  // namespace stepdance::sim
