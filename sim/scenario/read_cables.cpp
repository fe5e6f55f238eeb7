// [[cable]]: TRRS cables from output ports to input ports, with delay, stretch and glitches.
#include <map>
#include <utility>

#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Which cable (by line) already uses each port end.
using PortUsers = std::map<std::pair<std::string, char>, int>;

void claim(TableReader& reader, std::string_view key, const PortRef& port, const char* side, PortUsers& users) {
  const auto at = std::make_pair(port.board, port.port);
  if (const auto user = users.find(at); user != users.end()) {
    reader.error(key, std::string(side) + " port " + port.board + ":" + std::string(1, port.port) +
                          " already has a cable (line " + std::to_string(user->second) + ")");
  } else {
    users.emplace(at, reader.line());
  }
}

void read_cable(const toml::table& table, ParseContext& context, PortUsers& outputs, PortUsers& inputs) {
  TableReader reader(table, "[[cable]]", context.reporter);
  CableConfig cable;
  cable.line = reader.line();
  const std::optional<PortRef> from = read_port(reader, "from", true, context);
  const std::optional<PortRef> to = read_port(reader, "to", false, context);
  if (from) {
    cable.from = *from;
    claim(reader, "from", *from, "output", outputs);
  }
  if (to) {
    cable.to = *to;
    claim(reader, "to", *to, "input", inputs);
  }
  CableSettings& settings = cable.settings;
  if (const auto delay = reader.integer("delay_ns", ranges::kCableDelayNs)) settings.delay = *delay;
  if (const auto stretch = reader.integer("stretch_ns", ranges::kCableStretchNs)) settings.stretch = *stretch;
  if (const auto every = reader.integer("glitch_every_us", ranges::kGlitchEveryUs))
    settings.glitch_every = *every * kMicrosecond;
  if (const auto width = reader.integer("glitch_width_ns", ranges::kGlitchWidthNs)) settings.glitch_width = *width;
  reader.finish();
  if (from && to) context.scenario.cables.push_back(std::move(cable));
}

}  // namespace

void read_cables(TableReader& top, ParseContext& context) {
  PortUsers outputs;
  PortUsers inputs;
  for_each_table(top, "cable", [&](const toml::table& table) { read_cable(table, context, outputs, inputs); });
}

}  // namespace stepdance::sim::scenario
