// run_live: terminals, signal handling and wall-clock pacing around Simulation::run_until.
#include "live_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <thread>

#include "board/host/entry_monitor.hpp"
#include "live_pacer.hpp"
#include "pty_port.hpp"

namespace stepdance::cli {
namespace {

/// Simulated time between exchanges with the terminals: 1 ms, about a USB full-speed frame.
constexpr sim::SimTime kExchangeNs = sim::kMillisecond;

/// The longest the pacing sleeps at once, so a stop request is seen within this (at any speed).
constexpr auto kLongestSleep = std::chrono::milliseconds(20);
/// The longest a paced simulated millisecond waits for a client to read what its board wrote.
constexpr auto kReaderWait = std::chrono::milliseconds(100);
/// A client is waited for only while it drives its board (wrote within this) and reads (had
/// nothing left unread within this): not a terminal nobody reads, nor one that only writes.
constexpr auto kClientActive = std::chrono::seconds(1);
/// How often the wait for a reader looks again.
constexpr auto kReaderPoll = std::chrono::microseconds(100);

// Ctrl-C and SIGTERM reach the run through Containment (containment.hpp).
bool stop_requested() { return sim::EntryMonitor::requested() != sim::EscapeCause::kNone; }

// Sleeps until `due`, in short naps, while nobody asked the run to stop; returns the seconds
// it slept. With a view, the view serves its pages instead of sleeping.
double sleep_until(std::chrono::steady_clock::time_point due, LiveView* view) {
  const auto started = std::chrono::steady_clock::now();
  while (!stop_requested()) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= due) break;
    const auto nap = std::min<std::chrono::steady_clock::duration>(due - now, kLongestSleep);
    if (view != nullptr) {
      view->serve_for(nap);
    } else {
      std::this_thread::sleep_for(nap);
    }
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// Waits while a page has the run paused (serving the pages); true if it waited.
bool wait_while_paused(LiveView* view) {
  if (view == nullptr || !view->control().paused) return false;
  while (view->control().paused && !stop_requested()) view->serve_for(kLongestSleep);
  return true;
}

struct BoardLink {
  sim::SimBoard* board;
  std::unique_ptr<PtyPort> port;
  std::chrono::steady_clock::time_point client_wrote{};      // last time the client wrote (never: epoch)
  std::chrono::steady_clock::time_point client_caught_up{};  // last time it had read everything

