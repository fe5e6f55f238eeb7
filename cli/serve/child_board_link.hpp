// `stepdance serve <scenario>`'s board: a simulated board run in a child process of its own
// (serve/board_runner.hpp), so that whatever its sketch does, the server goes on.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/streambuf.hpp>
#include <nlohmann/json.hpp>

#include "board_link.hpp"
#include "serve/run_child.hpp"

namespace stepdance::cli::serve {

/// Context: the server's event loop.
class ChildBoardLink : public BoardLink {
 public:
  /// `runner_arguments`: `run-board …` (after argv[0]). Starts the child at once; its output goes
  /// to the server's own stdout and stderr. Throws std::runtime_error when it cannot start.
  ChildBoardLink(boost::asio::io_context& io, std::vector<std::string> runner_arguments, std::string board);
  ~ChildBoardLink() override;

  void send(const std::string& bytes) override;
  std::string describe() const override { return "simulated board " + board_; }
  /// Receives each drawing update and each report of a run's end ({"ended": {"text": …}}).
  void on_drawing(std::function<void(const nlohmann::json&)> handler) { on_drawing_ = std::move(handler); }
  void on_ended(std::function<void(const nlohmann::json&)> handler) { on_ended_ = std::move(handler); }
  /// The machine's travel area and the run's state as JSON (empty until the child is running).
  nlohmann::json machine_description() const { return machine_; }

  /// The child is running its board (it said hello) / it has ended (then `exit_status()` is its
  /// wait status, its report sent to on_ended).
  bool running() const { return running_; }
  bool ended() const { return ended_; }
  int exit_status() const { return exit_status_; }
  /// Starts a new child from the scenario's files as they are now, if the last one ended.
  void restart();
  /// Asks the child to end (SIGTERM: it writes its outputs), waits for it up to `grace` while
  /// running `io`, then ends its process group. Returns the files it wrote.
  std::vector<std::string> stop(boost::asio::io_context& io, std::chrono::seconds grace);

 private:
  void start();
  void read_next();
  void on_message(const std::string& line);
  void watch();
  void report_end();

  boost::asio::io_context& io_;
  std::vector<std::string> arguments_;
  std::string board_;
  std::unique_ptr<RunChild> child_;
  std::unique_ptr<boost::asio::posix::stream_descriptor> channel_;
  std::unique_ptr<boost::asio::streambuf> incoming_;
  boost::asio::steady_timer watch_timer_;
  nlohmann::json machine_ = nlohmann::json::object();
  std::function<void(const nlohmann::json&)> on_drawing_;
  std::function<void(const nlohmann::json&)> on_ended_;
  std::vector<std::string> wrote_;
  std::string ended_text_;
  std::chrono::steady_clock::time_point exited_at_;
  bool exited_ = false;
  bool running_ = false;
  bool ended_ = false;
  int exit_status_ = 0;
  std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

}  // namespace stepdance::cli::serve
