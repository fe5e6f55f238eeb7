// RunChannel: blocking writes, polled reads split into lines.
#include "run_channel.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace stepdance::cli::serve {
namespace {

/// A message from the page longer than this (the server's own limit is 64 KiB) ends the channel.
constexpr size_t kMaxPendingBytes = 1 << 20;

}  // namespace

RunChannel::RunChannel(int fd) : fd_(fd) { fcntl(fd_, F_SETFD, FD_CLOEXEC); }

bool RunChannel::send(std::string_view message) {
  std::string line(message);
  line += '\n';
  size_t sent = 0;
  while (open_ && sent < line.size()) {
    const ssize_t wrote = write(fd_, line.data() + sent, line.size() - sent);
    if (wrote > 0) {
      sent += static_cast<size_t>(wrote);
    } else if (wrote < 0 && errno != EINTR && errno != EAGAIN) {
      open_ = false;
    }
  }
  return open_;
}

bool RunChannel::receive(int timeout_ms, const std::function<void(std::string_view)>& received) {
  pollfd watched{fd_, POLLIN, 0};
  if (!open_ || poll(&watched, 1, timeout_ms) <= 0) return open_;
  char buffer[8192];
  const ssize_t got = read(fd_, buffer, sizeof buffer);
  if (got == 0 || (got < 0 && errno != EINTR && errno != EAGAIN)) open_ = false;
  if (got > 0) pending_.append(buffer, static_cast<size_t>(got));
  for (size_t end = pending_.find('\n'); end != std::string::npos; end = pending_.find('\n')) {
    received(std::string_view(pending_).substr(0, end));
    pending_.erase(0, end + 1);
  }
  if (pending_.size() > kMaxPendingBytes) open_ = false;
  return open_;
}

}  // namespace stepdance::cli::serve
