// What a device kind's model factory builds and plugs in: the device (SimDevice) and the board
// side it plugs into (DevicePlug), with no simulator kernel behind them.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/sim_time.hpp"
#include "kinds/page_part.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

class I2cDevice;
class Machine;

/// One CSV column of a device: its name, digits after the point, and its value at a time.
struct DeviceProbe {
  std::string column;
  int decimals = 0;
  std::function<double(SimTime)> read;
};

/// Writes a device's picture (an OLED's screen) as a file of the output folder.
class PictureSink {
 public:
  virtual ~PictureSink() = default;
  /// Writes `lit` (row-major, width × height) scaled `scale` times as the image file `file_name`
  /// of the output folder. Context: host, end of the run.
  virtual void write_picture(const std::string& file_name, const std::vector<bool>& lit, int width, int height,
                             int scale) = 0;
};

/// A device built from a scenario's [[device]]: its model, plugged into a board.
class SimDevice {
 public:
  virtual ~SimDevice() = default;
  /// Schedules one timeline action aimed at this device (the scenario reader has checked that
  /// the kind takes the action: DeviceKind::actions).
  virtual void schedule(const scenario::Action& action) { (void)action; }
  /// Appends the device's CSV columns, named after the device.
  virtual void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const {
    (void)name;
    (void)probes;
  }
  /// At the end of the run: writes the device's own files (exactly DeviceKind::output_names).
  virtual void write_outputs(const std::string& name, PictureSink& sink) {
    (void)name;
    (void)sink;
  }
  /// The live view's page: appends the device's state parts at `now` (ns) for an `update`
  /// (kinds/page_part.hpp), each naming the device `name` in its "device" key; the view sends
  /// those that changed. Context: the simulation's thread, between run_until() calls.
  virtual void add_page_parts(const std::string& name, SimTime now, PageParts& parts) const {
    (void)name;
    (void)now;
    (void)parts;
  }
  /// The live view's page: adds what the page needs to draw the device's control to `control`,
  /// the kind's PageControl as `hello` sends it (e.g. "counts_per_turn": the counts one turn of a
  /// knob gives). Context: the simulation's thread.
  virtual void describe_page_control(nlohmann::json& control) const { (void)control; }
  /// The replay page: adds the device's inputs at `now` (ns) to `inputs`, its entry of a recorded
  /// instant's "inputs" (e.g. "pressed": whether a hand holds a button), beside its CSV columns.
  /// Context: the simulation's thread, as the run is recorded.
  virtual void add_replay_inputs(SimTime now, nlohmann::json& inputs) const {
    (void)now;
    (void)inputs;
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

/// The board a device plugs into, by connector: the simulator's board wiring implements it. A
/// source is read whenever the sketch reads the line (it must be cheap and pure in time).
class DevicePlug {
 public:
  template <typename T>
  using Source = std::function<T(SimTime)>;

  virtual ~DevicePlug() = default;
  /// ENC1/ENC2: the quadrature counter's count.
  virtual void connect_encoder(scenario::Connector connector, Source<int64_t> counts) = 0;
  /// A1..A4: the 10-bit ADC reading.
  virtual void connect_analog(scenario::Connector connector, Source<uint16_t> value) = 0;
  /// D1, D2, A1..A4 or LIMIT_A..LIMIT_D: the input line's level.
  virtual void connect_digital(scenario::Connector connector, Source<bool> level) = 0;
  /// QWIIC0/QWIIC1: a device on the I2C bus at a 7-bit address (it must outlive the run).
  virtual void attach_i2c(scenario::Connector connector, uint8_t address, I2cDevice* device) = 0;
  /// Finds the scenario's machine when called (null without one, or before it is built).
  virtual std::function<const Machine*()> machine() const = 0;
  /// The scenario's seed, for anything random.
  virtual uint64_t seed() const = 0;
};

}  // namespace stepdance::sim
