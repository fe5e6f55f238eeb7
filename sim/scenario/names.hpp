// Scenario vocabulary: connector names, and what each module has (read from its board table).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "scenario/scenario.hpp"

namespace stepdance::sim::scenario {

/// The module's scenario name: "driver", "basic", …
std::string_view module_name(const BoardDefinition& module);
/// The connector with this silkscreen name, if any.
std::optional<Connector> parse_connector(std::string_view name);
/// Whether a module has the connector: its table has the pin(s) behind it (the Basic Module has no
/// limit headers).
bool module_has_connector(const BoardDefinition& module, Connector connector);
/// Connector groups, for the kinds' rules of where a device may sit.
bool is_encoder_connector(Connector connector);  ///< ENC1, ENC2
bool is_analog_connector(Connector connector);   ///< A1..A4
bool is_digital_connector(Connector connector);  ///< D1, D2
bool is_limit_connector(Connector connector);    ///< LIMIT_A..LIMIT_D
bool is_qwiic_connector(Connector connector);    ///< QWIIC0, QWIIC1
/// Index of a connector within its group (ENC1 → 0, A3 → 2, D2 → 1, LIMIT_C → 2, QWIIC1 → 1).
uint8_t connector_index(Connector connector);

/// Whether a module has output port `port` (Driver: A..D; Basic: A).
bool module_has_output_port(const BoardDefinition& module, char port);
/// Whether a module has input port `port` (Driver: A..D; Basic: A).
bool module_has_input_port(const BoardDefinition& module, char port);
/// "A, B, C and D": the letters of the module's driver sockets, for messages.
std::string socket_letters(const BoardDefinition& module);

/// "board:rest" split at its only ':'; nothing if the form is wrong or a part is empty.
struct SplitRef {
  std::string board;
  std::string rest;
};
std::optional<SplitRef> split_ref(std::string_view text);

}  // namespace stepdance::sim::scenario
