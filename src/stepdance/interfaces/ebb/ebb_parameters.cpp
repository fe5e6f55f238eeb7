// EbbParameters: comma rule, integer fields with ranges, text fields.
#include "stepdance/interfaces/ebb/ebb_parameters.hpp"

namespace stepdance::ebb {

// EBB framing (ebb-protocol.md): parameters follow the command after commas, no spaces; the first
// error is kept and every later read fails, so the reply names the first problem.
bool EbbParameters::open_parameter(bool required) {
  if (error_ != EbbError::kNone) return false;
  if (position_ >= length_) {
    if (required) error_ = EbbError::kMissing;
    return false;
  }
  if (text_[position_] != ',') {
    error_ = EbbError::kNeedComma;
    offending_ = text_[position_];
    return false;
  }
  ++position_;
  return true;
}

// Values are read in 64 bits and saturate far beyond any range, so an overlong number is "invalid"
// (!6) and never wraps into range. An empty optional field (",,") counts as absent.
bool EbbParameters::integer(int64_t min, int64_t max, bool required, int64_t& out) {
  if (!open_parameter(required)) return false;
  bool negative = false;
  if (position_ < length_ && (text_[position_] == '-' || text_[position_] == '+')) {
    negative = text_[position_] == '-';
    ++position_;
  }
  int64_t value = 0;
  size_t digits = 0;
  while (position_ < length_ && text_[position_] >= '0' && text_[position_] <= '9') {
    if (value < (int64_t{1} << 40)) value = value * 10 + (text_[position_] - '0');  // saturates far out of range
    ++digits;
    ++position_;
  }
  if (digits == 0) {
    // An empty field (",,") is missing when required; anything else is not a number.
    const bool empty = position_ >= length_ || text_[position_] == ',';
    error_ = empty && required ? EbbError::kMissing : EbbError::kInvalid;
    if (empty && !required) {
      error_ = EbbError::kNone;
      return false;
    }
    return false;
  }
  if (position_ < length_ && text_[position_] != ',') {
    error_ = EbbError::kNeedComma;
    offending_ = text_[position_];
    return false;
  }
  if (negative) value = -value;
  if (value < min || value > max) {
    error_ = EbbError::kInvalid;
    return false;
  }
  out = value;
  return true;
}

bool EbbParameters::letter(bool required, char& out) {
  if (!open_parameter(required)) return false;
  if (position_ >= length_ || text_[position_] == ',') {
    if (required) error_ = EbbError::kMissing;
    return false;
  }
  const char c = text_[position_++];
  if (position_ < length_ && text_[position_] != ',') {
    error_ = EbbError::kNeedComma;
    offending_ = text_[position_];
    return false;
  }
  out = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  return true;
}

// Text beyond the capacity is dropped, not an error: ST keeps the tag's first bytes.
bool EbbParameters::text(char* out, size_t capacity, bool required) {
  if (!open_parameter(required)) return false;
  size_t written = 0;
  while (position_ < length_ && text_[position_] != ',') {
    if (written + 1 < capacity) out[written++] = text_[position_];
    ++position_;
  }
  out[written] = '\0';
  return true;
}

// Anything left after the last expected parameter is "!7 Err: Extra parameter".
bool EbbParameters::finish() {
  if (error_ == EbbError::kNone && position_ < length_) error_ = EbbError::kExtra;
  return error_ == EbbError::kNone;
}

}  // namespace stepdance::ebb
