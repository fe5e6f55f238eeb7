// The reply ring of the host protocols.
#include "stepdance/interfaces/link/reply_ring.hpp"

#include <string.h>

namespace stepdance::link {

bool ReplyRingBase::send(const char* text) { return append(text, strlen(text)); }

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

bool ReplyRingBase::append(const char* bytes, size_t length) {
  if (length > space()) {
    ++dropped_;
    return false;
  }
  push(bytes, length);
  return true;
}

void ReplyRingBase::push(const char* bytes, size_t length) {
  for (size_t i = 0; i < length; ++i) data_[(head_ + count_ + i) % capacity_] = bytes[i];
  count_ += length;
}

size_t ReplyRingBase::flush(ByteStream& stream) {
  size_t total = 0;
  while (count_ > 0) {
    const size_t room = stream.write_space();
    size_t chunk = capacity_ - head_;  // contiguous bytes from head_
    if (chunk > count_) chunk = count_;
    if (chunk > room) chunk = room;
    if (chunk == 0) break;
    const size_t written = stream.write_bytes(reinterpret_cast<const uint8_t*>(data_ + head_), chunk);
    if (written == 0) break;
    head_ = (head_ + written) % capacity_;
    count_ -= written;
    total += written;
  }
  return total;
}

}  // namespace stepdance::link
