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

bool is_analog(Connector c) { return c == Connector::kA1 || c == Connector::kA2 || c == Connector::kA3 || c == Connector::kA4; }
bool is_limit(Connector c) {
  return c == Connector::kLimitA || c == Connector::kLimitB || c == Connector::kLimitC || c == Connector::kLimitD;
}
bool is_encoder(Connector c) { return c == Connector::kEnc1 || c == Connector::kEnc2; }
bool is_qwiic(Connector c) { return c == Connector::kQwiic0 || c == Connector::kQwiic1; }
bool is_digital_or_analog(Connector c) { return c == Connector::kD1 || c == Connector::kD2 || is_analog(c); }

// One row per device kind: adding a kind is adding a row (and its model in the simulation).
constexpr DeviceKind kDeviceKinds[] = {
    {DeviceType::kEncoder, "encoder", "an encoder", "ENC1 or ENC2", is_encoder},
    {DeviceType::kPotentiometer, "potentiometer", "a potentiometer", "A1..A4", is_analog},
    {DeviceType::kButton, "button", "a button", "D1, D2 or A1..A4", is_digital_or_analog},
    {DeviceType::kLimitSwitch, "limit_switch", "a limit switch", "LIMIT_A..LIMIT_D", is_limit},
    {DeviceType::kPendulum, "pendulum", "a pendulum", "ENC1 or ENC2", is_encoder},
    {DeviceType::kFiveBarArm, "five_bar_arm", "a five-bar arm", "ENC1 or ENC2", is_encoder},
    {DeviceType::kOled, "oled", "an OLED display", "QWIIC0 or QWIIC1", is_qwiic},
    {DeviceType::kTwist, "twist", "a Qwiic Twist knob", "QWIIC0 or QWIIC1", is_qwiic},
};
}  // namespace

DeviceKindList device_kinds() { return {kDeviceKinds, sizeof kDeviceKinds / sizeof kDeviceKinds[0]}; }

std::string_view connector_name(Connector connector) {
  for (const auto& [name, value] : kConnectors) {
    if (value == connector) return name;
  }
  return "?";
}

std::string_view module_name(Module module) { return module == Module::kBasic ? "basic" : "driver"; }

const DeviceKind& device_kind(DeviceType type) {
  for (const DeviceKind& kind : device_kinds()) {
    if (kind.type == type) return kind;
  }
  return device_kinds().front();  // unreachable: every DeviceType has a row
}

std::string_view device_type_name(DeviceType type) { return device_kind(type).name; }

std::string_view device_with_article(DeviceType type) { return device_kind(type).with_article; }

std::optional<Connector> parse_connector(std::string_view name) {
  for (const auto& [known, value] : kConnectors) {
    if (known == name) return value;
  }
  return std::nullopt;
}

bool module_has_connector(Module module, Connector connector) { return module == Module::kDriver || !is_limit(connector); }

bool device_fits_connector(DeviceType type, Connector connector) { return device_kind(type).fits(connector); }

std::string_view connectors_for(DeviceType type) { return device_kind(type).connectors; }

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
