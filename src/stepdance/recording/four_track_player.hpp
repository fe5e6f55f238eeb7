// FourTrackPlayer: plays a recording back into four ports, frame by frame.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/recording/recording_format.hpp"
#include "stepdance/recording/storage_pump.hpp"

namespace stepdance {

/// Plays `<name>.bin` (either format, told apart by its first bytes) into output_1..output_4:
/// each frame, in the input-port stage, one recorded frame's steps are pushed as changes of
/// steps × resolution world units. Original-format files carry no resolution: the player's
/// set_resolution() (default 0.01) applies; files in our format carry their own, which wins.
/// `<name>_len.bin` gives the number of frames; without it the player plays to the end of the
/// file.
///
/// Frame safety: the loop reads the file into a RAM ring of kBufferBytes, the frame only takes
/// bytes from it. When the ring runs dry before the end (the card is too slow), the frame
/// waits — no step is lost, playback resumes where it stopped — and the underrun is counted and
/// reported as a warning (FaultReason::kOverrun) once per dry spell.
class FourTrackPlayer : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "FourTrackPlayer"; }
  FourTrackPlayer();

  /// RAM between the card and the frame.
  static constexpr size_t kBufferBytes = 16384;

  /// Begins the outputs and registers the block in the input-port and loop stages.
  /// kFull if a registry is full. Context: loop.
  Status begin();
  /// Starts playing `<name>.bin` from its beginning (a playback under way is stopped first).
  /// kBadArgument for an empty or too long name, kIoError if the file cannot be read,
  /// kUnsupported for a file of our format this version cannot play or a board without a card
  /// slot (a Teensy 4.0) (all reported on the console). Context: loop.
  Status start(const char* name = "recording");
  /// Holds playback where it is. Context: loop.
  void pause() { paused_ = true; }
  /// Continues a paused playback. Context: loop.
  void resume() { paused_ = false; }
  /// Ends playback and closes the file. Context: loop.
  void stop();
  /// World units per recorded step of original-format files: `world_units` per `per_steps`.
  /// Context: loop (for playbacks started later).
  void set_resolution(double world_units, double per_steps = 1.0);

  /// Frame: push one recorded frame's steps. Context: frame ISR.
  void run() override;
  /// Keeps the ring filled from storage; closes a finished file. Context: loop.
  void loop() override;
  /// underruns, storage_errors, bytes_read. Context: loop.
  void report_counters(CounterSink& sink) const override;

  /// Frames in which the ring had run dry, since begin. Context: any.
  uint32_t underruns() const { return underruns_; }
  /// The format of the file playing (or last played). Context: loop.
  recording::RecordingFormat file_format() const { return file_format_; }

  BlockPort output_BlockPorts[recording::kTracks];
  BlockPort& output_1 = output_BlockPorts[0];
  BlockPort& output_2 = output_BlockPorts[1];
  BlockPort& output_3 = output_BlockPorts[2];
  BlockPort& output_4 = output_BlockPorts[3];

  /// Frames played so far. Context: read in the loop (the frame writes it).
  volatile uint64_t current_sample_index = 0;
  /// Frames in the recording (from the length file; UINT64_MAX when it is missing).
  uint64_t max_num_playback_samples = 0;
  /// True from start() until the recording ends or stop() (a pause keeps it true).
  volatile bool playback_active = false;

 private:
  Status open_files(const char* name);
  Status read_length_file(const char* name);
  Status take_header(const uint8_t* data, size_t length, size_t& data_start);
  bool play_frame();
  void fail(const char* message, Status status);

  recording::ByteRing<kBufferBytes> ring_;
  DecimalPosition positions_[recording::kTracks] = {};  // steps played per track
  double resolution_ = 0.01;                            // world units per step, original files
  recording::RecordingFormat file_format_ = recording::RecordingFormat::kOriginal;
  int handle_ = -1;                    // loop only
  bool file_open_ = false;             // loop only
  volatile bool end_of_file_ = false;  // loop: everything in the file is in the ring
  volatile bool paused_ = false;
  bool in_underrun_ = false;  // frame only
  uint64_t bytes_read_ = 0;
  uint32_t underruns_ = 0;
  uint32_t storage_errors_ = 0;
};

}  // namespace stepdance
