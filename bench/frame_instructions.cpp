// Runs N frames of a benchmark graph (step_a_sketch, step_a_sketch_tbi, harmonograph,
// clay_texturizer, axidraw_wave or pantograph); measured with callgrind to count instructions per frame (see
// measure_frame_instructions.sh).
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "axidraw_wave_graph.hpp"
#include "clay_texturizer_graph.hpp"
#include "harmonograph_graph.hpp"
#include "pantograph_graph.hpp"
#include "step_a_sketch_graph.hpp"
#include "step_a_sketch_tbi_graph.hpp"

namespace {

template <typename Graph>
uint32_t run(uint32_t frames) {
  Graph graph;
  for (uint32_t frame = 0; frame < frames; ++frame) graph.run_busy_frame(frame);
  return graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_FORWARD) +
         graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_REVERSE);
}

}  // namespace

int main(int argc, char** argv) {
  const uint32_t frames = argc > 1 ? static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 100000u;
  const char* workload = argc > 2 ? argv[2] : "step_a_sketch";
  uint32_t pulses = 0;
  if (std::strcmp(workload, "step_a_sketch") == 0) {
    pulses = run<stepdance::workloads::StepASketchGraph>(frames);
  } else if (std::strcmp(workload, "harmonograph") == 0) {
    pulses = run<stepdance::workloads::HarmonographGraph>(frames);
  } else if (std::strcmp(workload, "step_a_sketch_tbi") == 0) {
    pulses = run<stepdance::workloads::StepASketchTbiGraph>(frames);
  } else if (std::strcmp(workload, "clay_texturizer") == 0) {
    pulses = run<stepdance::workloads::ClayTexturizerGraph>(frames);
  } else if (std::strcmp(workload, "axidraw_wave") == 0) {
    pulses = run<stepdance::workloads::AxiDrawWaveGraph>(frames);
  } else if (std::strcmp(workload, "pantograph") == 0) {
    pulses = run<stepdance::workloads::PantographGraph>(frames);
  } else {
    std::fprintf(stderr,
                 "unknown workload '%s' (step_a_sketch, step_a_sketch_tbi, harmonograph, clay_texturizer, axidraw_wave "
                 "or pantograph)\n",
                 workload);
    return 2;
  }
  std::printf("workload=%s frames=%u pulses_a=%u\n", workload, frames, pulses);
  return pulses > 0 ? 0 : 1;
}
