// ImageSource: a firmware ELF loaded onto an emulated chip for a board.
#include "image/board/image_source.hpp"

#include "image/board/image_program.hpp"

namespace stepdance::sim::image {

std::unique_ptr<BoardFirmware> ImageSource::load(const std::string& image_path, const BoardDefinition& module,
                                                 Scheduler& scheduler, std::string& error) const {
  const TeensyModel model = module.teensy == &kTeensy41 ? TeensyModel::kTeensy41 : TeensyModel::kTeensy40;
  auto program = std::make_unique<ImageProgram>(scheduler, model, image_path);
  if (!program->load(error)) {
    error = image_path + ": " + error;
    return nullptr;
  }
  return program;
}

}  // namespace stepdance::sim::image
