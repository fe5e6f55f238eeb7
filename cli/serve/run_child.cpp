// RunChild: fork and exec with only async-signal-safe calls between them.
#include "serve/run_child.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace stepdance::cli::serve {
namespace {

constexpr int kChildChannelFd = 3;

// In the child, before exec: own process group, the channel on fd 3, the log on 1 and 2,
// nothing else open.
[[noreturn]] void become_runner(char* const* argv, int channel, int log) {
  setpgid(0, 0);
  if (channel == kChildChannelFd) {
    fcntl(channel, F_SETFD, 0);
  } else if (dup2(channel, kChildChannelFd) < 0) {
    _exit(127);
  }
  if (log >= 0 && (dup2(log, STDOUT_FILENO) < 0 || dup2(log, STDERR_FILENO) < 0)) _exit(127);
  const int null_in = open("/dev/null", O_RDONLY);
  if (null_in >= 0) dup2(null_in, STDIN_FILENO);
  for (int fd = kChildChannelFd + 1; fd < 1024; ++fd) close(fd);
  execv("/proc/self/exe", argv);
  _exit(127);
}

}  // namespace

RunChild::RunChild(const std::vector<std::string>& arguments, const std::string& log_path) {
  std::vector<std::string> words{"stepdance"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    throw std::runtime_error(std::string("cannot make the run's socket: ") + std::strerror(errno));
  }
  const int log = log_path.empty() ? -1 : open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
  pid_ = log < 0 && !log_path.empty() ? -1 : fork();
  if (pid_ == 0) become_runner(argv.data(), ends[1], log);
  const int error = errno;
  if (log >= 0) close(log);
  close(ends[1]);
  if (pid_ < 0) {
    close(ends[0]);
    throw std::runtime_error(std::string("cannot start the run's process: ") + std::strerror(error));
  }
  setpgid(pid_, pid_);  // also here, so end() never finds it still in ours
  channel_fd_ = ends[0];
}

RunChild::~RunChild() {
  end();
  if (channel_fd_ >= 0) close(channel_fd_);
}

int RunChild::take_channel_fd() {
  const int fd = channel_fd_;
  channel_fd_ = -1;
  return fd;
}

bool RunChild::ended(int& status) {
  if (reaped_) return true;
  if (waitpid(pid_, &status, WNOHANG) != pid_) return false;
  reaped_ = true;
  return true;
}

void RunChild::end() {
  if (pid_ <= 0) return;
  if (!group_killed_) kill(-pid_, SIGKILL);
  group_killed_ = true;
  if (reaped_) return;
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  reaped_ = true;
}

}  // namespace stepdance::cli::serve
