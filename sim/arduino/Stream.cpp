// Arduino's Stream on the host: the timed helpers wait through the backend's delay hook.
#include "Stream.h"

#include <string.h>

#include "arduino_backend.hpp"

namespace {
// Waiting for a byte lets board time pass in steps this long.
constexpr uint32_t kWaitStepUs = 1000;

bool is_digit(int c) { return c >= '0' && c <= '9'; }
}  // namespace

bool Stream::wait_for_byte() {
  // Counting the steps (not reading the clock) ends the wait even if a backend's clock stalls.
  const uint64_t timeout_us = static_cast<uint64_t>(timeout_ms_) * 1000u;
  for (uint64_t waited_us = 0;; waited_us += kWaitStepUs) {
    if (available() > 0) return true;
    if (waited_us >= timeout_us) return false;
    stepdance::arduino_backend::delay_us(kWaitStepUs);
  }
}

int Stream::timedRead() { return wait_for_byte() ? read() : -1; }

int Stream::timedPeek() { return wait_for_byte() ? peek() : -1; }

bool Stream::find(const char* target) {
  if (target == nullptr) return false;
  const size_t length = strlen(target);
  if (length == 0) return true;
  // Keeps the count of target characters matched so far; on a mismatch, restarts the match
  // at the longest suffix of what was read that is still a prefix of the target.
  size_t matched = 0;
  for (;;) {
    const int c = timedRead();
    if (c < 0) return false;
    while (true) {
      if (static_cast<char>(c) == target[matched]) {
        ++matched;
        break;
      }
      if (matched == 0) break;
      // Shorten the match: find the longest proper border of target[0..matched).
      size_t shorter = matched - 1;
      while (shorter > 0 && memcmp(target, target + matched - shorter, shorter) != 0) --shorter;
      matched = shorter;
    }
    if (matched == length) return true;
  }
}

bool Stream::find(char target) {
  const char text[2] = {target, '\0'};
  return find(text);
}

bool Stream::parse_integer_part(bool allow_point, bool& negative, long& value) {
  negative = false;
  value = 0;
  // Skip everything that cannot start a number.
  int c = timedPeek();
  while (c >= 0 && c != '-' && !is_digit(c) && !(allow_point && c == '.')) {
    read();
    c = timedPeek();
  }
  if (c < 0) return false;
  if (c == '-') {
    negative = true;
    read();
  }
  // Unsigned arithmetic: an absurdly long number wraps instead of overflowing.
  unsigned long magnitude = 0;
  for (c = timedPeek(); is_digit(c); c = timedPeek()) {
    magnitude = magnitude * 10u + static_cast<unsigned long>(c - '0');
    read();
  }
  value = static_cast<long>(magnitude);
  return true;
}

long Stream::parseInt() {
  bool negative = false;
  long value = 0;
  if (!parse_integer_part(false, negative, value)) return 0;
  return negative ? static_cast<long>(0ul - static_cast<unsigned long>(value)) : value;
}

float Stream::parseFloat() {
  bool negative = false;
  long whole = 0;
  if (!parse_integer_part(true, negative, whole)) return 0.0f;
  double value = static_cast<double>(whole);
  if (timedPeek() == '.') {
    read();
    double scale = 0.1;
    for (int c = timedPeek(); is_digit(c); c = timedPeek()) {
      value += (c - '0') * scale;
      scale /= 10;
      read();
    }
  }
  return static_cast<float>(negative ? -value : value);
}

size_t Stream::readBytes(char* buffer, size_t length) {
  size_t count = 0;
  while (count < length) {
    const int c = timedRead();
    if (c < 0) break;
    buffer[count++] = static_cast<char>(c);
  }
  return count;
}

size_t Stream::readBytesUntil(char terminator, char* buffer, size_t length) {
  size_t count = 0;
  while (count < length) {
    const int c = timedRead();
    if (c < 0 || static_cast<char>(c) == terminator) break;
    buffer[count++] = static_cast<char>(c);
  }
  return count;
}

String Stream::readString() {
  String text;
  for (int c = timedRead(); c >= 0; c = timedRead()) text.concat(static_cast<char>(c));
  return text;
}

String Stream::readStringUntil(char terminator) {
  String text;
  for (int c = timedRead(); c >= 0 && static_cast<char>(c) != terminator; c = timedRead()) {
    text.concat(static_cast<char>(c));
  }
  return text;
}
