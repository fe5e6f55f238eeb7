// Device kind "five_bar_arm": FiveBarArm with its two joint encoders; its hand follows path_mm
// (no page control: the path is its script).
#include "kinds/devices/five_bar_arm.hpp"

#include <cmath>

#include "kinds/device_keys.hpp"
#include "models/five_bar_arm.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

constexpr scenario::NumberRange kSpeedMmPerS{0, 10000, true, "mm/s"};
// The joints' home (−60°, 240°) must lie within the turn each stop allows.
constexpr scenario::NumberRange kRightMinDeg{-420, -60, false, "°"};
constexpr scenario::NumberRange kLeftMaxDeg{240, 600, false, "°"};

nlohmann::json point_json(const PenPoint& point) { return nlohmann::json::array({point.x_mm, point.y_mm}); }

/// The arm's joint encoders as CSV columns; on the live page, its linkage as an "arms" part (none
/// while the links cannot meet).
class ArmDevice : public ModelDevice<FiveBarArm> {
 public:
  using ModelDevice::ModelDevice;
  void add_page_parts(const std::string& name, SimTime, PageParts& parts) const override {
    FiveBarArm::Linkage linkage;
    if (!model().last_linkage(linkage)) return;
    parts.push_back({"arms",
                     {{"device", name},
                      {"right_pivot", point_json(linkage.right_pivot)},
                      {"left_pivot", point_json(linkage.left_pivot)},
                      {"c", point_json(linkage.c)},
                      {"d", point_json(linkage.d)},
                      {"e", point_json(linkage.e)},
                      {"t", point_json(linkage.t)}}});
  }
  void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const override {
    const FiveBarArm* arm = &model();
    probes.push_back(
        {name + "_right_counts", 0, [arm](SimTime time) { return static_cast<double>(arm->right_count_at(time)); }});
    probes.push_back(
        {name + "_left_counts", 0, [arm](SimTime time) { return static_cast<double>(arm->left_count_at(time)); }});
  }
};

/// left_connector (required): ENC1 or ENC2, not used by another device.
void read_left_connector(DeviceReading& reading, FiveBarArmConfig& config) {
  const auto text = reading.reader.string("left_connector", scenario::Need::kRequired);
  if (!text) return;
  const std::optional<scenario::Connector> connector = scenario::parse_connector(*text);
  if (!connector || !scenario::is_encoder_connector(*connector)) {
    reading.reader.error("left_connector", "'left_connector' must be ENC1 or ENC2, got \"" + *text + "\"");
    return;
  }
  if (reading.claim_connector("left_connector", *connector)) config.left_connector = *connector;
}

/// One path point: [x, y] or [x, y, dwell_s], finite, dwell in [0, 86400].
bool read_path_point(const toml::node& item, FiveBarArmConfig& config) {
  const toml::array* point = item.as_array();
  if (point == nullptr || point->size() < 2 || point->size() > 3) return false;
  double values[3] = {0, 0, 0};
  for (size_t i = 0; i < point->size(); ++i) {
    const auto value = (*point)[i].value<double>();
    if (!value || !std::isfinite(*value)) return false;
    values[i] = *value;
  }
  if (values[2] < 0 || values[2] > 86400) return false;
  config.path_mm.emplace_back(values[0], values[1]);
  config.dwell_s.push_back(values[2]);
  return true;
}

/// path_mm: at least one point.
void read_path(scenario::TableReader& reader, FiveBarArmConfig& config) {
  const toml::array* path = reader.array("path_mm", scenario::Need::kRequired);
  if (path == nullptr) return;
  for (const toml::node& item : *path) {
    if (!read_path_point(item, config)) {
      reader.error("path_mm",
                   "'path_mm' must be a list of [x, y] or [x, y, dwell_s] points (mm, s; dwell in 0..86400)");
      config.path_mm.clear();
      config.dwell_s.clear();
      return;
    }
  }
  if (config.path_mm.empty()) reader.error("path_mm", "'path_mm' needs at least one point");
}

std::any read(DeviceReading& reading) {
  FiveBarArmConfig config;
  scenario::TableReader& reader = reading.reader;
  read_left_connector(reading, config);
  read_pulses_per_revolution(reader, config.pulses_per_revolution);
  read_path(reader, config);
  read_bounded(reader, "speed_mm_per_s", kSpeedMmPerS, config.speed_mm_per_s);
  read_bounded(reader, "start_s", run_time_range(reading.context), config.start_s);
  read_bounded(reader, "right_min_deg", kRightMinDeg, config.right_min_deg);
  read_bounded(reader, "left_max_deg", kLeftMaxDeg, config.left_max_deg);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<FiveBarArmConfig>();
  FiveBarArmSettings settings;
  settings.pulses_per_revolution = config.pulses_per_revolution;
  for (const auto& [x, y] : config.path_mm) settings.path_mm.push_back(PenPoint{x, y});
  settings.dwell_s = config.dwell_s;
  settings.speed_mm_per_s = config.speed_mm_per_s;
  settings.start = from_seconds(config.start_s);
  constexpr double kDegreeRad = 3.14159265358979323846 / 180;
  settings.right_min_rad = config.right_min_deg * kDegreeRad;
  settings.left_max_rad = config.left_max_deg * kDegreeRad;
  auto built = std::make_unique<ArmDevice>(std::make_unique<FiveBarArm>(settings));
  const FiveBarArm* model = &built->model();
  plug.connect_encoder(device.connector, [model](SimTime time) { return model->right_count_at(time); });
  plug.connect_encoder(config.left_connector, [model](SimTime time) { return model->left_count_at(time); });
  return built;
}

}  // namespace

const DeviceKind& five_bar_arm_kind() {
  using Type = DeviceKey::Type;
  static const DeviceKind kind{
      "five_bar_arm",
      "a five-bar arm",
      "ENC1 or ENC2",
      scenario::is_encoder_connector,
      {integer_key("pulses_per_revolution", kPulsesPerRevolution), DeviceKey{"left_connector", Type::kString},
       DeviceKey{"path_mm", Type::kList}, number_key("speed_mm_per_s", kSpeedMmPerS),
       number_key("start_s", scenario::ranges::kTimeS), number_key("right_min_deg", kRightMinDeg),
       number_key("left_max_deg", kLeftMaxDeg)},
      read,
      build,
      0,
      PageControl{},
      nullptr,
      {"arms"},
  };
  return kind;
}

}  // namespace stepdance::sim
