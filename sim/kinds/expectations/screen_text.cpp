// Expectation kind "screen": screen = "<oled device>", shows = "text", row = 0..3 (optional) —
// the OLED shows a line of text at the end of the run, read back in Stepdance's font.
#include "kinds/expectations/screen_text.hpp"

#include "kinds/devices/oled.hpp"
#include "kinds/expectations/expectation_parts.hpp"
#include "models/ssd1306_display.hpp"

namespace stepdance::sim {
namespace {

/// shows (required, at most a row of 21 characters) and row (0..3).
bool read_text_and_row(scenario::TableReader& reader, ScreenTextCheck& check) {
  bool ok = true;
  if (const auto text = reader.string("shows", scenario::Need::kRequired)) {
    if (text->size() > 21) {
      reader.error("shows", "'shows' can be at most 21 characters (a row of the 128x32 screen)");
      ok = false;
    }
    check.shows = *text;
  } else {
    ok = false;
  }
  if (const auto row = reader.integer("row")) {
    if (*row < 0 || *row > 3) {
      reader.error("row", "'row' must be 0..3, got " + std::to_string(*row));
      ok = false;
    }
    check.row = *row;
  }
  return ok;
}

bool read(ExpectationReading& reading) {
  ScreenTextCheck check;
  const auto name = reading.reader.string("screen");
  bool ok = name.has_value();
  const scenario::DeviceConfig* device = name ? reading.context.scenario.device(*name) : nullptr;
  if (name && (device == nullptr || device->settings_as<OledConfig>() == nullptr)) {
    reading.reader.error("screen", "'screen' must name an oled device, got '" + *name + "'");
    ok = false;
  }
  if (ok) check.screen = *name;
  ok = read_text_and_row(reading.reader, check) && ok;
  reading.settings = check;
  return ok;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<ScreenTextCheck>(expectation);
  const Ssd1306Display* oled = model_of<Ssd1306Display>(run.device(check.screen));
  if (oled == nullptr) return {false, "screen: no such oled"};
  const std::vector<std::string> rows = oled->text_rows();
  std::string shown;
  bool found = false;
  for (size_t row = 0; row < rows.size(); ++row) {
    shown += (row == 0 ? "\"" : " | \"") + rows[row] + "\"";
    if (check.row < 0 || static_cast<size_t>(check.row) == row) found = found || rows[row] == check.shows;
  }
  const std::string where = check.row < 0 ? "a row" : "row " + std::to_string(check.row);
  return {found, "screen '" + check.screen + "' " + where + " shows \"" + check.shows + "\": rows " + shown};
}

}  // namespace

const ExpectationKind& screen_text_expectation() {
  static const ExpectationKind kind{"screen", {"shows", "row"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
