// The output ports' frames around evenly spaced instants: the replay page's logic-analyser strip.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "board/host/wire.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim::view {

/// One played frame kept for the strip: bit n of a word is the line's level from n µs to
/// n + 1 µs after `start_ns` (as WireListener::on_frame gives it).
struct KeptFrame {
  size_t port = 0;  ///< index into WireSampler::ports()
  SimTime start_ns = 0;
  uint32_t step_bits = 0;
  uint32_t dir_bits = 0;
};

/// Keeps the frames that output ports play within ±window_ns/2 of every multiple of
/// `interval_ns` (the replay's sample instants), at most `max_frames` per port and instant; the
/// frames past that are counted, never silently lost. Add the listeners (listener()) before the
/// run; take() each instant's frames once the run is past its window.
/// Context: the thread running the simulation.
class WireSampler {
 public:
  WireSampler(SimTime interval_ns, SimTime window_ns, size_t max_frames);
  ~WireSampler();
  WireSampler(const WireSampler&) = delete;
  WireSampler& operator=(const WireSampler&) = delete;

  /// A listener recording port `name` (e.g. "driver:OUT_A"); the sampler owns it.
  WireListener* listener(const std::string& name);
  /// The ports, in the order their listeners were made.
  const std::vector<std::string>& ports() const { return ports_; }

  /// What was kept around instant `index` × interval_ns (and is then forgotten), and how many
  /// frames there were beyond max_frames per port.
  std::vector<KeptFrame> take(int64_t index, size_t& not_kept);
  /// Keeps nothing more (the recording is full) and forgets what it holds.
  void stop();

 private:
  class Tap;
  struct Window {
    std::vector<KeptFrame> frames;
    std::vector<size_t> counts;  ///< frames seen per port
    size_t not_kept = 0;
  };
  void keep(size_t port, SimTime start_ns, uint32_t step_bits, uint32_t dir_bits);

  SimTime interval_ns_;
  SimTime half_window_ns_;
  size_t max_frames_;
  bool stopped_ = false;
  std::vector<std::string> ports_;
  std::vector<std::unique_ptr<Tap>> taps_;
  std::map<int64_t, Window> windows_;  ///< instant index → frames around it
};

}  // namespace stepdance::sim::view
