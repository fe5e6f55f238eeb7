// plug_front_end: SketchBuilder, image boards and the PNG module for a simulation the command line runs.
#include "simulator_hooks.hpp"

#include <memory>

#include "board/loader/sketch_builder.hpp"
#include "image/board/image_source.hpp"
#include "output/png_picture_writer.hpp"

namespace stepdance::cli {

void plug_front_end(sim::SimulationOptions& options, const std::string& cache_directory) {
  options.boards = std::make_shared<sim::SketchBuilder>(cache_directory);
  options.pictures = sim::png_pictures();
  options.firmware = std::make_shared<sim::image::ImageSource>();
}

}  // namespace stepdance::cli
