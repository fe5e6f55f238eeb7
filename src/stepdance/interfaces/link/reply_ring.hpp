// Replies of a host protocol waiting for the host to read them.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/text_writer.hpp"

namespace stepdance::link {

/// A ring of reply bytes in caller-sized storage (see ReplyRing<N>), flushed to the stream as
/// fast as the host reads. A protocol checks reserve() for its largest reply before it takes a
/// line, so a reply always fits: text is queued whole or not at all (never a torn line), and a
/// refusal is counted in dropped(), which stays 0 when the protocol keeps that rule.
/// Context: loop.
class ReplyRingBase {
 public:
  ReplyRingBase(const ReplyRingBase&) = delete;
  ReplyRingBase& operator=(const ReplyRingBase&) = delete;

  /// True when `bytes` more fit now.
  bool reserve(size_t bytes) const { return space() >= bytes; }
  /// Queues `text` whole; false (and counted) when it does not fit.
  bool send(const char* text);
  /// Queues the line followed by `ending` (CR LF unless told), whole; false (counted) otherwise.
  bool send_line(const TextWriter& line, const char* ending = "\r\n");
  /// Hands queued bytes to the stream while it takes them; returns the bytes written.
  size_t flush(ByteStream& stream);
  /// Bytes free, and bytes waiting.
  size_t space() const { return capacity_ - count_; }
  size_t pending() const { return count_; }
  /// Texts refused for lack of room since the start.
  uint32_t dropped() const { return dropped_; }
  /// Capacity, bytes.
  size_t capacity() const { return capacity_; }

 protected:
  ReplyRingBase(char* storage, size_t capacity) : data_(storage), capacity_(capacity) {}
  ~ReplyRingBase() = default;

 private:
  void push(const char* bytes, size_t length);

  char* data_;
  size_t capacity_;
  size_t head_ = 0;
  size_t count_ = 0;
  uint32_t dropped_ = 0;
};

/// A ReplyRingBase holding N bytes.
template <size_t N>
class ReplyRing final : public ReplyRingBase {
 public:
  ReplyRing() : ReplyRingBase(storage_, N) {}

 private:
  char storage_[N] = {};
};

}  // namespace stepdance::link
