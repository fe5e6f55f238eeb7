// A board's USB serial console, seen from both ends: the bytes a host sends the sketch, and what
// the sketch prints, kept for inspection and handed on line by line and byte by byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {

/// One board's console. Context: host, on the simulation's thread (the sketch's calls arrive
/// through SimBoard at the board's time).
class BoardConsole {
 public:
  /// The board's USB serial receive buffer: a Teensy 4 holds 8 packets of 512 bytes
  /// (teensy4/usb_serial.c in PJRC's cores); a host cannot get further ahead of the sketch.
  static constexpr size_t kInputBytes = 8 * 512;
  /// What the sketch printed is kept for inspection up to this much (the newest; older is dropped
  /// and counted; a one-hour soak's status replies made a megabyte of it), and a line longer than
  /// kLineBytes is handed on in pieces.
  static constexpr size_t kTextBytes = 64 * 1024;
  static constexpr size_t kLineBytes = 4096;
  /// A line left unfinished this long (simulated) is handed on as it is.
  static constexpr SimTime kQuietNs = 100 * kMillisecond;

  explicit BoardConsole(Scheduler& scheduler) : scheduler_(scheduler), quiet_event_(*this) {}
  ~BoardConsole() { scheduler_.cancel(quiet_event_); }
  BoardConsole(const BoardConsole&) = delete;
  BoardConsole& operator=(const BoardConsole&) = delete;

  // ---- the host's end ----
  /// Queues bytes for the sketch's Serial input (scripted senders: the scenario bounds them).
  void send(const std::string& bytes) { input_.insert(input_.end(), bytes.begin(), bytes.end()); }
  /// Room left in the receive buffer: a live terminal is read no further than this, so a host
  /// writing faster than the sketch reads is held back, as by a real board's USB.
  size_t input_room() const;
  /// Counts console bytes a live terminal dropped because nobody read them (the summary's
  /// console entry reports them).
  void count_dropped(uint64_t bytes) { dropped_bytes_ += bytes; }
  uint64_t dropped_bytes() const { return dropped_bytes_; }
  /// Bytes of text() dropped to keep it within kTextBytes.
  uint64_t text_dropped_bytes() const { return text_dropped_; }
  /// Calls `listener` with every complete line the sketch prints (without the line ending).
  void on_line(std::function<void(const std::string&)> listener) { line_listener_ = std::move(listener); }
  /// Hands the line the sketch has begun but not ended to the line listener (at the run's end,
  /// or after a quiet while), as if it had ended.
  void flush_line();
  /// Calls `listener` with the sketch's console bytes as they are written, unchanged (the live
  /// simulator forwards them to a pseudo-terminal).
  void on_bytes(std::function<void(const uint8_t*, size_t)> listener) { bytes_listener_ = std::move(listener); }
  /// What the sketch printed so far: everything, or its newest kTextBytes.
  const std::string& text() const { return text_; }

  // ---- the sketch's end ----
  /// The sketch writes `length` bytes at `now_ns` (the board's time); all are taken.
  size_t write(const uint8_t* data, size_t length, SimTime now_ns);
  /// Bytes the host has sent that the sketch has not read.
  size_t available() const { return input_.size() - read_position_; }
  /// The next byte the host sent, or -1.
  int read();

 private:
  /// Hands on a console line left unfinished for kQuietNs.
  struct QuietEvent : Event {
    explicit QuietEvent(BoardConsole& console) : Event(&fire), owner(console) {}
    static void fire(Event& event, Scheduler& scheduler);
    BoardConsole& owner;
  };
  void keep_text(const uint8_t* data, size_t length);

  Scheduler& scheduler_;
  QuietEvent quiet_event_;
  std::vector<uint8_t> input_;
  size_t read_position_ = 0;
  std::string text_;
  uint64_t text_dropped_ = 0;
  uint64_t dropped_bytes_ = 0;
  std::string line_;
  std::function<void(const std::string&)> line_listener_;
  std::function<void(const uint8_t*, size_t)> bytes_listener_;
};

}  // namespace stepdance::sim
