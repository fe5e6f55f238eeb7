// ServedRun: the child's messages forwarded line by line; its end noticed and reported.
#include "serve/served_run.hpp"

#include <fstream>
#include <sstream>

#include <boost/asio/read_until.hpp>
#include <boost/asio/write.hpp>
#include <nlohmann/json.hpp>

#include "serve/run_folders.hpp"
#include "serve/run_report.hpp"

namespace stepdance::cli::serve {
namespace {

namespace net = boost::asio;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

/// After the child ended, how long its last messages may take to arrive before its end is
/// reported as it is.
constexpr std::chrono::milliseconds kDrainAfterExit{300};
/// The end of the run's log shown with a report: the last lines, up to this many bytes.
constexpr std::streamoff kLogTailBytes = 2000;

}  // namespace

ServedRun::ServedRun(net::io_context& io, std::string folder, const std::vector<std::string>& arguments,
                     const ServedRunLimits& limits, Forward forward)
    : folder_(std::move(folder)),
      limits_(limits),
      forward_(std::move(forward)),
      child_(arguments, folder_ + "/run.log"),
      channel_(io, child_.take_channel_fd()),
      incoming_(limits.message_bytes),
      started_at_(Clock::now()) {
  read_next();
}

ServedRun::~ServedRun() {
  *alive_ = false;
  boost::system::error_code ignored;
  channel_.close(ignored);
  child_.end();
  remove_run_folder(folder_);
}

void ServedRun::read_next() {
  net::async_read_until(channel_, incoming_, '\n',
                        [this, alive = alive_](const boost::system::error_code& error, size_t length) {
                          if (!*alive || over_) return;
                          if (error) {
                            if (error == net::error::not_found)
                              finish("the run sent a message over the server's limit");
                            return;  // the end of the child is seen by check()
                          }
                          std::string line(net::buffers_begin(incoming_.data()),
                                           net::buffers_begin(incoming_.data()) + static_cast<long>(length) - 1);
                          incoming_.consume(length);
                          on_line(line);
                          if (!over_) read_next();
                        });
}

void ServedRun::on_line(const std::string& line) {
  const json message = json::parse(line, nullptr, false);
  const std::string type = message.is_object() ? message.value("type", "") : "";
  if (type == "started") running_ = true;
  const bool final = type == "result" || type == "failed";
  forward_(line, final);
  if (final) {
    over_ = true;
    child_.end();
  }
}

void ServedRun::to_child(const std::string& line) {
  if (over_) return;
  if (outgoing_bytes_ + line.size() > limits_.queued_bytes) {
    ++dropped_;
    return;
  }
  outgoing_.push_back(line + "\n");
  outgoing_bytes_ += line.size() + 1;
  write_next();
}

void ServedRun::write_next() {
  if (writing_ || outgoing_.empty()) return;
  writing_ = true;
  net::async_write(channel_, net::buffer(outgoing_.front()),
                   [this, alive = alive_](const boost::system::error_code& error, size_t) {
                     if (!*alive) return;
                     writing_ = false;
                     outgoing_bytes_ -= outgoing_.front().size();
                     outgoing_.pop_front();
                     if (!error) write_next();
                   });
}

bool ServedRun::check() {
  if (over_) return true;
  const Clock::time_point now = Clock::now();
  if (!exited_ && child_.ended(exit_status_)) {
    exited_ = true;
    exited_at_ = now;
  }
  if (exited_ && now - exited_at_ >= kDrainAfterExit) {
    finish(process_end_text(exit_status_));
  } else if (!running_ && now - started_at_ > limits_.build_s) {
    finish("the build took longer than " + std::to_string(limits_.build_s.count()) + " s of wall time");
  }
  return over_;
}

void ServedRun::finish(const std::string& message) {
  over_ = true;
  child_.end();
  const std::string tail = log_tail();
  std::string text = message + "\n";
  if (!tail.empty()) text += "the run's last output:\n" + tail;
  forward_(json{{"type", "ended"}, {"cause", "process"}, {"text", text}}.dump(), true);
}

std::string ServedRun::log_tail() const {
  std::ifstream log(folder_ + "/run.log", std::ios::binary | std::ios::ate);
  if (!log) return "";
  const std::streamoff size = log.tellg();
  log.seekg(std::max<std::streamoff>(0, size - kLogTailBytes));
  std::ostringstream tail;
  tail << log.rdbuf();
  return relative_to(tail.str(), folder_);
}

}  // namespace stepdance::cli::serve
