// Device kind "oled": Ssd1306Display on a QWIIC bus; writes its screen as pictures, shown as a
// screen on the page.
#include "kinds/devices/oled.hpp"

#include <cmath>
#include <cstdio>

#include "kinds/device_keys.hpp"
#include "models/ssd1306_display.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

/// An OLED picture's file name: "<name>-<t>s.png" at a snapshot time (ms precision).
std::string snapshot_name(const std::string& name, SimTime time) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "-%.3fs", to_seconds(time));
  return name + stamp + ".png";
}

/// A row of an OLED picture as hex digits, 4 pixels a digit, leftmost pixel the high bit (the
/// page's "screens" part, docs/simulator.md).
std::vector<std::string> screen_rows(const OledImage& image) {
  static const char kHex[] = "0123456789abcdef";
  std::vector<std::string> rows;
  for (int y = 0; y < OledImage::kHeight; ++y) {
    std::string row;
    for (int x = 0; x < OledImage::kWidth; x += 4) {
      int nibble = 0;
      for (int bit = 0; bit < 4; ++bit) nibble = nibble << 1 | (image.at(x + bit, y) ? 1 : 0);
      row += kHex[nibble];
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The screen as pictures, 4 px per pixel: "<name>.png" at the end and "<name>-<t>s.png" at each
/// snapshot time; on the live page, a "screens" part.
class OledDevice : public ModelDevice<Ssd1306Display> {
 public:
  using ModelDevice::ModelDevice;
  void add_page_parts(const std::string& name, SimTime, PageParts& parts) const override {
    parts.push_back(
        {"screens", {{"device", name}, {"on", model().display_on()}, {"rows", screen_rows(model().image())}}});
  }
  void write_outputs(const std::string& name, PictureSink& sink) override {
    model().finish();
    for (const auto& [time, picture] : model().snapshots()) write(sink, snapshot_name(name, time), picture);
    write(sink, name + ".png", model().image());
  }

 private:
  static void write(PictureSink& sink, const std::string& file_name, const OledImage& picture) {
    sink.write_picture(file_name, std::vector<bool>(picture.lit.begin(), picture.lit.end()), OledImage::kWidth,
                       OledImage::kHeight, 4);
  }
};

/// snapshots_s: times (s, within the run) at which the screen is saved as a picture.
void read_snapshots(DeviceReading& reading, OledConfig& config) {
  const toml::array* times = reading.reader.array("snapshots_s");
  if (times == nullptr) return;
  const scenario::ParseContext& context = reading.context;
  const double last_s = context.duration_valid ? to_seconds(context.scenario.duration) : 86400;
  for (const toml::node& item : *times) {
    const auto time = item.value<double>();
    if (!time || !std::isfinite(*time) || *time < 0 || *time > last_s) {
      reading.reader.error("snapshots_s",
                           "'snapshots_s' must be a list of times in [0, " + scenario::format_number(last_s) + "] s");
      config.snapshots_s.clear();
      return;
    }
    config.snapshots_s.push_back(*time);
  }
}

std::any read(DeviceReading& reading) {
  OledConfig config;
  read_i2c_address(reading, 0x3C);
  read_snapshots(reading, config);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  auto built = std::make_unique<OledDevice>(std::make_unique<Ssd1306Display>());
  std::vector<SimTime> times;
  for (double seconds : device.settings_as<OledConfig>()->snapshots_s) times.push_back(from_seconds(seconds));
  built->model().set_snapshot_times(std::move(times));
  plug.attach_i2c(device.connector, static_cast<uint8_t>(device.i2c_address), &built->model());
  return built;
}

/// "<name>-<t>s.png" at each snapshot time, then "<name>.png" for the end of the run.
std::vector<std::string> output_names(const scenario::DeviceConfig& device) {
  std::vector<std::string> names;
  for (double seconds : device.settings_as<OledConfig>()->snapshots_s) {
    names.push_back(snapshot_name(device.name, from_seconds(seconds)));
  }
  names.push_back(device.name + ".png");
  return names;
}

}  // namespace

const DeviceKind& oled_kind() {
  static const DeviceKind kind{
      "oled",
      "an OLED display",
      "QWIIC0 or QWIIC1",
      scenario::is_qwiic_connector,
      {DeviceKey{"address", DeviceKey::Type::kInteger, 0x08, 0x77, ""},
       DeviceKey{"snapshots_s", DeviceKey::Type::kList}},
      read,
      build,
      0,
      PageControl{PageControl::Type::kScreen, 0, 0, 1, "px"},
      output_names,
      {"screens"},
  };
  return kind;
}

}  // namespace stepdance::sim
