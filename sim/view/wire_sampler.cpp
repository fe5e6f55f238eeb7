// WireSampler: frames near the sample instants, bounded per port and instant.
#include "view/wire_sampler.hpp"

namespace stepdance::sim::view {

class WireSampler::Tap final : public WireListener {
 public:
  Tap(WireSampler& sampler, size_t port) : sampler_(sampler), port_(port) {}
  void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime /*frame_ns*/) override {
    sampler_.keep(port_, start_ns, words.step_bits, words.dir_bits);
  }

 private:
  WireSampler& sampler_;
  size_t port_;
};

WireSampler::WireSampler(SimTime interval_ns, SimTime window_ns, size_t max_frames)
    : interval_ns_(interval_ns), half_window_ns_(window_ns / 2), max_frames_(max_frames) {}

WireSampler::~WireSampler() = default;

WireListener* WireSampler::listener(const std::string& name) {
  ports_.push_back(name);
  taps_.push_back(std::make_unique<Tap>(*this, ports_.size() - 1));
  return taps_.back().get();
}

void WireSampler::keep(size_t port, SimTime start_ns, uint32_t step_bits, uint32_t dir_bits) {
  if (stopped_ || interval_ns_ <= 0 || start_ns < 0) return;
  const int64_t index = (start_ns + interval_ns_ / 2) / interval_ns_;  // the nearest instant
  const SimTime offset = start_ns - index * interval_ns_;
  if (offset < -half_window_ns_ || offset > half_window_ns_) return;
  Window& window = windows_[index];
  if (window.counts.size() < ports_.size()) window.counts.resize(ports_.size(), 0);
  if (window.counts[port]++ >= max_frames_) {
    ++window.not_kept;
    return;
  }
  window.frames.push_back({port, start_ns, step_bits, dir_bits});
}

std::vector<KeptFrame> WireSampler::take(int64_t index, size_t& not_kept) {
  not_kept = 0;
  std::vector<KeptFrame> frames;
  // Windows of earlier instants nobody asked for (a replay past its capacity) are dropped too.
  while (!windows_.empty() && windows_.begin()->first <= index) {
    if (windows_.begin()->first == index) {
      frames = std::move(windows_.begin()->second.frames);
      not_kept = windows_.begin()->second.not_kept;
    }
    windows_.erase(windows_.begin());
  }
  return frames;
}

void WireSampler::stop() {
  stopped_ = true;
  windows_.clear();
}

}  // namespace stepdance::sim::view
