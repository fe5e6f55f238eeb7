// HostClient: the step machine, line splitting, flow control and the transcript file.
#include "assembly/host_client.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace stepdance::sim {
namespace {

/// How often the client looks at the link: a USB full-speed frame.
constexpr SimTime kTickNs = kMillisecond;

/// The longest line kept whole: longer lines are kept as pieces of this many bytes, each but the
/// last marked `cut`, so a board printing without line ends cannot grow a line without bound.
constexpr size_t kLongestLineBytes = 1000;

std::string escaped(const std::string& bytes) {
  std::string out;
  for (const char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F && byte != '\\') {
      out += c;
    } else {
      char code[8];
      std::snprintf(code, sizeof code, "\\x%02X", byte);
      out += code;
    }
  }
  return out;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(begin, end - begin) + "\n");
    begin = end + 1;
  }
  return lines;
}

std::string format_ms(SimTime time) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", static_cast<double>(time) / kMillisecond);
  return text;
}

std::string seconds_text(SimTime time) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", to_seconds(time));
  return text;
}

}  // namespace

HostClient::HostClient(const scenario::HostClientConfig& config, SimBoard& board, Scheduler& scheduler)
    : config_(config), board_(board), scheduler_(scheduler), timer_(scheduler, &on_tick, this) {
  board_.console().on_bytes([this](const uint8_t* data, size_t length) { receive(data, length); });
}

void HostClient::start() { timer_.start(config_.start, kTickNs); }

void HostClient::on_tick(void* context, SimTime time) { static_cast<HostClient*>(context)->tick(time); }

void HostClient::receive(const uint8_t* data, size_t length) {
  for (size_t i = 0; i < length; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\r' && partial_line_.empty()) continue;  // the EBB ends some lines "\n\r"
    if (c != '\n') {
      // A CR may still end a full line ("\r\n"), so it waits one byte longer for the cut.
      if (partial_line_.size() >= kLongestLineBytes + (c == '\r' ? 1 : 0)) take_received_line(true);
      partial_line_ += c;
      continue;
    }
    if (!partial_line_.empty() && partial_line_.back() == '\r') partial_line_.pop_back();
    take_received_line(false);
  }
}

void HostClient::take_received_line(bool cut) {
  std::string rest;
  if (partial_line_.size() > kLongestLineBytes) {  // a CR that did not end the line goes on
    rest = partial_line_.substr(kLongestLineBytes);
    partial_line_.resize(kLongestLineBytes);
  }
  keep({scheduler_.now(), false, escaped(partial_line_), cut});
  if (!completed() && failure_.empty()) {  // a stopped client reads nothing more
    if (unread_.size() == kUnreadLines) {
      unread_.pop_front();
      ++unread_dropped_;
    }
    unread_.push_back(std::move(partial_line_));
  }
  partial_line_ = std::move(rest);
}

void HostClient::keep(Entry entry) {
  if (transcript_.size() < kTranscriptEntries) {
    transcript_.push_back(std::move(entry));
  } else {
    ++transcript_not_kept_;
  }
}

void HostClient::tick(SimTime now) {
  while (failure_.empty() && !completed()) {
    if (!step_entered_) enter_step(now);
    if (!run_step(now)) break;
    ++step_;
    step_entered_ = false;
  }
  if (!failure_.empty() || completed()) timer_.stop();
}

void HostClient::enter_step(SimTime now) {
  const scenario::HostStep& step = config_.steps[step_];
  step_entered_ = true;
  step_started_ = now;
  last_progress_ = now;
  if (step.kind == scenario::HostStep::Kind::kWait || step.kind == scenario::HostStep::Kind::kStream) {
    pattern_ = scenario::LinePattern(step.pattern);  // checked by the scenario reader
  }
  if (step.kind == scenario::HostStep::Kind::kStream) {
    lines_ = split_lines(step.bytes);
    next_line_ = 0;
    in_flight_.clear();
    in_flight_bytes_ = 0;
  }
}

