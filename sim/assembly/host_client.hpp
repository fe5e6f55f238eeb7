// A scripted program on the host end of a board's USB serial: send, stream with flow control, wait.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "board/host/sim_board.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kinds/finished_run.hpp"
#include "scenario/line_pattern.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Runs a [[host]] client's steps against one board, deterministically in simulated time.
///
/// The client looks at the link once per simulated millisecond (a USB full-speed frame): it takes
/// the lines the board printed since (split at '\n', a '\r' at either end dropped; a line over
/// 1,000 bytes is taken as pieces of 1,000, so no line held grows without bound), then advances
/// its steps as far as they can go. A line matches a pattern when the pattern (RE2,
/// scenario/line_pattern.hpp) finds a match anywhere in it (anchor with ^…$ for whole lines).
/// Steps:
///   send   — writes bytes at once;
///   stream — writes text line by line: with "ack" flow, the next line goes when the previous one
///            was acknowledged; with "character_counting", lines go while the unacknowledged
///            ones fit in buffer_bytes (Grbl's streaming protocol). Every received line matching
///            the ack pattern acknowledges the oldest line in flight; others are skipped. Fails
///            when no acknowledgement comes for `timeout`;
///   wait   — consumes received lines until one matches; fails after `timeout`.
///   Both may send `poll` bytes at their start and every poll_interval (a sender's `?`);
///   pause  — lets time pass.
/// A failed step stops the client (see failure()). Every line sent and received is kept, with
/// its time, in the transcript.
class HostClient {
 public:
  /// One line of the transcript (kinds/finished_run.hpp: the [[expect]] checks read it too).
  using Entry = HostLine;

  /// The transcript keeps the first kTranscriptEntries lines (later ones are counted, and the
  /// file says how many); at most kUnreadLines received lines wait for a step (the oldest go
  /// first, counted), and none once every step ran.
  static constexpr size_t kTranscriptEntries = 100000;
  static constexpr size_t kUnreadLines = 10000;

  HostClient(const scenario::HostClientConfig& config, SimBoard& board, Scheduler& scheduler);
  HostClient(const HostClient&) = delete;
  HostClient& operator=(const HostClient&) = delete;

  /// Begins ticking at the configured start time.
  void start();

  const std::string& board_name() const { return config_.board; }
  const std::vector<Entry>& transcript() const { return transcript_; }
  /// True once every step ran.
  bool completed() const { return step_ >= config_.steps.size(); }
  /// Why the client stopped early (empty while running or when completed).
  const std::string& failure() const { return failure_; }
  /// Lines sent by stream steps that were acknowledged.
  size_t acknowledged_lines() const { return acknowledged_; }
  /// Transcript lines not kept, and received lines dropped unread (see kTranscriptEntries).
  uint64_t transcript_lines_not_kept() const { return transcript_not_kept_; }
  uint64_t unread_lines_dropped() const { return unread_dropped_; }

  /// Writes the transcript: one entry per line, `<ms> > text` (sent) or `<ms> < text` (received).
  /// Throws std::runtime_error("path: …") when the file cannot be written.
  void write_transcript(const std::string& path) const;

 private:
  static void on_tick(void* context, SimTime time);
  void tick(SimTime now);
  void receive(const uint8_t* data, size_t length);
  /// Moves the received text so far into the transcript and the unread lines.
  void take_received_line(bool cut);
  /// Advances the current step; true when it finished (the next may start at once).
  bool run_step(SimTime now);
  bool run_stream(const scenario::HostStep& step, SimTime now);
  bool run_wait(const scenario::HostStep& step, SimTime now);
  void enter_step(SimTime now);
  void poll_if_due(const scenario::HostStep& step, SimTime now);
  void send(const std::string& bytes, SimTime now);
  void fail(const std::string& why);
  void keep(Entry entry);

  const scenario::HostClientConfig& config_;
  SimBoard& board_;
  Scheduler& scheduler_;
  PeriodicTimer timer_;
  std::vector<Entry> transcript_;
  std::string partial_line_;
  std::deque<std::string> unread_;  // received lines no step has consumed yet
  uint64_t transcript_not_kept_ = 0;
  uint64_t unread_dropped_ = 0;
  size_t step_ = 0;
  bool step_entered_ = false;
  SimTime step_started_ = 0;
  SimTime last_progress_ = 0;  // stream: the last acknowledgement
  SimTime last_poll_ = 0;      // stream and wait: when the poll bytes last went out
  scenario::LinePattern pattern_;
  // The current stream step: its lines, the next to send, the sizes of those in flight.
  std::vector<std::string> lines_;
  size_t next_line_ = 0;
  std::deque<size_t> in_flight_;
  size_t in_flight_bytes_ = 0;
  size_t acknowledged_ = 0;
  std::string failure_;
};

}  // namespace stepdance::sim
