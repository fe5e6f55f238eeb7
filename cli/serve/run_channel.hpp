// The runner's end of its socket to the sketch server: JSON messages, one a line, both ways.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace stepdance::cli::serve {

/// Context: the runner's main thread only.
class RunChannel {
 public:
  /// Takes `fd` (closed on exec, so the compiler does not hold it).
  explicit RunChannel(int fd);
  /// Sends one message (a line without a newline in it); blocks while the server is behind.
  /// False once the server is gone.
  bool send(std::string_view message);
  /// Waits up to `timeout_ms` for messages and hands each to `received`; false once the server
  /// closed its end (the run must stop).
  bool receive(int timeout_ms, const std::function<void(std::string_view)>& received);

 private:
  int fd_;
  std::string pending_;
  bool open_ = true;
};

}  // namespace stepdance::cli::serve
