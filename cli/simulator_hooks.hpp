// What the command line plugs into the simulator library: the compiling board source, image
// boards and the PNG module.
#pragma once

#include <string>

#include "assembly/simulation.hpp"

namespace stepdance::cli {

/// Sets `options`' board source to a SketchBuilder caching in `cache_directory` ("" = its
/// default), its firmware source to image boards (sim/image) and its picture writer to the PNG
/// module. Context: before Simulation::create.
void plug_front_end(sim::SimulationOptions& options, const std::string& cache_directory);

}  // namespace stepdance::cli
