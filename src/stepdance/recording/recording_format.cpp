// The recording file formats: packing frames, our header, and the ASCII length file.
#include "stepdance/recording/recording_format.hpp"

#include <string.h>

#include "stepdance/core/frame_period.hpp"

namespace stepdance::recording {
namespace {

constexpr uint8_t kMagic[8] = {'S', 'D', 'R', 'E', 'C', 'O', 'R', 'D'};
constexpr uint8_t kCodeForward = 0b11;
constexpr uint8_t kCodeReverse = 0b10;
constexpr uint8_t kStepBit = 0b10;
constexpr uint8_t kForwardBit = 0b01;

// The header is little-endian by definition, written byte by byte so the file is the same on any
// host (the simulator) and on the Teensy.
void put_le(uint8_t* out, uint64_t value, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) out[i] = static_cast<uint8_t>(value >> (8 * i));
}

uint64_t get_le(const uint8_t* in, size_t bytes) {
  uint64_t value = 0;
  for (size_t i = 0; i < bytes; ++i) value |= uint64_t{in[i]} << (8 * i);
  return value;
}

}  // namespace

// The original format (original-library.md §4.12): one byte per frame, 2 bits per track from bit 0,
// 11 = forward step, 10 = reverse step, 00 = none. Track 1 is the lowest pair.
uint8_t pack_original_frame(const int8_t (&steps)[kTracks]) {
  uint8_t byte = 0;
  for (size_t track = 0; track < kTracks; ++track) {
    const uint8_t code = steps[track] > 0 ? kCodeForward : steps[track] < 0 ? kCodeReverse : 0;
    byte = static_cast<uint8_t>(byte | (code << (2 * track)));
  }
  return byte;
}

// Code 01 (never written) has no step bit and reads as no step.
void unpack_original_frame(uint8_t byte, int8_t (&steps)[kTracks]) {
  for (size_t track = 0; track < kTracks; ++track) {
    const uint8_t code = static_cast<uint8_t>((byte >> (2 * track)) & 0b11);
    steps[track] = (code & kStepBit) == 0 ? 0 : (code & kForwardBit) != 0 ? 1 : -1;
  }
}

// Our 64-byte header: "SDRECORD", version u16 @8, header size u16 @10, frame period ns u32 @12,
// track count @16, bytes per track per frame @17 (1: a signed step count), then the tracks'
// resolutions as IEEE-754 doubles @24. Unused bytes are zero for later versions to use.
void write_header(const RecordingHeader& header, uint8_t (&out)[kHeaderBytes]) {
  memset(out, 0, sizeof(out));
  memcpy(out, kMagic, sizeof(kMagic));
  put_le(out + 8, header.version, 2);
  put_le(out + 10, kHeaderBytes, 2);
  put_le(out + 12, header.frame_period_ns, 4);
  out[16] = kTracks;
  out[17] = 1;
  for (size_t track = 0; track < kTracks; ++track) {
    uint64_t bits = 0;
    memcpy(&bits, &header.resolution[track], sizeof(bits));
    put_le(out + 24 + 8 * track, bits, 8);
  }
}

// Everything this version cannot play exactly is kUnsupported (never guessed): another version or
// layout, a period that is not a whole number of µs the engine supports, a resolution ≤ 0 or NaN.
HeaderCheck read_header(const uint8_t* data, size_t length, RecordingHeader& out) {
  if (length < sizeof(kMagic) || memcmp(data, kMagic, sizeof(kMagic)) != 0) return HeaderCheck::kNotOurs;
  if (length < kHeaderBytes) return HeaderCheck::kTruncated;
  RecordingHeader header;
  header.version = static_cast<uint16_t>(get_le(data + 8, 2));
  header.header_bytes = static_cast<uint16_t>(get_le(data + 10, 2));
  header.frame_period_ns = static_cast<uint32_t>(get_le(data + 12, 4));
  if (header.version != kFormatVersion || header.header_bytes != kHeaderBytes || data[16] != kTracks || data[17] != 1 ||
      header.frame_period_ns % 1000u != 0 || !frame_period_supported(header.frame_period_ns / 1000u)) {
    return HeaderCheck::kUnsupported;
  }
  for (size_t track = 0; track < kTracks; ++track) {
    const uint64_t bits = get_le(data + 24 + 8 * track, 8);
    memcpy(&header.resolution[track], &bits, sizeof(bits));
    if (!(header.resolution[track] > 0.0)) return HeaderCheck::kUnsupported;  // also rejects NaN
  }
  out = header;
  return HeaderCheck::kOk;
}

// Decimal without printf (not on the real-time build) and 64 bits wide: 20 digits + CRLF + NUL.
size_t format_length(uint64_t frames, char (&out)[kLengthTextBytes]) {
  char digits[20];
  size_t count = 0;
  do {
    digits[count++] = static_cast<char>('0' + frames % 10);
    frames /= 10;
  } while (frames > 0);
  size_t length = 0;
  while (count > 0) out[length++] = digits[--count];
  out[length++] = '\r';
  out[length++] = '\n';
  out[length] = '\0';
  return length;
}

// Accepts digits followed only by white space (the original wrote CRLF); overflow and stray
// characters fail, so a corrupt length file falls back to playing the whole data file.
bool parse_length(const char* text, size_t length, uint64_t& frames) {
  uint64_t value = 0;
  size_t i = 0;
  for (; i < length && text[i] >= '0' && text[i] <= '9'; ++i) {
    const uint64_t digit = static_cast<uint64_t>(text[i] - '0');
    if (value > (UINT64_MAX - digit) / 10) return false;
    value = value * 10 + digit;
  }
  if (i == 0) return false;
  for (; i < length; ++i) {
    if (text[i] != '\r' && text[i] != '\n' && text[i] != ' ' && text[i] != '\t') return false;
  }
  frames = value;
  return true;
}

}  // namespace stepdance::recording
