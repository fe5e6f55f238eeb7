// ChildBoardLink: the child's lines turned back into the link's calls; its end noticed.
#include "serve/child_board_link.hpp"

#include <signal.h>

#include <boost/asio/read_until.hpp>
#include <boost/asio/write.hpp>

#include "serve/run_report.hpp"

namespace stepdance::cli::serve {
namespace {

namespace net = boost::asio;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr std::chrono::milliseconds kWatchPeriod{100};
/// After the child ended, how long its last messages may take to arrive.
constexpr std::chrono::milliseconds kDrainAfterExit{300};
constexpr size_t kMaxMessageBytes = 16u << 20;

std::string text_of(const json& message) { return message.dump(-1, ' ', false, json::error_handler_t::replace); }

}  // namespace

ChildBoardLink::ChildBoardLink(net::io_context& io, std::vector<std::string> runner_arguments, std::string board)
    : io_(io), arguments_(std::move(runner_arguments)), board_(std::move(board)), watch_timer_(io) {
  start();
  watch();
}

ChildBoardLink::~ChildBoardLink() {
  *alive_ = false;
  if (channel_) channel_->close();
}

void ChildBoardLink::start() {
  child_ = std::make_unique<RunChild>(arguments_, "");
  channel_ = std::make_unique<net::posix::stream_descriptor>(io_, child_->take_channel_fd());
  incoming_ = std::make_unique<net::streambuf>(kMaxMessageBytes);
  running_ = ended_ = exited_ = false;
  ended_text_.clear();
  read_next();
}

void ChildBoardLink::restart() {
  if (!ended_) return;
  *alive_ = false;
  alive_ = std::make_shared<bool>(true);
  channel_->close();
  start();
}

void ChildBoardLink::read_next() {
  net::async_read_until(*channel_, *incoming_, '\n',
                        [this, alive = alive_](const boost::system::error_code& error, size_t length) {
                          if (!*alive || error) return;
                          std::string line(net::buffers_begin(incoming_->data()),
                                           net::buffers_begin(incoming_->data()) + static_cast<long>(length) - 1);
                          incoming_->consume(length);
                          on_message(line);
                          read_next();
                        });
}

void ChildBoardLink::on_message(const std::string& line) {
  const json message = json::parse(line, nullptr, false);
  if (!message.is_object()) return;
  if (message.contains("line") && message["line"].is_string()) {
    if (on_line_) on_line_(message["line"].get<std::string>());
  } else if (message.contains("drawing")) {
    if (on_drawing_) on_drawing_(message);
  } else if (message.contains("hello")) {
    machine_ = message["hello"];
    if (machine_.contains("machine") && machine_["machine"].contains("board")) board_ = machine_["machine"]["board"];
    running_ = true;
  } else if (message.contains("ended") && message["ended"].contains("text")) {
    ended_text_ = message["ended"]["text"].get<std::string>();
  } else if (message.contains("wrote") && message["wrote"].is_array()) {
    wrote_ = message["wrote"].get<std::vector<std::string>>();
  }
}

void ChildBoardLink::send(const std::string& bytes) {
  if (!running_ || ended_) return;
  auto text = std::make_shared<std::string>(text_of(json{{"send", bytes}}) + "\n");
  net::async_write(*channel_, net::buffer(*text), [text](const boost::system::error_code&, size_t) {});
}

// Every kWatchPeriod: has the child ended? Its last messages get kDrainAfterExit to arrive.
void ChildBoardLink::watch() {
  watch_timer_.expires_after(kWatchPeriod);
  watch_timer_.async_wait([this, alive = alive_](const boost::system::error_code& error) {
    if (error) return;
    if (!ended_ && !exited_ && child_->ended(exit_status_)) {
      exited_ = true;
      exited_at_ = Clock::now();
    }
    if (!ended_ && exited_ && Clock::now() - exited_at_ >= kDrainAfterExit) report_end();
    watch();
  });
}

void ChildBoardLink::report_end() {
  ended_ = true;
  running_ = false;
  child_->end();
  std::string text = ended_text_.empty() ? process_end_text(exit_status_) + "\n" : ended_text_;
  text += "the board's run has ended; a page that connects starts it again from the scenario's files\n";
  if (on_ended_) on_ended_(json{{"ended", {{"board", board_}, {"text", text}}}});
}

std::vector<std::string> ChildBoardLink::stop(net::io_context& io, std::chrono::seconds grace) {
  watch_timer_.cancel();
  if (!ended_ && !exited_) {
    io.restart();
    kill(child_->pid(), SIGTERM);
    const Clock::time_point deadline = Clock::now() + grace;
    while (!child_->ended(exit_status_) && Clock::now() < deadline) io.run_for(std::chrono::milliseconds(20));
    io.run_for(std::chrono::milliseconds(50));  // its last messages
  }
  child_->end();
  return wrote_;
}

}  // namespace stepdance::cli::serve
