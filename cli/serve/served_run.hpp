// One run of the sketch server, seen from the server: its folder, its child process and the
// socket between them. Whatever the child does, the server only forwards, times and ends it.
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/streambuf.hpp>

#include "serve/run_child.hpp"

namespace stepdance::cli::serve {

/// Limits the server puts on a run from outside its process.
struct ServedRunLimits {
  std::chrono::seconds build_s{120};  ///< wall time from the start until `started` or `failed`
  size_t message_bytes = 16u << 20;   ///< the longest message the child may send
  size_t queued_bytes = 1u << 20;     ///< page messages waiting for a child that does not read
};

/// Context: the server's event loop. The run's folder is removed when the run ends, however it
/// ends. Callbacks are never called after the object is gone.
class ServedRun {
 public:
  /// A message for the page (a line the child sent); `final` the run's last (`result`,
  /// `failed`, or the report of its end).
  using Forward = std::function<void(const std::string& message, bool final)>;

  /// Starts `stepdance <arguments>` in `folder` (which it now owns). Throws std::runtime_error.
  ServedRun(boost::asio::io_context& io, std::string folder, const std::vector<std::string>& arguments,
            const ServedRunLimits& limits, Forward forward);
  /// Ends the child and its process group, removes the folder.
  ~ServedRun();

  /// Queues a page's message for the child (dropped, counted, when the child stopped reading).
  void to_child(const std::string& line);
  /// Looks at the child: reports and ends a run whose process ended without its result, or
  /// whose build took too long. Call it periodically. True once the run is over.
  bool check();
  bool over() const { return over_; }
  uint64_t dropped_to_child() const { return dropped_; }

 private:
  void read_next();
  void on_line(const std::string& line);
  void write_next();
  void finish(const std::string& message);
  std::string log_tail() const;

  std::string folder_;
  ServedRunLimits limits_;
  Forward forward_;
  RunChild child_;
  boost::asio::posix::stream_descriptor channel_;
  boost::asio::streambuf incoming_;
  std::deque<std::string> outgoing_;
  size_t outgoing_bytes_ = 0;
  bool writing_ = false;
  uint64_t dropped_ = 0;
  std::chrono::steady_clock::time_point started_at_;
  std::chrono::steady_clock::time_point exited_at_{};
  int exit_status_ = 0;
  bool exited_ = false;
  bool running_ = false;  ///< `started` seen
  bool over_ = false;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace stepdance::cli::serve
