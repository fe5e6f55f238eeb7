// Runs N frames of the Step-A-Sketch-sized graph; measured with callgrind to count
// instructions per frame (see measure_frame_instructions.sh).
#include <cstdio>
#include <cstdlib>

#include "step_a_sketch_graph.hpp"

int main(int argc, char** argv) {
  const uint32_t frames = argc > 1 ? static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 100000u;
  stepdance::workloads::StepASketchGraph graph;
  for (uint32_t frame = 0; frame < frames; ++frame) graph.run_busy_frame(frame);
  std::printf("frames=%u pulses_a=%u\n", frames,
              graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_FORWARD) +
                  graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_REVERSE));
  return 0;
}
