// Capture decoder: STEP edges paired into pulses, DIR sampled, decode_pulse called, frames grouped;
// edge by edge (StepDirDecoder), or over two edge lists at once (decode_step_dir).
#include "decode/capture_decoder.hpp"

namespace stepdance::sim {

uint64_t capture_ticks(SimTime time_ns, uint32_t ticks_per_us) {
  const uint64_t ns = static_cast<uint64_t>(time_ns);
  return ns / 1000 * ticks_per_us + (ns % 1000 * ticks_per_us + 500) / 1000;
}

StepDirDecoder::StepDirDecoder(const DecodeOptions& options, InitialLevels initial)
    : sample_edge_(protocol::dir_sample_edge(options.mode)),
      dir_level_(initial.dir),
      level_(initial.step),
      pending_level_(initial.step),
      frames_(options.frame_period_us) {
  result_.options = options;
  if (level_) ++result_.incomplete;  // already high: its rise was not captured
}

void StepDirDecoder::step_edge(SimTime time_ns, bool level) {
  if (pending_count_ > 0 && time_ns > pending_time_) flush();
  if (level == pending_level_) return;
  if (pending_count_ == 0) {
    pending_time_ = time_ns;
    pending_first_ = level;
  }
  ++pending_count_;
  pending_level_ = level;
}

void StepDirDecoder::dir_edge(SimTime time_ns, bool level) {
  if (pending_count_ > 0 && time_ns > pending_time_) flush();
  dir_level_ = level;
}

void StepDirDecoder::flush() {
  bool level = pending_first_;
  for (uint64_t i = 0; i < pending_count_; ++i, level = !level) apply_step(pending_time_, level);
  pending_count_ = 0;
}

void StepDirDecoder::apply_step(SimTime time_ns, bool level) {
  level_ = level;
  if (level) {
    have_rise_ = true;
    rise_ = time_ns;
    dir_at_rise_ = dir_level_;
    return;
  }
  if (!have_rise_) return;  // the fall of a pulse already high at the start
  have_rise_ = false;
  const DecodeOptions& options = result_.options;
  const bool dir_high = sample_edge_ == protocol::DirSampleEdge::kRising ? dir_at_rise_ : dir_level_;
  const protocol::CapturedPulse pulse =
      protocol::captured_from_ticks(capture_ticks(rise_, options.clock.ticks_per_us),
                                    capture_ticks(time_ns, options.clock.ticks_per_us), dir_high, options.clock);
  const protocol::DecodedPulse decoded =
      protocol::decode_pulse(pulse, options.clock, options.mode, options.step_dir_signal);
  result_.counts.add(decoded);
  if (decoded.verdict == protocol::PulseVerdict::kAccepted) {
    ++result_.accepted;
    frames_.add(rise_, time_ns);
    return;
  }
  if (result_.first_rejected.size() < options.max_rejected_examples) {
    result_.first_rejected.push_back(RejectedPulse{rise_, time_ns, decoded.width_us, decoded.verdict});
  }
}

DecodeResult StepDirDecoder::finish() {
  flush();
  if (have_rise_) ++result_.incomplete;  // still high at the end
  result_.frames = frames_.stats();
  return result_;
}

DecodeResult decode_step_dir(const EdgeList& step, const EdgeList& dir, const DecodeOptions& options,
                             InitialLevels initial) {
  StepDirDecoder decoder(options, initial);
  size_t next_dir = 0;
  for (const Edge& edge : step) {
    while (next_dir < dir.size() && dir[next_dir].time <= edge.time) {
      decoder.dir_edge(dir[next_dir].time, dir[next_dir].level);
      ++next_dir;
    }
    decoder.step_edge(edge.time, edge.level);
  }
  return decoder.finish();
}

}  // namespace stepdance::sim
