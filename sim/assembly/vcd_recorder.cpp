// VCD recording of output ports (frame by frame) and input ports (what cables deliver).
#include "assembly/vcd_recorder.hpp"

#include "assembly/frame_waveform.hpp"

namespace stepdance::sim {

/// Turns each played frame into edges on the port's two VCD wires.
class VcdRecorder::OutputTap final : public WireListener {
 public:
  OutputTap(VcdRecorder& recorder, LinePair lines) : recorder_(recorder), lines_(lines) {}
  void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime /*frame_ns*/) override {
    frame_waveform(start_ns, words, waveform_);
    recorder_.record(lines_, waveform_);
  }

 private:
  VcdRecorder& recorder_;
  LinePair lines_;
  PortWaveform waveform_;
};

VcdRecorder::VcdRecorder(const std::string& path) : writer_(path, VcdWriterOptions{}) {}

VcdRecorder::~VcdRecorder() = default;

VcdRecorder::LinePair VcdRecorder::declare(const std::string& board, const std::string& prefix) {
  return {writer_.add_wire(board, prefix + "_STEP"), writer_.add_wire(board, prefix + "_DIR")};
}

WireListener* VcdRecorder::record_output(const std::string& board, char port_letter) {
  outputs_.push_back(std::make_unique<OutputTap>(*this, declare(board, std::string("OUT_") + port_letter)));
  return outputs_.back().get();
}

size_t VcdRecorder::declare_input(const std::string& board, char port_letter) {
  inputs_.push_back(declare(board, std::string("IN_") + port_letter));
  return inputs_.size() - 1;
}

void VcdRecorder::record_input(size_t input, const PortWaveform& waveform) { record(inputs_.at(input), waveform); }

void VcdRecorder::record(const LinePair& lines, const PortWaveform& waveform) {
  for (const Edge& edge : waveform.step) {
    if (edge.time <= end_ns_) writer_.record(lines.step, edge.time, edge.level);
  }
  for (const Edge& edge : waveform.dir) {
    if (edge.time <= end_ns_) writer_.record(lines.dir, edge.time, edge.level);
  }
}

}  // namespace stepdance::sim
