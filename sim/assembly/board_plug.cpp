// BoardPlug: a connector's pin or channel on the board's definition; PictureFileSink.
#include "assembly/board_plug.hpp"

#include <filesystem>

#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

using scenario::Connector;

/// The board pin behind a digital, analog or limit connector.
uint8_t connector_pin(const BoardDefinition& board, Connector connector) {
  const uint8_t index = scenario::connector_index(connector);
  if (scenario::is_analog_connector(connector)) return board.io_a[index];
  if (scenario::is_digital_connector(connector)) return board.io_d[index];
  return board.output_ports[index].limit;
}

}  // namespace

void BoardPlug::connect_encoder(Connector connector, Source<int64_t> counts) {
  board_.wire(terminal::Encoder{scenario::connector_index(connector)}, std::move(counts));
}

void BoardPlug::connect_analog(Connector connector, Source<uint16_t> value) {
  board_.wire(terminal::Analog{connector_pin(board_.definition(), connector)}, std::move(value));
}

void BoardPlug::connect_digital(Connector connector, Source<bool> level) {
  board_.wire(terminal::InputPin{connector_pin(board_.definition(), connector)}, std::move(level));
}

void BoardPlug::attach_i2c(Connector connector, uint8_t address, I2cDevice* device) {
  board_.wire(terminal::I2c{scenario::connector_index(connector), address}, device);
}

void PictureFileSink::write_picture(const std::string& file_name, const std::vector<bool>& lit, int width, int height,
                                    int scale) {
  const std::string path = path_for_(file_name);
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  writer_.write_screen(path, lit, width, height, scale);
  files_.push_back(path);
}

}  // namespace stepdance::sim
