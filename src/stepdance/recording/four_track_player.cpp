// FourTrackPlayer: the loop reads the file into RAM, the frame plays one recorded frame per frame.
#include "stepdance/recording/four_track_player.hpp"

#include <stdint.h>

#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/hal/storage.hpp"

namespace stepdance {
namespace {

constexpr const char* kSource = "player";

using recording::FileName;
using recording::recording_file_name;

}  // namespace

FourTrackPlayer::FourTrackPlayer() {
  for (BlockPort& port : output_BlockPorts) port.set_ratio(resolution_, 1.0);
}

// The player registers in the input-port stage, like the original (original-library.md §4.12), so its steps
// enter the frame where received pulses do and reach the channels in the same frame; the loop stage
// refills the RAM ring from the card.
Status FourTrackPlayer::begin() {
  for (size_t track = 0; track < recording::kTracks; ++track) {
    output_BlockPorts[track].begin(&positions_[track], BLOCKPORT_OUTPUT, this);
  }
  const Status status = register_in(Stage::kInputPorts);
  return status != Status::kOk ? status : register_in(Stage::kLoop);
}

// Applies to original-format files only (they carry no resolution); a Stepdance-format file sets
// each track's resolution from its header. A zero ratio is ignored rather than dividing by it.
void FourTrackPlayer::set_resolution(double world_units, double per_steps) {
  if (world_units == 0.0 || per_steps == 0.0) return;
  resolution_ = world_units / per_steps;
}

// Validates the name before touching the card, so a bad name leaves the previous state stopped
// but the card untouched. Loop context.
Status FourTrackPlayer::start(const char* name) {
  stop();
  FileName probe;
  if (!recording_file_name(name, ".bin", probe)) {
    fail("FourTrackPlayer::start: the name is empty or too long for the card", Status::kBadArgument);
    return Status::kBadArgument;
  }
  const Status status = open_files(name);
  if (status != Status::kOk) return status;
  current_sample_index = 0;
  paused_ = false;
  in_underrun_ = false;
  playback_active = true;
  return Status::kOk;
}

// Reads the length file, opens the data file, recognises its format and fills the ring.
Status FourTrackPlayer::open_files(const char* name) {
  read_length_file(name);
  FileName data_name;
  recording_file_name(name, ".bin", data_name);
  FileStorage& storage = hal::storage();
  const Status opened = storage.open(data_name, FileMode::kRead, handle_);
  if (opened == Status::kUnsupported) {
    fail("FourTrackPlayer::start: this board has no SD card slot (a Teensy 4.0 has none; play back on a 4.1)", opened);
    return opened;
  }
  if (opened != Status::kOk) {
    fail("FourTrackPlayer::start: cannot open the recording", Status::kIoError);
    return Status::kIoError;
  }
  file_open_ = true;
  uint8_t first[recording::kStorageChunkBytes];
  size_t length = 0;
  Status status = storage.read(handle_, first, sizeof(first), length);
  size_t data_start = 0;
  if (status == Status::kOk) status = take_header(first, length, data_start);
  if (status != Status::kOk) {
    stop();
    return status;
  }
  for (size_t i = data_start; i < length; ++i) ring_.push(first[i]);
  bytes_read_ = length;
  bool end = length < sizeof(first);
  status = recording::fill_ring_from_file(ring_, storage, handle_, end, bytes_read_);
  end_of_file_ = end;
  if (status != Status::kOk) fail("FourTrackPlayer::start: the card failed reading the recording", status);
  return status;
}

// The frame count lives in a separate ASCII file (<name>_len.bin, the original's layout) because the
// recorder only knows it at the end. Without it the player plays to the end of the data file
// instead of refusing: the steps are still valid.
Status FourTrackPlayer::read_length_file(const char* name) {
  max_num_playback_samples = UINT64_MAX;
  FileName length_name;
  recording_file_name(name, "_len.bin", length_name);
  FileStorage& storage = hal::storage();
  int handle = -1;
  if (storage.open(length_name, FileMode::kRead, handle) != Status::kOk) return Status::kIoError;
  char text[32];
  size_t length = 0;
  const Status status = storage.read(handle, reinterpret_cast<uint8_t*>(text), sizeof(text), length);
  storage.close(handle);
  uint64_t frames = 0;
  if (status != Status::kOk || !recording::parse_length(text, length, frames)) {
    hal::log_message("FourTrackPlayer::start: the length file is unreadable; playing to the end of the file");
    return Status::kIoError;
  }
  max_num_playback_samples = frames;
  return Status::kOk;
}

// Chooses the format from the first bytes and sets the outputs' resolution from it.
// A file without our magic is taken as the original format (one byte per frame, no header), which
// only has a meaning at the original 40 µs frame. Our format records its frame period, and a
// recording played at another period would play at the wrong speed, so it is refused.
Status FourTrackPlayer::take_header(const uint8_t* data, size_t length, size_t& data_start) {
  recording::RecordingHeader header;
  const recording::HeaderCheck check = recording::read_header(data, length, header);
  if (check == recording::HeaderCheck::kNotOurs) {
    if (frame_period_us() != recording::kOriginalFramePeriodUs) {
      fail("FourTrackPlayer::start: an original-format recording plays at 40 us frames only", Status::kUnsupported);
      return Status::kUnsupported;
    }
    file_format_ = recording::RecordingFormat::kOriginal;
    for (BlockPort& port : output_BlockPorts) port.set_ratio(resolution_, 1.0);
    data_start = 0;
    return Status::kOk;
  }
  if (check != recording::HeaderCheck::kOk) {
    fail("FourTrackPlayer::start: a recording of a format version this library cannot play", Status::kUnsupported);
    return Status::kUnsupported;
  }
  if (header.frame_period_ns != frame_period_us() * 1000u) {
    fail("FourTrackPlayer::start: the recording was made at another frame period", Status::kUnsupported);
    return Status::kUnsupported;
  }
  file_format_ = recording::RecordingFormat::kStepdance;
  for (size_t track = 0; track < recording::kTracks; ++track) {
    output_BlockPorts[track].set_ratio(header.resolution[track], 1.0);
  }
  data_start = header.header_bytes;
  return Status::kOk;
}

// Loop context: the ring is emptied so a later start() cannot play bytes of this recording.
void FourTrackPlayer::stop() {
  playback_active = false;
  if (file_open_) hal::storage().close(handle_);
  file_open_ = false;
  end_of_file_ = false;
  uint8_t stale = 0;
  while (ring_.pop(stale) == Status::kOk) {
  }
}

// Frame context (input-port stage). The ports are pushed every frame, playing or not, so a
// downstream block always sees this frame's (possibly unchanged) positions.
void FourTrackPlayer::run() {
  if (playback_active && !paused_ && !play_frame()) playback_active = false;
  for (BlockPort& port : output_BlockPorts) port.push();
}

// Plays one recorded frame; false when the recording has ended.
// An empty ring before the end of file is an underrun: the frame waits (playback stretches in
// time) rather than skipping steps, which would shift the drawing. Warned once per underrun.
// A frame's bytes are only popped when the whole frame is in the ring.
bool FourTrackPlayer::play_frame() {
  if (current_sample_index >= max_num_playback_samples) return false;
  const size_t bytes = recording::bytes_per_frame(file_format_);
  if (ring_.size() < bytes) {
    if (end_of_file_) return false;
    ++underruns_;
    if (!in_underrun_)
      report_fault(FaultLevel::kWarning, FaultReason::kOverrun, kSource, "storage too slow: playback waits");
    in_underrun_ = true;
    return true;
  }
  in_underrun_ = false;
  int8_t steps[recording::kTracks] = {};
  uint8_t byte = 0;
  if (file_format_ == recording::RecordingFormat::kOriginal) {
    ring_.pop(byte);
    recording::unpack_original_frame(byte, steps);
  } else {
    for (int8_t& step : steps) {
      ring_.pop(byte);
      step = static_cast<int8_t>(byte);
    }
  }
  for (size_t track = 0; track < recording::kTracks; ++track) {
    if (steps[track] != 0) output_BlockPorts[track].set(positions_[track] + steps[track]);
  }
  current_sample_index = current_sample_index + 1;
  return true;
}

// Loop context: the card is only read here, never in the frame (SD reads take milliseconds).
// Playback ended by the frame (playback_active false) is finished here, closing the file.
void FourTrackPlayer::loop() {
  if (!file_open_) return;
  if (!playback_active) {
    stop();
    return;
  }
  bool end = end_of_file_;
  const Status status = recording::fill_ring_from_file(ring_, hal::storage(), handle_, end, bytes_read_);
  end_of_file_ = end;
  if (status != Status::kOk) {
    fail("FourTrackPlayer: the card failed; playback stopped", status);
    stop();
  }
}

// Card errors count as hardware faults; refusals (bad name, wrong format) as refused requests.
void FourTrackPlayer::fail(const char* message, Status status) {
  hal::log_message(message);
  const bool storage = status == Status::kIoError;
  if (storage) ++storage_errors_;
  report_fault(FaultLevel::kWarning, storage ? FaultReason::kHardware : FaultReason::kRefused, kSource, message);
}

void FourTrackPlayer::report_counters(CounterSink& sink) const {
  sink.counter("underruns", underruns_);
  sink.counter("storage_errors", storage_errors_);
  sink.counter("bytes_read", bytes_read_);
}

}  // namespace stepdance