  // Whether simulated time should wait for this client to read its board's output now.
  bool owes_a_read(std::chrono::steady_clock::time_point now) {
    port->flush();
    if (port->unread_by_client() == 0) {
      client_caught_up = now;
      return false;
    }
    return now - client_wrote < kClientActive && now - client_caught_up < kClientActive;
  }
};

std::vector<BoardLink> open_terminals(sim::Simulation& simulation, const std::vector<std::string>& boards,
                                      const LiveOptions& options) {
  std::vector<BoardLink> links;
  for (const std::string& name : boards) {
    BoardLink link{simulation.board(name), std::make_unique<PtyPort>()};
    auto found = options.serial_links.find(name);
    if (found != options.serial_links.end()) link.port->link_as(found->second);
    PtyPort* port = link.port.get();
    LiveView* view = options.view;
    const auto* also = &options.on_console;
    link.board->console().on_bytes([port, view, also, name](const uint8_t* data, size_t length) {
      port->write_to_client(data, length);
      if (view != nullptr) view->console(name, data, length);
      if (*also) (*also)(name, data, length);
    });
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
    link.port->read_from_client(received, link.board->console().input_room());
    if (!received.empty()) {
      link.board->console().send(received);
      link.client_wrote = std::chrono::steady_clock::now();
    }
    link.port->flush();
  }
}

// A client that drives its board gets up to kReaderWait to read what the board wrote before
// simulated time goes on: a G-code sender sees its `ok`s (and can refill the queue) before the
// run moves past them, so a run on a loaded machine goes slower than the clock instead of
// draining a sender's queue behind its back. Returns the seconds waited.
double wait_for_readers(std::vector<BoardLink>& links, LiveView* view) {
  const auto started = std::chrono::steady_clock::now();
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    bool waiting = false;
    for (BoardLink& link : links) waiting = link.owes_a_read(now) || waiting;
    if (!waiting || now - started >= kReaderWait || stop_requested()) break;
    if (view != nullptr) {
      view->serve_for(kReaderPoll);
    } else {
      std::this_thread::sleep_for(kReaderPoll);
    }
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// Detaches the boards from their terminals, counting and announcing what nobody read.
void close_terminals(std::vector<BoardLink>& links, const std::vector<std::string>& boards) {
  for (size_t i = 0; i < links.size(); ++i) {
    links[i].board->console().on_bytes(nullptr);
    const uint64_t dropped = links[i].port->dropped_bytes();
    links[i].board->console().count_dropped(dropped);
    if (dropped > 0) {
      std::printf("serial %s: %llu bytes the board printed were dropped, oldest first (nobody read them)\n",
                  boards[i].c_str(), static_cast<unsigned long long>(dropped));
    }
  }
}

}  // namespace

LiveTiming run_live(sim::Simulation& simulation, const std::vector<std::string>& boards, const LiveOptions& options) {
  std::vector<BoardLink> links = open_terminals(simulation, boards, options);
  for (size_t i = 0; i < links.size(); ++i)
    std::printf("serial %s: %s\n", boards[i].c_str(), links[i].port->path().c_str());
  LiveView* view = options.view;
  if (view != nullptr) {
    view->control().speed = options.speed;
    std::printf("%s\n", view->announcement().c_str());
  }
  std::fflush(stdout);
  const auto wall_start = std::chrono::steady_clock::now();
  LivePacer pacer;
  pacer.anchor(wall_start, simulation.now(), options.speed);
  double slept_s = 0;
  LiveTiming timing;
  double lag_total_ms = 0;
  // Every simulated millisecond, wherever the run is (a sketch waiting in delay() included).
  simulation.pace_every(kExchangeNs, [&](sim::SimTime now) {
    exchange(links);
    if (options.on_tick) options.on_tick(now);
    if (view != nullptr) {
      view->serve_now(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count());
      const auto paused_at = std::chrono::steady_clock::now();
      const bool paused = wait_while_paused(view);
      const auto resumed_at = std::chrono::steady_clock::now();
      if (paused) slept_s += std::chrono::duration<double>(resumed_at - paused_at).count();
      // After a pause or at a new speed the run is paced from here on, not from the start.
      if (paused || view->control().speed != pacer.speed()) pacer.anchor(resumed_at, now, view->control().speed);
    }
    if (pacer.speed() <= 0.0) return;
    slept_s += wait_for_readers(links, view);
    // Late by more than the catch-up limit, the run gives the time up rather than racing the
    // sender on the other end of the terminal (LivePacer).
    const LivePacer::Due due = pacer.due(now, std::chrono::steady_clock::now());
    ++timing.paced_ms;
    lag_total_ms += due.lag_ms;
    timing.lag_max_ms = std::max(timing.lag_max_ms, due.lag_ms);
    timing.given_up_ms += due.given_up_ms;
    slept_s += sleep_until(due.wall, view);
  });
  exchange(links);
  while (!stop_requested() && simulation.now() < simulation.duration() && !simulation.stopped()) {
    simulation.run_until(simulation.duration());
  }
  exchange(links);
  close_terminals(links, boards);
  if (view != nullptr) view->finish();
  simulation.end_now();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  timing.wall_s = wall_s;
  timing.computing_s = std::max(0.0, wall_s - slept_s);
  timing.lag_mean_ms = timing.paced_ms > 0 ? lag_total_ms / static_cast<double>(timing.paced_ms) : 0.0;
  return timing;
}

}  // namespace stepdance::cli
