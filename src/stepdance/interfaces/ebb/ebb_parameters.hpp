// Reading an EBB command's comma-separated parameters, with the EBB's error numbers.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance::ebb {

/// The EBB's parse errors (`!N Err: …`).
enum class EbbError : uint8_t {
  kNone = 0,
  kRateTooHigh = 1,     ///< reported as "!0 Err: <axisN> step rate too high"
  kMissing = 4,         ///< "!4 Err: Missing parameter(s)"
  kNeedComma = 5,       ///< "!5 Err: Need comma next, found: 'X'"
  kInvalid = 6,         ///< "!6 Err: Invalid parameter value"
  kExtra = 7,           ///< "!7 Err: Extra parameter"
  kUnknownCommand = 8,  ///< "!8 Err: Unknown command 'XX:hhhh'"
  kOverrun = 3,         ///< "!3 Err: RX Buffer overrun"
  kAlarm = 9,           ///< ours: "!9 Err: Alarm raised: motor moves refused until it is cleared"
};

/// Walks the parameters after a command name: each is ",value". The first problem sticks: once
/// error() is set every further read fails, so handlers read all parameters and then check once.
/// Context: loop (pure).
class EbbParameters {
 public:
  /// `text` is what follows the command name (e.g. ",1000,250,-766"), without the line ending.
  EbbParameters(const char* text, size_t length) : text_(text), length_(length) {}

  /// Reads an integer in [min, max]. Absent and required: kMissing; absent and optional: false
  /// with no error (out untouched). Not a number or out of range: kInvalid.
  bool integer(int64_t min, int64_t max, bool required, int64_t& out);
  /// Reads a one-character parameter (PD/PI/PO's port), upper-cased. Absent: as integer(); more
  /// than one character: kNeedComma at the second, as the EBB reads it.
  bool letter(bool required, char& out);
  /// Reads the rest of a parameter as text (ST's name), at most capacity − 1 bytes.
  bool text(char* out, size_t capacity, bool required);
  /// True if another parameter follows.
  bool more() const { return position_ < length_; }
  /// Sets kExtra if anything is left unread; returns true when everything is fine.
  bool finish();

  EbbError error() const { return error_; }
  /// The character that broke the comma rule (kNeedComma).
  char offending() const { return offending_; }

 private:
  bool open_parameter(bool required);

  const char* text_;
  size_t length_;
  size_t position_ = 0;
  EbbError error_ = EbbError::kNone;
  char offending_ = 0;
};

}  // namespace stepdance::ebb
