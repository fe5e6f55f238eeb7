// PtyPort: posix_openpt, raw termios on the terminal side, non-blocking master I/O.
#include "pty_port.hpp"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
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

void PtyPort::read_from_client(std::string& out, size_t max_bytes) {
  char buffer[4096];
  size_t room = max_bytes;
  while (room > 0) {
    const ssize_t count = read(master_, buffer, room < sizeof buffer ? room : sizeof buffer);
    if (count > 0) {
      out.append(buffer, static_cast<size_t>(count));
      room -= static_cast<size_t>(count);
      continue;
    }
    if (count < 0 && errno == EINTR) continue;
    return;  // EAGAIN: nothing more now (EIO cannot happen while keeper_ is open)
  }
}

// Appends to the ring, dropping its oldest bytes (counted) when it is full.
void PtyPort::write_to_client(const uint8_t* data, size_t length) {
  flush();
  for (size_t i = 0; i < length; ++i) {
    if (size_ == kMaxPendingBytes) {
      head_ = (head_ + 1) % kMaxPendingBytes;
      --size_;
      ++dropped_;
    }
    pending_[(head_ + size_) % kMaxPendingBytes] = data[i];
    ++size_;
  }
  flush();
}

// Bytes written to the master reach the terminal's read queue through the kernel's flip buffer, a
// work item run later by a kernel thread (much later on a loaded machine); FIONREAD does not
// count them until then. poll() on the terminal side runs that pending work first when the
// queue looks empty (n_tty_poll), so the count that follows includes every byte written so far.
size_t PtyPort::unread_by_client() const {
  pollfd terminal{keeper_, POLLIN, 0};
  (void)poll(&terminal, 1, 0);
  int in_terminal = 0;
  if (ioctl(keeper_, FIONREAD, &in_terminal) != 0) in_terminal = 0;
  return size_ + static_cast<size_t>(std::max(in_terminal, 0));
}

// Writes the ring's contiguous runs while the terminal takes them.
void PtyPort::flush() {
  while (size_ > 0) {
    const size_t run = std::min(size_, kMaxPendingBytes - head_);
    const ssize_t count = write(master_, pending_.data() + head_, run);
    if (count < 0 && errno == EINTR) continue;
    if (count <= 0) return;  // EAGAIN: the terminal's buffer is full until the client reads
    head_ = (head_ + static_cast<size_t>(count)) % kMaxPendingBytes;
    size_ -= static_cast<size_t>(count);
  }
}

}  // namespace stepdance::cli
