// The reply ring of the host protocols.
#include "stepdance/interfaces/link/reply_ring.hpp"

#include <string.h>

namespace stepdance::link {

// One pass: the bytes go in as they are read and count only once the whole text fitted.
bool ReplyRingBase::send(const char* text) {
  const size_t room = space();
  size_t tail = head_ + count_;
  if (tail >= capacity_) tail -= capacity_;
  size_t length = 0;
  for (; text[length] != '\0'; ++length) {
    if (length == room) {
      ++dropped_;
      return false;
    }
    data_[tail] = text[length];
    if (++tail == capacity_) tail = 0;
  }
  count_ += length;
  return true;
}

// All or nothing: a reply that does not fit is dropped whole and counted, never sent cut short (a
// client would misparse half a line). Protocols reserve room before executing a command so this is
// the exception, not the flow control.
bool ReplyRingBase::send_line(const TextWriter& line, const char* ending) {
  const size_t ending_length = strlen(ending);
  if (line.size() + ending_length > space()) {
    ++dropped_;
    return false;
  }
  push(line.c_str(), line.size());
  push(ending, ending_length);
  return true;
}

// Replies are a few bytes: a byte loop that wraps costs less than two memcpy calls.
void ReplyRingBase::push(const char* bytes, size_t length) {
  size_t tail = head_ + count_;
  if (tail >= capacity_) tail -= capacity_;
  for (size_t i = 0; i < length; ++i) {
    data_[tail] = bytes[i];
    if (++tail == capacity_) tail = 0;
  }
  count_ += length;
}

// Loop context. Written in at most two contiguous pieces (the ring's wrap), non-blocking: a host that
// reads slowly leaves bytes in the ring, the loop never waits for USB.
size_t ReplyRingBase::flush(ByteStream& stream) {
  size_t total = 0;
  while (count_ > 0) {
    size_t chunk = capacity_ - head_;  // contiguous bytes from head_
    if (chunk > count_) chunk = count_;
    // write_bytes() never blocks: it takes what fits, and the rest waits for the next flush.
    const size_t written = stream.write_bytes(reinterpret_cast<const uint8_t*>(data_ + head_), chunk);
    head_ += written;
    if (head_ == capacity_) head_ = 0;  // a chunk never runs past the end of the storage
    count_ -= written;
    total += written;
    if (written < chunk) break;
  }
  return total;
}

}  // namespace stepdance::link
