// The sketch server's side of a run's child process: started in a process group of its own,
// ended with everything it started.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace stepdance::cli::serve {

/// A `stepdance run-sketch` child. Context: the server's event loop.
class RunChild {
 public:
  /// Starts this program (/proc/self/exe) with `arguments` (after argv[0]) in a new process
  /// group, its stdout and stderr appended to `log_path` ("": this process's own), file descriptor 3 a socket whose
  /// other end channel_fd() is. Throws std::runtime_error when it cannot.
  RunChild(const std::vector<std::string>& arguments, const std::string& log_path);
  /// end().
  ~RunChild();
  RunChild(const RunChild&) = delete;
  RunChild& operator=(const RunChild&) = delete;

  /// The server's end of the socket; the caller takes it (and closes it).
  int take_channel_fd();
  pid_t pid() const { return pid_; }
  /// True once the child ended (reaped; `status` its wait status), without waiting.
  bool ended(int& status);
  /// Kills its process group (the child and whatever it started that is still in it) with
  /// SIGKILL and reaps the child. Idempotent.
  void end();

 private:
  pid_t pid_ = -1;
  int channel_fd_ = -1;
  bool reaped_ = false;
  bool group_killed_ = false;
};

}  // namespace stepdance::cli::serve
