// Scenario vocabulary tables.
#include "scenario/names.hpp"

#include <array>
#include <utility>

namespace stepdance::sim::scenario {

namespace {
constexpr std::array<std::pair<std::string_view, Connector>, 12> kConnectors{{
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
}};

bool is_analog(Connector c) { return c == Connector::kA1 || c == Connector::kA2 || c == Connector::kA3 || c == Connector::kA4; }
bool is_limit(Connector c) {
  return c == Connector::kLimitA || c == Connector::kLimitB || c == Connector::kLimitC || c == Connector::kLimitD;
}
}  // namespace

std::string_view connector_name(Connector connector) {
  for (const auto& [name, value] : kConnectors) {
    if (value == connector) return name;
  }
  return "?";
}

std::string_view module_name(Module module) { return module == Module::kBasic ? "basic" : "driver"; }

std::string_view device_type_name(DeviceType type) {
  switch (type) {
    case DeviceType::kEncoder:
      return "encoder";
    case DeviceType::kPotentiometer:
      return "potentiometer";
    case DeviceType::kButton:
      return "button";
    case DeviceType::kLimitSwitch:
      return "limit_switch";
  }
  return "?";
}

std::string_view device_with_article(DeviceType type) {
  switch (type) {
    case DeviceType::kEncoder:
      return "an encoder";
    case DeviceType::kPotentiometer:
      return "a potentiometer";
    case DeviceType::kButton:
      return "a button";
    case DeviceType::kLimitSwitch:
      return "a limit switch";
  }
  return "?";
}

std::optional<Connector> parse_connector(std::string_view name) {
  for (const auto& [known, value] : kConnectors) {
    if (known == name) return value;
  }
  return std::nullopt;
}

bool module_has_connector(Module module, Connector connector) { return module == Module::kDriver || !is_limit(connector); }

bool device_fits_connector(DeviceType type, Connector connector) {
  switch (type) {
    case DeviceType::kEncoder:
      return connector == Connector::kEnc1 || connector == Connector::kEnc2;
    case DeviceType::kPotentiometer:
      return is_analog(connector);
    case DeviceType::kButton:
      return connector == Connector::kD1 || connector == Connector::kD2 || is_analog(connector);
    case DeviceType::kLimitSwitch:
      return is_limit(connector);
  }
  return false;
}

std::string_view connectors_for(DeviceType type) {
  switch (type) {
    case DeviceType::kEncoder:
      return "ENC1 or ENC2";
    case DeviceType::kPotentiometer:
      return "A1..A4";
    case DeviceType::kButton:
      return "D1, D2 or A1..A4";
    case DeviceType::kLimitSwitch:
      return "LIMIT_A..LIMIT_D";
  }
  return "?";
}

bool module_has_port(Module module, char port) {
  return module == Module::kBasic ? port == 'A' : (port >= 'A' && port <= 'D');
}

std::optional<SplitRef> split_ref(std::string_view text) {
  const size_t colon = text.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon + 1 == text.size()) return std::nullopt;
  if (text.find(':', colon + 1) != std::string_view::npos) return std::nullopt;
  return SplitRef{std::string(text.substr(0, colon)), std::string(text.substr(colon + 1))};
}

}  // namespace stepdance::sim::scenario
