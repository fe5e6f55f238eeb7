// FourTrackRecorder: the frame packs samples into RAM, the loop writes them to storage.
#include "stepdance/recording/four_track_recorder.hpp"

#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/hal/storage.hpp"

namespace stepdance {
namespace {

constexpr const char* kSource = "recorder";

}  // namespace

FourTrackRecorder::FourTrackRecorder() = default;

// Post-channel stage, as in the original (original-library.md §4.12): it records what the channels did this
// frame. The loop stage writes the RAM ring to the card.
Status FourTrackRecorder::begin() {
  for (RecorderTrack& track : tracks) track.begin(this);
  const Status status = register_in(Stage::kPostChannel);
  return status != Status::kOk ? status : register_in(Stage::kLoop);
}

void FourTrackRecorder::set_resolution(double world_units, double per_steps) {
  for (RecorderTrack& track : tracks) track.set_resolution(world_units, per_steps);
}

// Loop context. start() while recording resumes (the original's behaviour). The planned length in
// frames is computed in 64 bits: the original's minutes × 60 × 1 000 000 overflowed a 32-bit long
// from 36 minutes on (original-library.md §7.6 #37). Our header records the frame period and each track's
// resolution so the player can refuse a recording it would play at the wrong scale or speed.
Status FourTrackRecorder::start(const char* name, uint32_t minutes) {
  if (recorder_active) {
    resume();
    return Status::kOk;
  }
  if (file_open_) finish();  // the frame stopped the last one; the loop has not finished it yet
  if (!recording::recording_file_name(name, ".bin", data_name_) ||
      !recording::recording_file_name(name, "_len.bin", length_name_)) {
    hal::log_message("FourTrackRecorder::start: the name is empty or too long for the card");
    report_fault(FaultLevel::kWarning, FaultReason::kRefused, kSource, "recording name empty or too long");
    return Status::kBadArgument;
  }
  if (format_ == RecordingFormat::kOriginal && frame_period_us() != recording::kOriginalFramePeriodUs) {
    hal::log_message(
        "FourTrackRecorder::start: the original format holds 40 us frames only; use RECORDING_FORMAT_STEPDANCE");
    report_fault(FaultLevel::kWarning, FaultReason::kRefused, kSource, "the original format holds 40 us frames only");
    return Status::kUnsupported;
  }
  FileStorage& storage = hal::storage();
  const Status opened = storage.open(data_name_, FileMode::kWriteTruncate, handle_);
  if (opened == Status::kUnsupported) {
    hal::log_message(
        "FourTrackRecorder::start: this board has no SD card slot (a Teensy 4.0 has none; record on a 4.1)");
    report_fault(FaultLevel::kWarning, FaultReason::kRefused, kSource, "no SD card slot on this board");
    return Status::kUnsupported;
  }
  if (opened != Status::kOk) {
    hal::log_message("FourTrackRecorder::start: cannot create the recording file (no card?)");
    report_fault(FaultLevel::kWarning, FaultReason::kHardware, kSource, "cannot create the recording file");
    return Status::kIoError;
  }
  file_open_ = true;
  file_format_ = format_;
  uint8_t stale = 0;
  while (ring_.pop(stale) == Status::kOk) {
  }  // left by a recording the card cut short
  bytes_written_ = 0;
  if (file_format_ == RecordingFormat::kStepdance) {
    recording::RecordingHeader header;
    header.frame_period_ns = frame_period_us() * 1000u;
    for (size_t track = 0; track < recording::kTracks; ++track) header.resolution[track] = tracks[track].resolution();
    uint8_t bytes[recording::kHeaderBytes];
    recording::write_header(header, bytes);
    if (storage.write(handle_, bytes, sizeof(bytes)) != Status::kOk) {
      fail_storage("cannot write the recording header");
      return Status::kIoError;
    }
    bytes_written_ = sizeof(bytes);
  }
  current_sample_index = 0;
  max_num_samples = recording::frames_for_minutes(minutes, frame_rate_hz());
  stop_cause_ = StopCause::kNone;
  paused_ = false;
  recorder_active = true;
  return Status::kOk;
}

// Loop context. Distinguishes a user stop from a stop the frame already decided (full, overrun),
// so finish() logs the real cause.
Status FourTrackRecorder::stop() {
  if (!file_open_) return Status::kNotStarted;
  if (recorder_active) stop_cause_ = StopCause::kUser;
  recorder_active = false;
  return finish();
}

// Frame context (post-channel). While paused or idle the tracks follow their input silently, so
// resuming records only motion made after the resume and not the jump accumulated meanwhile.
// A full ring stops the recording instead of dropping a frame: a recording with a hole would play
// back displaced, one that ends early is merely short.
void FourTrackRecorder::run() {
  for (RecorderTrack& track : tracks) track.follow_input();
  if (!recorder_active || paused_) {
    for (RecorderTrack& track : tracks) track.sync_to_input();
    return;
  }
  if (current_sample_index >= max_num_samples) {
    stop_cause_ = StopCause::kFull;
    recorder_active = false;
    return;
  }
  if (!queue_sample()) {
    ++overruns_;
    stop_cause_ = StopCause::kOverrun;
    recorder_active = false;
    report_fault(FaultLevel::kWarning, FaultReason::kOverrun, kSource, "storage too slow: recording stopped");
    return;
  }
  current_sample_index = current_sample_index + 1;
}

// Packs this frame's steps and queues them whole, or not at all when the ring lacks room.
// The original format holds at most one step per track per frame (2 bits), ours a signed byte
// (±127); faster motion is spread over later frames by step_toward_input().
bool FourTrackRecorder::queue_sample() {
  const bool original = file_format_ == RecordingFormat::kOriginal;
  const size_t bytes = recording::bytes_per_frame(file_format_);
  if (kBufferBytes - ring_.size() < bytes) return false;
  const int32_t most = original ? recording::kMaxStepsPerFrameOriginal : recording::kMaxStepsPerFrameStepdance;
  int8_t steps[recording::kTracks];
  bool lagging = false;
  for (size_t track = 0; track < recording::kTracks; ++track) {
    steps[track] = static_cast<int8_t>(tracks[track].step_toward_input(most));
    lagging = lagging || (steps[track] == most || steps[track] == -most);
  }
  if (original) {
    ring_.push(recording::pack_original_frame(steps));
  } else {
    for (int8_t step : steps) ring_.push(static_cast<uint8_t>(step));
  }
  // A track at the format's limit may have been cut short (it catches up in later frames).
  if (lagging && most > 1) ++lagging_frames_;
  return true;
}

// Loop context: writes whole 512-byte chunks while recording (card-friendly), and everything left
// once the frame has stopped the recording.
void FourTrackRecorder::loop() {
  if (!file_open_) return;
  const Status status = recording::drain_ring_to_file(ring_, hal::storage(), handle_, false, bytes_written_);
  if (status != Status::kOk) {
    fail_storage("the card refused a write: recording stopped");
    return;
  }
  if (!recorder_active) finish();
}

// Flushes, closes, then writes the length file; the first error wins, but the file is always
// closed so what reached the card stays readable.
Status FourTrackRecorder::finish() {
  if (!file_open_) return Status::kNotStarted;
  FileStorage& storage = hal::storage();
  Status status = recording::drain_ring_to_file(ring_, storage, handle_, true, bytes_written_);
  const Status closed = storage.close(handle_);
  file_open_ = false;
  if (status == Status::kOk) status = closed;
  if (status == Status::kOk) status = write_length_file();
  if (stop_cause_ == StopCause::kOverrun) {
    hal::log_message("FourTrackRecorder: the card was too slow, the buffer overran; recording stopped");
  } else if (stop_cause_ == StopCause::kFull) {
    hal::log_message("FourTrackRecorder: the recording reached its planned length and stopped");
  }
  if (status != Status::kOk) {
    ++storage_errors_;
    hal::log_message("FourTrackRecorder: the card failed while finishing the recording");
    report_fault(FaultLevel::kWarning, FaultReason::kHardware, kSource, "storage failed while finishing");
  }
  return status;
}

// The frame count as ASCII digits and CRLF in <name>_len.bin, the original's companion file.
Status FourTrackRecorder::write_length_file() {
  FileStorage& storage = hal::storage();
  int handle = -1;
  Status status = storage.open(length_name_, FileMode::kWriteTruncate, handle);
  if (status != Status::kOk) return status;
  char text[recording::kLengthTextBytes];
  const size_t length = recording::format_length(current_sample_index, text);
  status = storage.write(handle, reinterpret_cast<const uint8_t*>(text), length);
  const Status closed = storage.close(handle);
  return status != Status::kOk ? status : closed;
}

// A storage error mid-recording: stop recording, keep what reached the card, report it.
void FourTrackRecorder::fail_storage(const char* what) {
  recorder_active = false;
  stop_cause_ = StopCause::kStorage;
  ++storage_errors_;
  hal::storage().close(handle_);
  file_open_ = false;
  hal::log_message("FourTrackRecorder: the card failed; recording stopped");
  report_fault(FaultLevel::kWarning, FaultReason::kHardware, kSource, what);
}

void FourTrackRecorder::report_counters(CounterSink& sink) const {
  sink.counter("overruns", overruns_);
  sink.counter("storage_errors", storage_errors_);
  sink.counter("bytes_written", bytes_written_);
  sink.counter("lagging_frames", lagging_frames_);
}

}  // namespace stepdance
