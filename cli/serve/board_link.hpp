// The board side of `stepdance serve`: a real serial device or a simulated board.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace stepdance::cli::serve {

/// Splits a byte stream into lines (LF-terminated; a CR before it dropped). A line longer than
/// max_bytes is cut there and its rest discarded up to the next LF, counted in overlong().
class LineSplitter {
 public:
  explicit LineSplitter(size_t max_bytes) : max_bytes_(max_bytes) {}
  /// Calls `line` with every line completed by `bytes`.
  void feed(std::string_view bytes, const std::function<void(std::string_view)>& line);
  uint64_t overlong() const { return overlong_; }

 private:
  size_t max_bytes_;
  std::string partial_;
  bool discarding_ = false;
  uint64_t overlong_ = 0;
};

/// A board the bridge talks to: bytes out, lines in. Context: the server's event loop.
class BoardLink {
 public:
  using LineHandler = std::function<void(std::string_view line)>;
  virtual ~BoardLink() = default;
  /// Called with every line the board sends (without its line ending).
  void on_line(LineHandler handler) { on_line_ = std::move(handler); }
  /// Queues bytes for the board; never blocks.
  virtual void send(const std::string& bytes) = 0;
  /// A one-line description for the start-up message, e.g. "serial /dev/ttyACM0".
  virtual std::string describe() const = 0;

 protected:
  LineHandler on_line_;
};

}  // namespace stepdance::cli::serve
