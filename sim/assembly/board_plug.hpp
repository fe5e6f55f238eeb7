// The board side of a device kind's model factory: DevicePlug over a SimBoard (connector → pin,
// encoder counter, ADC channel or I2C bus), and PictureSink into the output folder.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "board/host/sim_board.hpp"
#include "kinds/sim_device.hpp"
#include "output/picture_writer.hpp"

namespace stepdance::sim {

/// Plugs devices into one board. Sources go to the board unwrapped (no extra call per read).
class BoardPlug : public DevicePlug {
 public:
  BoardPlug(SimBoard& board, uint64_t seed, std::function<const Machine*()> machine)
      : board_(board), seed_(seed), machine_(std::move(machine)) {}

  void connect_encoder(scenario::Connector connector, Source<int64_t> counts) override;
  void connect_analog(scenario::Connector connector, Source<uint16_t> value) override;
  void connect_digital(scenario::Connector connector, Source<bool> level) override;
  void attach_i2c(scenario::Connector connector, uint8_t address, I2cDevice* device) override;
  std::function<const Machine*()> machine() const override { return machine_; }
  uint64_t seed() const override { return seed_; }

 private:
  SimBoard& board_;
  uint64_t seed_;
  std::function<const Machine*()> machine_;
};

/// Writes device pictures into files through `writer` (the PNG module); path_for(file name)
/// gives the path in the output folder. The paths written are appended to `files`.
class PictureFileSink : public PictureSink {
 public:
  PictureFileSink(const PictureWriter& writer, std::function<std::string(const std::string&)> path_for,
                  std::vector<std::string>& files)
      : writer_(writer), path_for_(std::move(path_for)), files_(files) {}
  void write_picture(const std::string& file_name, const std::vector<bool>& lit, int width, int height,
                     int scale) override;

 private:
  const PictureWriter& writer_;
  std::function<std::string(const std::string&)> path_for_;
  std::vector<std::string>& files_;
};

}  // namespace stepdance::sim
