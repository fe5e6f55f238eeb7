// A test-only device kind, "test_crank": a hand crank on an encoder connector turning at a steady
// rate until it stops. Its model, reader, factory, page control and page state (a "cranks" part:
// the count turned so far) live here and nowhere else: registering it (ScopedKind<DeviceRegistry>)
// is all the simulator and its live view need.
#pragma once

#include <algorithm>
#include <memory>

#include "kinds/device_keys.hpp"
#include "kinds/device_registry.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim::test {

/// The crank's settings: counts per second (signed) and when it stops turning.
struct TestCrankConfig {
  int64_t counts_per_s = 0;
  double stop_s = 0;
};

inline constexpr scenario::IntegerRange kCrankRate{-100000, 100000, "counts/s"};

/// The model: the count at a time is the rate times the time turned so far.
class TestCrank {
 public:
  explicit TestCrank(const TestCrankConfig& config) : config_(config) {}
  int64_t count_at(SimTime time) const {
    const SimTime turned = std::min(time, from_seconds(config_.stop_s));
    return config_.counts_per_s * turned / kSecond;
  }

 private:
  TestCrankConfig config_;
};

inline std::any read_test_crank(DeviceReading& reading) {
  TestCrankConfig config;
  if (const auto rate = reading.reader.integer("counts_per_s", kCrankRate, scenario::Need::kRequired)) {
    config.counts_per_s = *rate;
  }
  read_bounded(reading.reader, "stop_s", run_time_range(reading.context), config.stop_s);
  return config;
}

/// The crank on the live view's page: a "cranks" part, the count it has turned so far.
class TestCrankDevice : public ModelDevice<TestCrank> {
 public:
  using ModelDevice::ModelDevice;
  void add_page_parts(const std::string& name, SimTime now, PageParts& parts) const override {
    parts.push_back({"cranks", {{"device", name}, {"count", model().count_at(now)}}});
  }
};

inline std::unique_ptr<SimDevice> build_test_crank(const scenario::DeviceConfig& device, DevicePlug& plug) {
  auto built = std::make_unique<TestCrankDevice>(std::make_unique<TestCrank>(*device.settings_as<TestCrankConfig>()));
  const TestCrank* model = &built->model();
  plug.connect_encoder(device.connector, [model](SimTime time) { return model->count_at(time); });
  return built;
}

inline const DeviceKind& test_crank_kind() {
  static const DeviceKind kind{
      "test_crank",
      "a test crank",
      "ENC1 or ENC2",
      scenario::is_encoder_connector,
      {integer_key("counts_per_s", kCrankRate), number_key("stop_s", scenario::ranges::kTimeS)},
      read_test_crank,
      build_test_crank,
      0,
      PageControl{PageControl::Type::kKnob, 0, 0, 1, "counts"},
      nullptr,
      {"cranks"},
  };
  return kind;
}

}  // namespace stepdance::sim::test
