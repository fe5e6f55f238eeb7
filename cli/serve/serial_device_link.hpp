// A real board on a serial device (/dev/ttyACM0 …), read and written without blocking.
#pragma once

#include <array>
#include <deque>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>

#include "board_link.hpp"

namespace stepdance::cli::serve {

/// Opens `path` raw at `baud` (8N1, no flow control; USB CDC ignores the rate). Bytes to send
/// wait in a queue of at most kMaxQueuedBytes; beyond that send() drops them and counts them.
/// Throws std::runtime_error when the device cannot be opened. Context: the event loop.
class SerialDeviceLink : public BoardLink {
 public:
  static constexpr size_t kMaxQueuedBytes = 1 << 16;
  static constexpr size_t kMaxLineBytes = 1 << 16;

  SerialDeviceLink(boost::asio::io_context& io, const std::string& path, unsigned baud);
  void send(const std::string& bytes) override;
  std::string describe() const override { return "serial " + path_; }

 private:
  void read_more();
  void write_more();

  boost::asio::serial_port port_;
  std::string path_;
  std::array<char, 4096> read_buffer_{};
  LineSplitter lines_{kMaxLineBytes};
  std::deque<std::string> outgoing_;
  size_t queued_bytes_ = 0;
  bool writing_ = false;
  uint64_t dropped_bytes_ = 0;
};

}  // namespace stepdance::cli::serve
