// A run recorded for the replay page: view-protocol updates at evenly spaced instants, the
// devices' inputs and the wire around each instant, within stated capacities.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/simulation.hpp"
#include "view/run_control.hpp"
#include "view/view_session.hpp"
#include "view/wire_sampler.hpp"

namespace stepdance::sim::view {

/// The replay's format version (its "version" key); the page refuses others. Version 2: the
/// samples' updates are view protocol 2's deltas.
constexpr int kReplayFormatVersion = 2;

/// What a recording holds at most (docs/simulator.md, "The replay page").
struct ReplayLimits {
  /// Instants recorded per simulated second at most (the page's slider steps).
  double samples_per_s = 30;
  /// Instants at most: a longer batch run is sampled more sparsely (the interval grows to
  /// duration / max_samples); a live run's recording ends there (said in the recording).
  size_t max_samples = 20000;
  /// Bytes of recorded messages at most; the recording ends at the instant that passes it.
  size_t max_bytes = 16u << 20;
  /// The wire kept around each instant: frames starting within ±wire_window_ns / 2 of it.
  SimTime wire_window_ns = 400 * kMicrosecond;
  /// Frames kept per output port and instant at most (a frame is at most 32 edges a line).
  size_t max_frames_per_window = 16;
};

/// The interval between recorded instants for a run of `duration_ns` (ns): 1 / samples_per_s,
/// or duration / max_samples when that is longer. Context: any.
SimTime replay_interval_ns(SimTime duration_ns, const ReplayLimits& limits);

/// Records one Simulation for the replay page. Make it before the run (it adds wire listeners
/// on every output port and takes each board's console bytes), call sample() at every multiple
/// of interval_ns() of simulated time (attach_pacer() does it in a batch run), and recording()
/// after Simulation::finish(). Context: the thread running the simulation, between run_until()
/// calls or inside its pacer.
class ReplayRecorder {
 public:
  ReplayRecorder(Simulation& simulation, SimTime interval_ns, const ReplayLimits& limits = {});

  /// Makes the simulation call sample() every interval_ns() (its one pacer: a batch run only).
  void attach_pacer();
  /// Records the state at `now_ns` if an instant (a multiple of interval_ns()) not yet recorded
  /// is at or before it: exactly on it in a batch run, on the live run's next tick after it.
  void sample(SimTime now_ns);
  /// Bytes a board printed (the live front end passes them on; in a batch run the recorder
  /// takes them itself).
  void console(const std::string& board, const uint8_t* data, size_t length);
  /// The whole recording, the run's final state last: the JSON the page reads.
  nlohmann::json recording();

  SimTime interval_ns() const { return interval_ns_; }

 private:
  struct Probe {
    std::string device;
    std::string key;  ///< the probe's column without the device's name: "counts"
    std::function<double(SimTime)> read;
  };
  /// Appends the state at `now_ns` for instant `index` (-1: the end, no wire); the wire of the
  /// instant before it is complete by now.
  void record(SimTime now_ns, int64_t index, nlohmann::json update);
  void take_pending_wire();
  nlohmann::json inputs_json(SimTime now_ns) const;

  Simulation& simulation_;
  ReplayLimits limits_;
  SimTime interval_ns_;
  RunControl control_;
  ViewSession session_;
  WireSampler wire_;
  std::vector<Probe> probes_;
  nlohmann::json hello_;  ///< as the run starts
  nlohmann::json samples_ = nlohmann::json::array();
  int64_t next_index_ = 0;     ///< the next instant to record, in intervals
  int64_t pending_wire_ = -1;  ///< the last recorded instant whose wire is still being played
  size_t bytes_ = 0;
  bool full_ = false;  ///< a capacity was reached: nothing more recorded
  std::string full_reason_;
  SimTime full_at_ns_ = 0;
  size_t wire_frames_not_kept_ = 0;
};

}  // namespace stepdance::sim::view
