// run_live: terminals, signal handling and wall-clock pacing around Simulation::run_until.
#include "live_run.hpp"

#include <signal.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <thread>

#include "pty_port.hpp"

namespace stepdance::cli {
namespace {

/// Simulated time between exchanges with the terminals: 1 ms, about a USB full-speed frame.
constexpr sim::SimTime kExchangeNs = sim::kMillisecond;

volatile sig_atomic_t stop_requested = 0;

void request_stop(int) { stop_requested = 1; }

/// Installs the stop handler for SIGINT and SIGTERM while in scope, restoring the old ones after.
class StopSignals {
 public:
  StopSignals() {
    stop_requested = 0;
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~StopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

struct BoardLink {
  sim::SimBoard* board;
  std::unique_ptr<PtyPort> port;
};

std::vector<BoardLink> open_terminals(sim::Simulation& simulation, const std::vector<std::string>& boards,
                                      const LiveOptions& options) {
  std::vector<BoardLink> links;
  for (const std::string& name : boards) {
    BoardLink link{simulation.board(name), std::make_unique<PtyPort>()};
    auto found = options.serial_links.find(name);
    if (found != options.serial_links.end()) link.port->link_as(found->second);
    PtyPort* port = link.port.get();
    link.board->on_console_bytes([port](const uint8_t* data, size_t length) { port->write_to_client(data, length); });
    links.push_back(std::move(link));
  }
  for (const auto& [name, path] : options.serial_links) {
    if (simulation.board(name) == nullptr) throw std::runtime_error("--serial-link: no board named '" + name + "'");
  }
  return links;
}

void exchange(std::vector<BoardLink>& links) {
  std::string received;
  for (BoardLink& link : links) {
    received.clear();
    link.port->read_from_client(received);
    if (!received.empty()) link.board->send_console(received);
    link.port->flush();
  }
}

}  // namespace

void run_live(sim::Simulation& simulation, const std::vector<std::string>& boards, const LiveOptions& options) {
  std::vector<BoardLink> links = open_terminals(simulation, boards, options);
  for (size_t i = 0; i < links.size(); ++i) std::printf("serial %s: %s\n", boards[i].c_str(), links[i].port->path().c_str());
  std::fflush(stdout);
  StopSignals signals;
  const auto wall_start = std::chrono::steady_clock::now();
  const sim::SimTime sim_start = simulation.now();
  while (!stop_requested && simulation.now() < simulation.duration()) {
    exchange(links);
    simulation.run_until(simulation.now() + kExchangeNs);
    if (options.speed <= 0.0) continue;
    const double due_s = sim::to_seconds(simulation.now() - sim_start) / options.speed;
    const auto due = wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(due_s));
    std::this_thread::sleep_until(due);
  }
  exchange(links);
  for (BoardLink& link : links) link.board->on_console_bytes(nullptr);
  simulation.end_now();
}

}  // namespace stepdance::cli
