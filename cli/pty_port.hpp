// A pseudo-terminal standing in for a board's USB serial port in the live simulator.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <string>
#include <vector>

namespace stepdance::cli {

/// A pty pair in raw mode (no echo, no CR/LF translation, all 256 byte values pass). Host
/// programs open path() as a serial port; the simulator reads and writes the master side.
///
/// The port keeps a descriptor of its own on the terminal side, so a client may close and reopen
/// it at any time without the master seeing a hang-up. Bytes the board writes while nobody reads
/// fill the terminal's own buffer, then wait in ours of kMaxPendingBytes; beyond that the oldest
/// are dropped and counted (a reader that comes back gets the newest). Bytes the client writes
/// are read only as far as the caller has room, so a client that writes faster than the board
/// reads is held back by the terminal (its writes block or return EAGAIN). Baud-rate and other
/// settings a client makes are accepted (a pty moves bytes, not bits).
/// Context: the live run's thread only.
class PtyPort {
 public:
  static constexpr size_t kMaxPendingBytes = 64 * 1024;

  /// Opens the pair; throws std::runtime_error with the reason on failure.
  PtyPort();
  ~PtyPort();
  PtyPort(const PtyPort&) = delete;
  PtyPort& operator=(const PtyPort&) = delete;

  /// The terminal's path, e.g. /dev/pts/7.
  const std::string& path() const { return path_; }
  /// Also reachable as `link` (a symlink, replaced if one exists; removed on destruction).
  /// Throws std::runtime_error when it cannot be made.
  void link_as(const std::string& link);

  /// Appends to `out` what the client has written since the last call, at most `max_bytes`.
  void read_from_client(std::string& out, size_t max_bytes);
  /// Queues bytes for the client and sends what the terminal accepts now.
  void write_to_client(const uint8_t* data, size_t length);
  /// Sends queued bytes the terminal can take now.
  void flush();
  /// Bytes dropped because the client did not read (see kMaxPendingBytes).
  uint64_t dropped_bytes() const { return dropped_; }
  /// Bytes written for the client that it has not read yet (in the terminal's read queue, on
  /// their way there in the kernel, or still queued here): every byte written so far counts at
  /// once, so a wait on this never sees 0 while the client has not yet seen a reply. May first
  /// wait for the kernel to move bytes still on their way (a moment; on a loaded machine, until
  /// its worker thread runs).
  size_t unread_by_client() const;

 private:
  int master_ = -1;
  int keeper_ = -1;  // our own descriptor on the terminal side (see the class comment)
  std::string path_;
  std::string link_;
  /// Bytes waiting for the client: a ring of kMaxPendingBytes, oldest at head_.
  std::vector<uint8_t> pending_ = std::vector<uint8_t>(kMaxPendingBytes);
  size_t head_ = 0;
  size_t size_ = 0;
  uint64_t dropped_ = 0;
};

}  // namespace stepdance::cli
