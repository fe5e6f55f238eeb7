// Frame words to edges.
#include "assembly/frame_waveform.hpp"

namespace stepdance::sim {
namespace {

void line_edges(SimTime start_ns, uint32_t bits, EdgeList& out) {
  out.clear();
  bool level = false;
  for (int bit = 0; bit < protocol::kFrameBitsUs; ++bit) {
    const bool high = ((bits >> bit) & 1u) != 0;
    if (high == level) continue;
    level = high;
    out.push_back({start_ns + SimTime{bit} * kMicrosecond, high});
  }
  if (level) out.push_back({start_ns + SimTime{protocol::kFrameBitsUs} * kMicrosecond, false});
}

}  // namespace

void frame_waveform(SimTime start_ns, const protocol::FrameWords& words, PortWaveform& out) {
  line_edges(start_ns, words.step_bits, out.step);
  line_edges(start_ns, words.dir_bits, out.dir);
}

}  // namespace stepdance::sim
