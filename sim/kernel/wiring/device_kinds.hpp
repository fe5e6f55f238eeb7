// Input devices of the simulation by kind: one builder per scenario DeviceType, one interface
// for what the timeline and the CSV need of any device. A new kind is a new row here.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "board/sim_board.hpp"
#include "models/machine.hpp"
#include "scenario/scenario.hpp"
#include "wiring/csv_sampler.hpp"

namespace stepdance::sim {

/// A device built from a scenario's [[device]]: its model, plugged into a board.
class SimDevice {
 public:
  virtual ~SimDevice() = default;
  /// Schedules one timeline action aimed at this device (the scenario reader has checked that
  /// the action fits the kind: turn → encoder, set → pot, press/release/click → button).
  virtual void schedule(const scenario::Action& action) { (void)action; }
  /// Appends the device's CSV columns, named after the device.
  virtual void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const {
    (void)name;
    (void)probes;
  }
  /// At the end of the run: writes the device's own files (an OLED's screen pictures), named
  /// after the device; path_for(file name) gives the path in the output folder. Appends the
  /// paths written to `files`.
  virtual void write_outputs(const std::string& name, const std::function<std::string(const std::string&)>& path_for,
                             std::vector<std::string>& files) {
    (void)name;
    (void)path_for;
    (void)files;
  }
};

/// A device whose model is a T; model_of<T>() finds it again.
template <typename T>
class ModelDevice : public SimDevice {
 public:
  explicit ModelDevice(std::unique_ptr<T> model) : model_(std::move(model)) {}
  T& model() { return *model_; }
  const T& model() const { return *model_; }

 private:
  std::unique_ptr<T> model_;
};

/// The model behind a device if it is a T, else null.
template <typename T>
const T* model_of(const SimDevice* device) {
  const auto* typed = dynamic_cast<const ModelDevice<T>*>(device);
  return typed == nullptr ? nullptr : &typed->model();
}

/// What a builder may use to plug its model in.
struct DeviceSocket {
  SimBoard& board;
  uint64_t scenario_seed;
  /// The machine limit switches watch (null until built, or without a machine).
  std::function<const Machine*()> machine;
};

/// Builds the model of one [[device]] and connects it to the board.
std::unique_ptr<SimDevice> build_device_model(const scenario::DeviceConfig& device, DeviceSocket& socket);

/// The names of the files (in the output folder) the device will write at the end of the run,
/// known before it is built, so they can be checked against the run's other files; empty for
/// a kind that writes none. SimDevice::write_outputs writes exactly these. Context: host.
std::vector<std::string> device_output_names(const scenario::DeviceConfig& device);

}  // namespace stepdance::sim
