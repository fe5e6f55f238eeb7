// Scenario vocabulary tables.
#include "scenario/names.hpp"

#include <array>
#include <utility>

namespace stepdance::sim::scenario {

namespace {
constexpr std::array<std::pair<std::string_view, Connector>, 14> kConnectors{{
    {"ENC1", Connector::kEnc1},
    {"ENC2", Connector::kEnc2},
    {"A1", Connector::kA1},
    {"A2", Connector::kA2},
    {"A3", Connector::kA3},
    {"A4", Connector::kA4},
    {"D1", Connector::kD1},
    {"D2", Connector::kD2},
    {"LIMIT_A", Connector::kLimitA},
    {"LIMIT_B", Connector::kLimitB},
    {"LIMIT_C", Connector::kLimitC},
    {"LIMIT_D", Connector::kLimitD},
    {"QWIIC0", Connector::kQwiic0},
    {"QWIIC1", Connector::kQwiic1},
}};

}  // namespace

std::string_view connector_name(Connector connector) {
  for (const auto& [name, value] : kConnectors) {
    if (value == connector) return name;
  }
  return "?";
}

std::string_view module_name(const BoardDefinition& module) { return module.scenario_name; }

std::optional<Connector> parse_connector(std::string_view name) {
  for (const auto& [known, value] : kConnectors) {
    if (known == name) return value;
  }
  return std::nullopt;
}

bool module_has_connector(const BoardDefinition& module, Connector connector) {
  const uint8_t index = connector_index(connector);
  if (is_encoder_connector(connector)) return module.encoder_pins[index][0] != kNoPin;
  if (is_analog_connector(connector)) return module.io_a[index] != kNoPin;
  if (is_digital_connector(connector)) return module.io_d[index] != kNoPin;
  if (is_qwiic_connector(connector)) return module.qwiic[index][0] != kNoPin;
  return index < module.output_port_count && module.output_ports[index].limit != kNoPin;
}

bool is_encoder_connector(Connector c) { return c == Connector::kEnc1 || c == Connector::kEnc2; }
bool is_analog_connector(Connector c) {
  return c == Connector::kA1 || c == Connector::kA2 || c == Connector::kA3 || c == Connector::kA4;
}
bool is_digital_connector(Connector c) { return c == Connector::kD1 || c == Connector::kD2; }
bool is_limit_connector(Connector c) {
  return c == Connector::kLimitA || c == Connector::kLimitB || c == Connector::kLimitC || c == Connector::kLimitD;
}
bool is_qwiic_connector(Connector c) { return c == Connector::kQwiic0 || c == Connector::kQwiic1; }

uint8_t connector_index(Connector connector) {
  switch (connector) {
    case Connector::kEnc1:
    case Connector::kA1:
    case Connector::kD1:
    case Connector::kLimitA:
    case Connector::kQwiic0: return 0;
    case Connector::kEnc2:
    case Connector::kA2:
    case Connector::kD2:
    case Connector::kLimitB:
    case Connector::kQwiic1: return 1;
    case Connector::kA3:
    case Connector::kLimitC: return 2;
    case Connector::kA4:
    case Connector::kLimitD: return 3;
  }
  return 0;
}

bool module_has_output_port(const BoardDefinition& module, char port) {
  return port >= 'A' && port < 'A' + module.output_port_count;
}

bool module_has_input_port(const BoardDefinition& module, char port) {
  return port >= 'A' && port < 'A' + module.input_port_count;
}

std::string socket_letters(const BoardDefinition& module) {
  std::string text;
  for (uint8_t port = 0; port < module.output_port_count; ++port) {
    if (port > 0) text += port + 1 == module.output_port_count ? " and " : ", ";
    text += static_cast<char>('A' + port);
  }
  return text;
}

std::optional<SplitRef> split_ref(std::string_view text) {
  const size_t colon = text.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon + 1 == text.size()) return std::nullopt;
  if (text.find(':', colon + 1) != std::string_view::npos) return std::nullopt;
  return SplitRef{std::string(text.substr(0, colon)), std::string(text.substr(colon + 1))};
}

}  // namespace stepdance::sim::scenario
