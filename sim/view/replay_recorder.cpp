// ReplayRecorder: the view session's updates, inputs and wire at each instant, bounded.
#include "view/replay_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "scenario/names.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;

std::string seconds_text(SimTime time_ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f s", to_seconds(time_ns));
  return text;
}

/// The points of an update's stroke parts.
size_t points_in(const json& update) {
  size_t points = 0;
  if (const auto strokes = update.find("strokes"); strokes != update.end()) {
    for (const json& part : *strokes) points += part["points"].size();
  }
  return points;
}

}  // namespace

SimTime replay_interval_ns(SimTime duration_ns, const ReplayLimits& limits) {
  const SimTime shortest = from_seconds(1.0 / limits.samples_per_s);
  const SimTime spread =
      limits.max_samples > 1 ? duration_ns / static_cast<SimTime>(limits.max_samples - 1) : duration_ns;
  // Whole milliseconds past the shortest interval, so the instants read plainly.
  if (spread <= shortest) return shortest;
  return (spread + kMillisecond - 1) / kMillisecond * kMillisecond;
}

ReplayRecorder::ReplayRecorder(Simulation& simulation, SimTime interval_ns, const ReplayLimits& limits)
    : simulation_(simulation),
      limits_(limits),
      interval_ns_(std::max<SimTime>(interval_ns, limits.wire_window_ns + kMicrosecond)),
      session_(simulation, control_),
      wire_(interval_ns_, limits.wire_window_ns, limits.max_frames_per_window) {
  for (const scenario::BoardConfig& board : simulation_.scenario().boards) {
    for (char port = 'A'; port <= 'D'; ++port) {
      if (!scenario::module_has_output_port(*board.module, port)) continue;
      simulation_.board(board.name)
          ->wire(terminal::OutputPort{static_cast<uint8_t>(port - 'A')}, wire_.listener(board.name + ":OUT_" + port));
    }
    const std::string name = board.name;
    simulation_.board(name)->console().on_bytes(
        [this, name](const uint8_t* data, size_t length) { session_.console_output(name, data, length); });
  }
  for (const scenario::DeviceConfig& device : simulation_.scenario().devices) {
    std::vector<DeviceProbe> found;
    if (const SimDevice* model = simulation_.device(device.name)) model->add_probes(device.name, found);
    for (DeviceProbe& probe : found) {
      std::string key =
          probe.column.rfind(device.name + "_", 0) == 0 ? probe.column.substr(device.name.size() + 1) : probe.column;
      probes_.push_back({device.name, std::move(key), std::move(probe.read)});
    }
  }
  hello_ = json::parse(session_.hello());
  sample(simulation_.now());
}

void ReplayRecorder::attach_pacer() {
  simulation_.pace_every(interval_ns_, [this](SimTime now) { sample(now); });
}

void ReplayRecorder::console(const std::string& board, const uint8_t* data, size_t length) {
  session_.console_output(board, data, length);
}

void ReplayRecorder::sample(SimTime now_ns) {
  if (full_ || now_ns >= simulation_.duration()) return;  // the end is recorded by recording()
  const int64_t index = now_ns / interval_ns_;
  if (index < next_index_) return;
  next_index_ = index + 1;
  record(now_ns, index, json::parse(session_.update_now()));
}

json ReplayRecorder::inputs_json(SimTime now_ns) const {
  json inputs = json::object();
  for (const scenario::DeviceConfig& device : simulation_.scenario().devices) {
    const SimDevice* model = simulation_.device(device.name);
    if (model == nullptr) continue;
    json own = json::object();
    model->add_replay_inputs(now_ns, own);
    if (!own.empty()) inputs[device.name] = std::move(own);
  }
  for (const Probe& probe : probes_) inputs[probe.device][probe.key] = probe.read(now_ns);
  return inputs;
}

void ReplayRecorder::take_pending_wire() {
  if (pending_wire_ < 0 || samples_.empty()) return;
  size_t not_kept = 0;
  json frames = json::array();
  const SimTime instant = pending_wire_ * interval_ns_;  // the offsets are from here
  for (const KeptFrame& frame : wire_.take(pending_wire_, not_kept)) {
    frames.push_back({frame.port, frame.start_ns - instant, frame.step_bits, frame.dir_bits});
  }
  pending_wire_ = -1;
  bytes_ += frames.dump().size();
  wire_frames_not_kept_ += not_kept;
  samples_.back()["wire"] = std::move(frames);
  if (not_kept > 0) samples_.back()["wire_frames_not_kept"] = not_kept;
}

void ReplayRecorder::record(SimTime now_ns, int64_t index, json update) {
  take_pending_wire();
  json sample = {{"update", std::move(update)}, {"inputs", inputs_json(now_ns)}, {"wire", json::array()}};
  const size_t size = sample.dump().size();
  const char* reason = nullptr;
  if (samples_.size() >= limits_.max_samples) reason = "instants";
  if (bytes_ + size > limits_.max_bytes) reason = "bytes";
  if (reason != nullptr) {
    full_ = true;
    full_at_ns_ = now_ns;
    full_reason_ = std::string("the recording reached its capacity of ") +
                   (reason == std::string("bytes") ? std::to_string(limits_.max_bytes) + " bytes"
                                                   : std::to_string(limits_.max_samples) + " instants") +
                   " at " + seconds_text(now_ns) + "; the run went on without it";
    wire_.stop();
    return;
  }
  bytes_ += size;
  samples_.push_back(std::move(sample));
  pending_wire_ = index;
}

json ReplayRecorder::recording() {
  if (!full_) {
    // The final state: everything the view still has to send, in one update (an update that
    // is short of kMaxPointsPerUpdate points holds all there was).
    json update = json::parse(session_.update_now());
    for (size_t points = points_in(update); points >= kMaxPointsPerUpdate;) {
      json more = json::parse(session_.update_now());
      points = points_in(more);
      for (json& part : more["strokes"]) update["strokes"].push_back(std::move(part));
      more["strokes"] = std::move(update["strokes"]);
      more["console"] = std::move(update["console"]);
      update = std::move(more);
    }
    record(simulation_.now(), -1, std::move(update));  // no wire: the run's end is no instant
    take_pending_wire();
  }
  json wire_info = {{"ports", wire_.ports()},
                    {"window_ns", limits_.wire_window_ns},
                    {"max_frames_per_window", limits_.max_frames_per_window},
                    {"frames_not_kept", wire_frames_not_kept_},
                    {"pulse_widths_us", json::object()}};
  static const char kNames[] = "XYRTZE";
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    wire_info["pulse_widths_us"][std::string(1, kNames[signal])] = protocol::pulse_width_us(signal);
  }
  return {{"format", "stepdance-replay"},
          {"version", kReplayFormatVersion},
          {"scenario", simulation_.scenario().file},
          {"duration_s", to_seconds(simulation_.duration())},
          {"interval_s", to_seconds(interval_ns_)},
          {"complete", !full_},
          {"note", full_reason_},
          {"limits",
           {{"max_samples", limits_.max_samples},
            {"max_bytes", limits_.max_bytes},
            {"samples_per_s", limits_.samples_per_s},
            {"wire_window_ns", limits_.wire_window_ns},
            {"max_frames_per_window", limits_.max_frames_per_window}}},
          {"hello", hello_},
          {"wire", std::move(wire_info)},
          {"samples", std::move(samples_)}};
}

}  // namespace stepdance::sim::view
