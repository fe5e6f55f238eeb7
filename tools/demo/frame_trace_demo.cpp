// Demo of the engine without hardware: turns two virtual knobs of a Step-A-Sketch graph, reads
// every frame back off the wire and prints the decoded trace and per-port pulse counts.
#include <cstdio>
#include <cstdlib>

#include "hal_manual.hpp"
#include "step_a_sketch_graph.hpp"
#include "stepdance/protocol/frame_reader.hpp"

namespace {

using stepdance::OutputPort;
using namespace stepdance::protocol;

constexpr char kSignalNames[] = "XYRTZE";
constexpr uint8_t kPorts = 3;

struct Tally {
  uint32_t forward[stepdance::kNumSignals] = {};
  uint32_t reverse[stepdance::kNumSignals] = {};
  uint32_t rejected = 0;
};

// Decodes one port's frame as a receiving Stepdance input port would, printing each pulse.
void decode_port_frame(uint8_t port, Tally& tally, bool print) {
  const FrameWords words = stepdance::hal_manual::last_frame(port);
  WirePulse pulses[stepdance::kNumSignals];
  const size_t count = read_wire_pulses(words, pulses, stepdance::kNumSignals);
  const CaptureClock clock;
  for (size_t i = 0; i < count; ++i) {
    const CapturedPulse captured = capture_wire_pulse(pulses[i], clock, 0, DirSampleEdge::kFalling);
    const DecodedPulse decoded = decode_pulse(captured, clock, stepdance::INPUT_MODE_STEPDANCE, 0);
    if (decoded.verdict != PulseVerdict::kAccepted) {
      ++tally.rejected;
      continue;
    }
    (decoded.direction > 0 ? tally.forward : tally.reverse)[decoded.signal]++;
    if (print) {
      std::printf("  port %c: %c%c  STEP %2u..%2u us\n", 'A' + port, kSignalNames[decoded.signal],
                  decoded.direction > 0 ? '+' : '-', pulses[i].rise_us, pulses[i].fall_us);
    }
  }
}

// Sets the knobs for a frame: X out 3 mm and back, then Y out 2 mm, pen down meanwhile.
void drive_knobs(uint32_t frame, stepdance::workloads::StepASketchGraph& graph) {
  if (frame == 0) graph.pen.go(-200, stepdance::ABSOLUTE, 2000);
  const int32_t x_counts = frame < 10000 ? frame / 33 : 300 - (frame - 10000) / 33;
  const int32_t y_counts = frame < 20000 ? 0 : (frame - 20000) / 50;
  stepdance::hal_manual::set_quadrature(0, x_counts < 0 ? 0 : x_counts);
  stepdance::hal_manual::set_quadrature(1, y_counts > 200 ? 200 : y_counts);
}

}  // namespace

int main(int argc, char** argv) {
  const uint32_t frames = argc > 1 ? static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 32000u;
  const uint32_t printed_frames = 12;
  stepdance::workloads::StepASketchGraph graph;
  OutputPort* ports[kPorts] = {&graph.output_a, &graph.output_b, &graph.output_c};
  Tally tallies[kPorts];
  uint32_t printed = 0;

  std::printf("Stepdance frame trace: %u frames of 40 us (%.2f s), Step-A-Sketch graph\n", frames, frames * 40e-6);
  for (uint32_t frame = 0; frame < frames; ++frame) {
    drive_knobs(frame, graph);
    stepdance::engine().run_frame();
    bool any = false;
    for (uint8_t port = 0; port < kPorts; ++port) any |= stepdance::hal_manual::last_frame(port).step_bits != 0;
    const bool print = any && printed < printed_frames;
    if (print) std::printf("frame %u (t = %.2f ms)\n", frame, frame * 0.04);
    for (uint8_t port = 0; port < kPorts; ++port) decode_port_frame(port, tallies[port], print);
    if (print) ++printed;
  }

  std::printf("\nDecoded off the wire vs counted by the output ports (signal E):\n");
  int mismatches = 0;
  for (uint8_t port = 0; port < kPorts; ++port) {
    const uint32_t sent_f = ports[port]->pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_FORWARD);
    const uint32_t sent_r = ports[port]->pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_REVERSE);
    const Tally& t = tallies[port];
    std::printf("  port %c: decoded %5u forward %5u reverse, %u rejected | sent %5u forward %5u reverse\n", 'A' + port,
                t.forward[stepdance::SIGNAL_E], t.reverse[stepdance::SIGNAL_E], t.rejected, sent_f, sent_r);
    mismatches += (t.forward[stepdance::SIGNAL_E] != sent_f) + (t.reverse[stepdance::SIGNAL_E] != sent_r);
  }
  std::printf("Pen channel target: %.1f steps (servo µs offset)\n", graph.channel_z.target_position);
  std::printf("%s\n", mismatches == 0 ? "Every pulse sent was decoded." : "MISMATCH between sent and decoded pulses!");
  return mismatches == 0 ? 0 : 1;
}
