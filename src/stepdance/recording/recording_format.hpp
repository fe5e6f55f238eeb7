// The two recording file formats: the original library's (1 byte per frame) and ours (versioned).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance::recording {

/// Tracks in a recording (the recorder's input_1..4, the player's output_1..4).
constexpr size_t kTracks = 4;

/// Which file format a recorder writes (a player recognises both by their first bytes).
enum class RecordingFormat : uint8_t {
  /// The original library's: `<name>.bin` holds one byte per 40 µs frame, 2 bits per track
  /// (track 1 in bits 0–1 … track 4 in bits 6–7; per track bit 1 = a step was taken, bit 0 =
  /// forward), so at most one step per frame per track; `<name>_len.bin` holds the frame count
  /// in ASCII decimal followed by CR LF. No header: the resolution is not stored.
  kOriginal = 0,
  /// Ours, version 1: a 64-byte header (see RecordingHeader) then 4 bytes per frame, one signed
  /// step count per track (−127…127 steps per frame; −128 is never written). `<name>_len.bin`
  /// is written as for kOriginal (64-bit count).
  kStepdance = 1,
};

/// Most steps one frame of a track can hold in each format.
constexpr int32_t kMaxStepsPerFrameOriginal = 1;
constexpr int32_t kMaxStepsPerFrameStepdance = 127;

/// Bytes each frame takes in the data part of a file.
constexpr size_t bytes_per_frame(RecordingFormat format) { return format == RecordingFormat::kOriginal ? 1 : kTracks; }

/// Frames in `minutes` of recording at `frames_per_s` (25 kHz: 40 µs frames), in 64 bits (the
/// original overflowed past 35 min).
constexpr uint64_t frames_for_minutes(uint32_t minutes, uint32_t frames_per_s = 25000u) {
  return uint64_t{minutes} * 60u * frames_per_s;
}
/// The only frame period the original format can mean (it stores none).
constexpr uint32_t kOriginalFramePeriodUs = 40;

// ---- The original format ----------------------------------------------------------------------

/// Packs one frame's steps (each −1, 0 or +1; anything else counts by its sign) into a byte.
/// Context: any (pure).
uint8_t pack_original_frame(const int8_t (&steps)[kTracks]);
/// Unpacks a byte into steps (−1, 0, +1); the unused code 01 reads as no step. Context: any (pure).
void unpack_original_frame(uint8_t byte, int8_t (&steps)[kTracks]);

// ---- Our format -------------------------------------------------------------------------------

/// The 64-byte header of a kStepdance file, all fields little-endian:
///   0  8 bytes  magic "SDRECORD"
///   8  u16      format version (1)
///  10  u16      header length in bytes (64; a later version may grow it, data starts there)
///  12  u32      frame period in nanoseconds (40 000, or 10 000 / 20 000 / 25 000)
///  16  u8       tracks (4)
///  17  u8       bytes per track per frame (1: a signed step count)
///  18  6 bytes  zero
///  24  4 × f64  resolution of each track, world units per recorded step (IEEE 754 binary64)
///  56  8 bytes  zero
struct RecordingHeader {
  uint16_t version = 1;
  uint16_t header_bytes = 64;
  uint32_t frame_period_ns = 40000;
  double resolution[kTracks] = {0.01, 0.01, 0.01, 0.01};
};
constexpr size_t kHeaderBytes = 64;
constexpr uint16_t kFormatVersion = 1;

/// How a file's first bytes read.
enum class HeaderCheck : uint8_t {
  kOk,           ///< a header this code can play
  kNotOurs,      ///< no magic: an original-format file
  kUnsupported,  ///< our magic, but a version, track layout or frame period (not 10, 20, 25, 40 µs) we cannot play
  kTruncated,    ///< our magic, but shorter than the header
};

/// Writes `header` into 64 bytes. Context: any (pure).
void write_header(const RecordingHeader& header, uint8_t (&out)[kHeaderBytes]);
/// Reads a header from the first `length` bytes of a file. Context: any (pure).
HeaderCheck read_header(const uint8_t* data, size_t length, RecordingHeader& out);

// ---- The length file --------------------------------------------------------------------------

/// Longest text format_length() writes: 20 digits + CR LF + NUL.
constexpr size_t kLengthTextBytes = 23;
/// Writes `frames` in ASCII decimal + CR LF; returns the length (without the NUL). Context: any.
size_t format_length(uint64_t frames, char (&out)[kLengthTextBytes]);
/// Reads a frame count: decimal digits, optionally followed by whitespace (CR LF). False for no
/// digits, another character, or a value beyond 64 bits. Context: any (pure).
bool parse_length(const char* text, size_t length, uint64_t& frames);

}  // namespace stepdance::recording
