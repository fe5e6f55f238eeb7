// Device kind "encoder": QuadratureEncoder on ENC1/ENC2; `turn` actions, a knob on the page.
#include "kinds/devices/encoder.hpp"

#include "kinds/device_keys.hpp"
#include "models/quadrature_encoder.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

class EncoderDevice : public ModelDevice<QuadratureEncoder> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override { model().turn(action.time, action.counts, action.over); }
  /// The page's knob turns the encoder one revolution per turn of the hand.
  void describe_page_control(nlohmann::json& control) const override {
    control["counts_per_turn"] = model().counts_per_revolution();
  }
  void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const override {
    const QuadratureEncoder* encoder = &model();
    probes.push_back(
        {name + "_counts", 0, [encoder](SimTime time) { return static_cast<double>(encoder->count_at(time)); }});
  }
};

std::any read(DeviceReading& reading) {
  EncoderConfig config;
  read_pulses_per_revolution(reading.reader, config.pulses_per_revolution);
  if (const auto start = reading.reader.integer("start_count", scenario::ranges::kEncoderCounts)) {
    config.start_count = *start;
  }
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<EncoderConfig>();
  auto built = std::make_unique<EncoderDevice>(
      std::make_unique<QuadratureEncoder>(config.pulses_per_revolution, config.start_count));
  const QuadratureEncoder* model = &built->model();
  plug.connect_encoder(device.connector, [model](SimTime time) { return model->count_at(time); });
  return built;
}

}  // namespace

const DeviceKind& encoder_kind() {
  static const DeviceKind kind{
      "encoder",
      "an encoder",
      "ENC1 or ENC2",
      scenario::is_encoder_connector,
      {integer_key("pulses_per_revolution", kPulsesPerRevolution),
       integer_key("start_count", scenario::ranges::kEncoderCounts)},
      read,
      build,
      actions({scenario::ActionType::kTurn}),
      PageControl{PageControl::Type::kKnob, 0, 0, 1, "counts"},
  };
  return kind;
}

}  // namespace stepdance::sim
