// PtyPort: posix_openpt, raw termios on the terminal side, non-blocking master I/O.
#include "pty_port.hpp"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include <stdexcept>

namespace stepdance::cli {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + ": " + strerror(errno)); }

void make_raw(int fd) {
  termios settings{};
  if (tcgetattr(fd, &settings) != 0) fail("tcgetattr");
  cfmakeraw(&settings);
  if (tcsetattr(fd, TCSANOW, &settings) != 0) fail("tcsetattr");
}

}  // namespace

PtyPort::PtyPort() {
  master_ = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (master_ < 0) fail("posix_openpt");
  if (grantpt(master_) != 0 || unlockpt(master_) != 0) fail("grantpt/unlockpt");
  const char* name = ptsname(master_);
  if (name == nullptr) fail("ptsname");
  path_ = name;
  keeper_ = open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (keeper_ < 0) fail(path_);
  make_raw(keeper_);
}

PtyPort::~PtyPort() {
  if (!link_.empty()) unlink(link_.c_str());
  if (keeper_ >= 0) close(keeper_);
  if (master_ >= 0) close(master_);
}

void PtyPort::link_as(const std::string& link) {
  unlink(link.c_str());  // a stale link from an earlier run
  if (symlink(path_.c_str(), link.c_str()) != 0) fail(link);
  link_ = link;
}

void PtyPort::read_from_client(std::string& out) {
  char buffer[4096];
  for (;;) {
    const ssize_t count = read(master_, buffer, sizeof buffer);
    if (count > 0) {
      out.append(buffer, static_cast<size_t>(count));
      continue;
    }
    if (count < 0 && errno == EINTR) continue;
    return;  // EAGAIN: nothing more now (EIO cannot happen while keeper_ is open)
  }
}

void PtyPort::write_to_client(const uint8_t* data, size_t length) {
  const size_t room = kMaxPendingBytes - pending_.size();
  const size_t kept = length < room ? length : room;
  pending_.insert(pending_.end(), data, data + kept);
  dropped_ += length - kept;
  flush();
}

void PtyPort::flush() {
  size_t sent = 0;
  while (sent < pending_.size()) {
    const ssize_t count = write(master_, pending_.data() + sent, pending_.size() - sent);
    if (count > 0) {
      sent += static_cast<size_t>(count);
      continue;
    }
    if (count < 0 && errno == EINTR) continue;
    break;  // EAGAIN: the terminal's buffer is full until the client reads
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(sent));
}

}  // namespace stepdance::cli