bool HostClient::run_step(SimTime now) {
  const scenario::HostStep& step = config_.steps[step_];
  switch (step.kind) {
    case scenario::HostStep::Kind::kSend: send(step.bytes, now); return true;
    case scenario::HostStep::Kind::kPause: return now - step_started_ >= step.pause;
    case scenario::HostStep::Kind::kWait: return run_wait(step, now);
    case scenario::HostStep::Kind::kStream: return run_stream(step, now);
  }
  return true;
}

void HostClient::poll_if_due(const scenario::HostStep& step, SimTime now) {
  if (step.poll.empty()) return;
  if (now != step_started_ && now - last_poll_ < step.poll_interval) return;
  send(step.poll, now);
  last_poll_ = now;
}

bool HostClient::run_wait(const scenario::HostStep& step, SimTime now) {
  poll_if_due(step, now);
  while (!unread_.empty()) {
    const bool matched = pattern_.found_in(unread_.front());
    unread_.pop_front();
    if (matched) return true;
  }
  if (now - step_started_ > step.timeout) {
    fail("waited " + seconds_text(step.timeout) + " for a line matching \"" + step.pattern + "\"");
  }
  return false;
}

bool HostClient::run_stream(const scenario::HostStep& step, SimTime now) {
  poll_if_due(step, now);
  while (!unread_.empty()) {
    const bool ack = pattern_.found_in(unread_.front());
    unread_.pop_front();
    if (!ack || in_flight_.empty()) continue;  // a report or message, not an acknowledgement
    in_flight_bytes_ -= in_flight_.front();
    in_flight_.pop_front();
    ++acknowledged_;
    last_progress_ = now;
  }
  const bool counting = step.flow == scenario::HostStep::Flow::kCharacterCounting;
  const size_t budget = counting ? static_cast<size_t>(step.buffer_bytes) : 0;
  while (next_line_ < lines_.size()) {
    const size_t size = lines_[next_line_].size();
    const bool fits = in_flight_.empty() || (counting && in_flight_bytes_ + size <= budget);
    if (!fits) break;
    send(lines_[next_line_], now);
    in_flight_.push_back(size);
    in_flight_bytes_ += size;
    ++next_line_;
  }
  if (next_line_ == lines_.size() && in_flight_.empty()) return true;
  if (now - last_progress_ > step.timeout) {
    fail("no acknowledgement matching \"" + step.pattern + "\" for " + seconds_text(step.timeout) + " (line " +
         std::to_string(next_line_ - in_flight_.size() + 1) + " of the stream)");
  }
  return false;
}

void HostClient::send(const std::string& bytes, SimTime now) {
  board_.console().send(bytes);
  // One transcript entry per line sent (a long one in pieces), as for received lines.
  size_t begin = 0;
  do {
    size_t end = bytes.find('\n', begin);
    if (end == std::string::npos) end = bytes.size();
    const bool cut = end - begin > kLongestLineBytes;
    if (cut) end = begin + kLongestLineBytes;
    keep({now, true, escaped(bytes.substr(begin, end - begin)), cut});
    begin = cut ? end : end + 1;
  } while (begin < bytes.size());
}

void HostClient::fail(const std::string& why) {
  const scenario::HostStep& step = config_.steps[step_];
  failure_ = "host client on '" + config_.board + "', step at line " + std::to_string(step.line) + ": " + why;
}

void HostClient::write_transcript(const std::string& path) const {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << "# simulated ms, > sent by the host / < received from the board, the line\n";
  for (const Entry& entry : transcript_) {
    out << format_ms(entry.time) << (entry.from_host ? " > " : " < ") << entry.text << '\n';
    if (entry.cut)
      out << "# the line above goes on in the next one (lines over " << kLongestLineBytes << " bytes are split)\n";
  }
  if (transcript_not_kept_ > 0) {
    out << "# " << transcript_not_kept_ << " more lines not kept (a transcript keeps the first " << kTranscriptEntries
        << ")\n";
  }
  if (!failure_.empty()) out << "# stopped: " << failure_ << '\n';
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the host transcript");
}

}  // namespace stepdance::sim
