// A host link for protocol tests: bytes the host sent wait in `to_board`, what the board wrote
// lands in `from_board`; `write_room` limits what the board may write (a slow host).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <string>

#include "stepdance/core/byte_stream.hpp"

namespace stepdance::test_support {

struct FakeByteStream final : ByteStream {
  std::deque<uint8_t> to_board;
  std::string from_board;
  size_t write_room = 1 << 20;

  size_t bytes_available() override { return to_board.size(); }
  int read_byte() override {
    if (to_board.empty()) return -1;
    const uint8_t byte = to_board.front();
    to_board.pop_front();
    return byte;
  }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    const size_t n = length < write_room ? length : write_room;
    from_board.append(reinterpret_cast<const char*>(data), n);
    write_room -= n;
    return n;
  }
  size_t write_space() override { return write_room; }

  /// Queues text as the host would send it.
  void send(const std::string& text) { to_board.insert(to_board.end(), text.begin(), text.end()); }
  /// Everything the board wrote since the last take().
  std::string take() {
    std::string out;
    out.swap(from_board);
    return out;
  }
};

}  // namespace stepdance::test_support
