// FourTrackRecorder: records four positions, step by step, to a file on the board's storage.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/recording/recorder_track.hpp"
#include "stepdance/recording/recording_format.hpp"
#include "stepdance/recording/storage_pump.hpp"

namespace stepdance {

using recording::RecordingFormat;
/// Sketch-style names of the two formats (set_file_format).
constexpr RecordingFormat RECORDING_FORMAT_ORIGINAL = RecordingFormat::kOriginal;
constexpr RecordingFormat RECORDING_FORMAT_STEPDANCE = RecordingFormat::kStepdance;

/// Records what reaches input_1..input_4 (map them to the ports to record, e.g. a kinematics
/// block's inputs: the recorder pulls their changes) as whole steps of `resolution` world units,
/// once per frame in the post-channel stage, to `<name>.bin` and `<name>_len.bin` (see
/// recording_format.hpp for both formats; the original's is the default).
///
/// Frame safety: the frame only packs each frame's steps into a RAM ring of kBufferBytes; the
/// loop (dance_loop) writes the ring to storage in 512-byte chunks. If storage falls so far
/// behind that the ring is full, the recording stops cleanly (everything recorded so far is
/// kept and the length file written), the overrun is counted and reported as a warning
/// (FaultReason::kOverrun), and motion goes on. kBufferBytes holds 655 ms of the original
/// format (25 kB/s) or 164 ms of ours (100 kB/s): the card must sustain that rate with no
/// stall longer than that.
///
/// Differences from the original: sizes in 64 bits (it overflowed past 35 minutes), names of
/// any length the storage accepts (it overflowed 30-byte buffers), errors on the board's console
/// and the fault path (it used a hardware UART), recording never inside the frame.
class FourTrackRecorder : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "FourTrackRecorder"; }
  FourTrackRecorder();

  /// RAM between the frame and the card.
  static constexpr size_t kBufferBytes = 16384;

  /// Begins the inputs and registers the block in the post-channel and loop stages.
  /// kFull if a registry is full. Context: loop.
  Status begin();
  /// Starts recording into `<name>.bin` (created or emptied) for at most `minutes`; while
  /// already recording it only resumes. kBadArgument if the name is empty or too long for the
  /// storage with "_len.bin" appended, kUnsupported on a board without a card slot (a Teensy
  /// 4.0), kIoError if the file cannot be created (all reported on the console). Context: loop.
  Status start(const char* name, uint32_t minutes = 30);
  /// Stops adding samples (the inputs' moves meanwhile are not recorded). Context: loop.
  void pause() { paused_ = true; }
  /// Adds samples again, from the inputs' present position. Context: loop.
  void resume() { paused_ = false; }
  /// Ends the recording: writes what is buffered, closes the file and writes `<name>_len.bin`.
  /// kNotStarted if nothing is being recorded; the first storage error otherwise. Context: loop.
  Status stop();
  /// Every track records one step per `world_units / per_steps` world units (default 0.01).
  /// Takes effect for recordings started later. Context: loop.
  void set_resolution(double world_units, double per_steps = 1.0);
  /// Chooses the file format of recordings started later (default RECORDING_FORMAT_ORIGINAL).
  /// Context: loop.
  void set_file_format(RecordingFormat format) { format_ = format; }

  /// Frame: follow the inputs and queue one sample. Context: frame ISR.
  void run() override;
  /// Writes queued samples to storage; finishes a recording the frame stopped. Context: loop.
  void loop() override;
  /// overruns, storage_errors, bytes_written, lagging_frames (a track needed more steps than a
  /// frame of the format holds). Context: loop.
  void report_counters(CounterSink& sink) const override;

  /// Overruns (recordings stopped because the ring was full) since begin. Context: any.
  uint32_t overruns() const { return overruns_; }
  /// Bytes written to storage by the current or last recording (header included). Context: loop.
  uint64_t bytes_written() const { return bytes_written_; }

  RecorderTrack tracks[recording::kTracks];
  BlockPort& input_1 = tracks[0].input_target_position;
  BlockPort& input_2 = tracks[1].input_target_position;
  BlockPort& input_3 = tracks[2].input_target_position;
  BlockPort& input_4 = tracks[3].input_target_position;

  /// Samples (frames) recorded so far in the current or last recording. Context: read in the
  /// loop (the frame writes it).
  volatile uint64_t current_sample_index = 0;
  /// Most samples the current recording may take (minutes × 60 × frames per second).
  uint64_t max_num_samples = 0;
  /// True from start() until the recording stops (a pause keeps it true).
  volatile bool recorder_active = false;

 private:
  enum class StopCause : uint8_t { kNone, kUser, kOverrun, kFull, kStorage };

  bool queue_sample();
  Status finish();
  Status write_length_file();
  void fail_storage(const char* what);

  recording::ByteRing<kBufferBytes> ring_;
  recording::FileName data_name_ = {};
  recording::FileName length_name_ = {};
  RecordingFormat format_ = RecordingFormat::kOriginal;
  RecordingFormat file_format_ = RecordingFormat::kOriginal;  // of the open file
  int handle_ = -1;                                           // loop only
  bool file_open_ = false;                                    // loop only
  volatile bool paused_ = false;
  volatile StopCause stop_cause_ = StopCause::kNone;  // written by whoever stopped recording
  uint64_t bytes_written_ = 0;
  uint32_t overruns_ = 0;
  uint32_t storage_errors_ = 0;
  uint32_t lagging_frames_ = 0;
};

}  // namespace stepdance
