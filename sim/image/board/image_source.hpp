// Loads firmware images for a Simulation: the front end's FirmwareSource for image boards.
#pragma once

#include <memory>

#include "board/host/board_firmware.hpp"

namespace stepdance::sim::image {

/// Image boards for the simulator library (plugged in by the command line, as SketchBuilder is).
/// The Teensy emulated is the module's (the Driver Module's Teensy 4.1, the Basic Module's 4.0).
class ImageSource final : public FirmwareSource {
 public:
  std::unique_ptr<BoardFirmware> load(const std::string& image_path, const BoardDefinition& module,
                                      Scheduler& scheduler, std::string& error) const override;
};

}  // namespace stepdance::sim::image
