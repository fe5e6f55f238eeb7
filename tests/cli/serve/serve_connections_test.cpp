// `stepdance serve` under a flood of connections (issue 27): it spun at 100 % CPU and served
// nothing once file descriptors ran out under 200 half-open connections, accepted any number of
// connections, and gave a request 30 s to arrive. Each case runs the real command, bridging a
// pseudo-terminal (a serial device, so no sketch is built), in a process of its own with a
// descriptor limit, and talks to it over TCP.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace stepdance::cli::serve {
namespace {

using Clock = std::chrono::steady_clock;

/// A `stepdance serve` process on a fresh pseudo-terminal, with `ulimit -n` descriptors.
class ServeProcess {
 public:
  explicit ServeProcess(int descriptor_limit) {
    terminal_ = posix_openpt(O_RDWR | O_NOCTTY);
    grantpt(terminal_);
    unlockpt(terminal_);
    const std::string device = ptsname(terminal_);
    int out[2];
    if (pipe(out) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      const std::string command = "ulimit -n " + std::to_string(descriptor_limit) +
                                  " && exec " STEPDANCE_BUILD_DIR "/stepdance serve " + device + " --port 0";
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(out[1]);
    port_ = read_port(out[0]);
    close(out[0]);
  }
  ~ServeProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
    if (terminal_ >= 0) close(terminal_);
  }

  int port() const { return port_; }
  /// CPU time the server has used so far, in seconds (/proc/<pid>/stat: utime + stime).
  double cpu_seconds() const {
    std::ifstream stat("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    std::istringstream fields(text.substr(text.rfind(')') + 2));
    std::string field;
    unsigned long long utime = 0, stime = 0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
      if (i == 14) utime = std::stoull(field);
      if (i == 15) stime = std::stoull(field);
    }
    return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
  }

 private:
  /// The port of the announcement "serving http://127.0.0.1:PORT/ for …" (0 if none in 30 s).
  static int read_port(int fd) {
    std::string text;
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (text.find('\n') == std::string::npos && Clock::now() < deadline) {
      pollfd ready{fd, POLLIN, 0};
      if (poll(&ready, 1, 100) <= 0) continue;
      char buffer[256];
      const ssize_t count = read(fd, buffer, sizeof buffer);
      if (count <= 0) break;
      text.append(buffer, static_cast<size_t>(count));
    }
    const size_t colon = text.find(":", text.find("127.0.0.1"));
    return colon == std::string::npos ? 0 : std::atoi(text.c_str() + colon + 1);
  }

  int terminal_ = -1;
  pid_t pid_ = -1;
  int port_ = 0;
};

/// A TCP connection to the server that sends nothing (half-open, as far as HTTP goes).
int connect_to(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

/// Whether the server closed `fd` (it reads end-of-file) within `wait`.
bool closed_within(int fd, std::chrono::milliseconds wait) {
  pollfd ready{fd, POLLIN, 0};
  if (poll(&ready, 1, static_cast<int>(wait.count())) <= 0) return false;
  char byte;
  return recv(fd, &byte, 1, 0) <= 0;
}

/// The status line of GET / (empty if no answer within 2 s).
std::string get_page(int port) {
  const int fd = connect_to(port);
  if (fd < 0) return {};
  const std::string request =
      "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n";
  send(fd, request.data(), request.size(), MSG_NOSIGNAL);
  std::string reply;
  char buffer[512];
  pollfd ready{fd, POLLIN, 0};
  if (poll(&ready, 1, 2000) > 0) {
    const ssize_t count = recv(fd, buffer, sizeof buffer, 0);
    if (count > 0) reply.assign(buffer, static_cast<size_t>(count));
  }
  close(fd);
  return reply.substr(0, reply.find("\r\n"));
}

TEST(ServeConnectionsTest, OutOfDescriptorsItWaitsInsteadOfSpinningAndRecovers) {
  ServeProcess server(48);  // fewer descriptors than the 200 connections below
  ASSERT_GT(server.port(), 0);
  std::vector<int> flood;
  for (int i = 0; i < 200; ++i) flood.push_back(connect_to(server.port()));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const double cpu_before = server.cpu_seconds();
  std::this_thread::sleep_for(std::chrono::seconds(2));
  const double cpu_used = server.cpu_seconds() - cpu_before;
  EXPECT_LT(cpu_used, 0.5) << "2 s out of descriptors took " << cpu_used << " s of CPU";
  for (int fd : flood) close(fd);
  std::string status;
  for (const auto deadline = Clock::now() + std::chrono::seconds(10); Clock::now() < deadline;) {
    status = get_page(server.port());
    if (status == "HTTP/1.1 200 OK") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_EQ(status, "HTTP/1.1 200 OK");
}

TEST(ServeConnectionsTest, ConnectionsBeyondTheCapAreClosedAtOnce) {
  ServeProcess server(1024);
  ASSERT_GT(server.port(), 0);
  std::vector<int> flood;
  for (int i = 0; i < 100; ++i) flood.push_back(connect_to(server.port()));
  int closed = 0;
  for (int fd : flood) closed += closed_within(fd, std::chrono::milliseconds(50)) ? 1 : 0;
  EXPECT_EQ(closed, 100 - 64);  // WebServer::kMaxConnections stay open, waiting for a request
  for (int fd : flood) close(fd);
}

TEST(ServeConnectionsTest, AConnectionThatSendsNothingIsClosedAfterFiveSeconds) {
  ServeProcess server(1024);
  ASSERT_GT(server.port(), 0);
  const int fd = connect_to(server.port());
  const auto opened = Clock::now();
  ASSERT_TRUE(closed_within(fd, std::chrono::seconds(10)));
  const double waited = std::chrono::duration<double>(Clock::now() - opened).count();
  EXPECT_GT(waited, 4.5);
  EXPECT_LT(waited, 7.0);  // WebServer::kRequestTimeout, 5 s (30 s before)
  close(fd);
}

}  // namespace
}  // namespace stepdance::cli::serve
