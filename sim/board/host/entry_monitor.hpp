// Which sketch code is running now, and how the simulator takes it back: the host half of
// contained sketches (the board half is sim/board/runtime/entry_guard.hpp).
#pragma once

#include <atomic>
#include <csignal>
#include <cstdint>

#include "board/loader/board_library.hpp"

namespace stepdance::sim {

class SimBoard;

/// The board entry point a sketch's code runs in.
enum class SketchEntry : uint8_t {
  kSetup,
  kLoop,
  kFrameTick,
  kKhzTick,
  kCapture,
  kFirmware,  ///< a firmware image on an emulated chip (its own entries are its exceptions)
};
/// "setup()", "loop()", "the frame timer interrupt", …
const char* describe(SketchEntry entry);

/// Why the simulator left a sketch's entry point early.
enum class EscapeCause : uint8_t {
  kNone,
  kRunOver,      ///< the run ended (its duration, or another board stopped it) inside a delay
  kCrashed,      ///< a signal: invalid memory access, abort, arithmetic fault, …
  kEnded,        ///< the sketch called exit(), abort() or their kin
  kHung,         ///< it ran past the wall-clock budget without simulated time moving
  kInterrupted,  ///< Ctrl-C or SIGTERM
};

/// What the simulator knows about the latest escape. Filled before the escape, read after the
/// entry point returned.
struct EscapeRecord {
  static constexpr int kMaxFrames = 48;
  EscapeCause cause = EscapeCause::kNone;
  int detail = 0;      ///< kCrashed, kInterrupted: the signal number; kHung: wall seconds waited
  int end_how = 0;     ///< kEnded: a StepdanceSketchEnd
  int end_status = 0;  ///< kEnded: exit()'s status
  void* frames[kMaxFrames] = {};
  int frame_count = 0;
  /// The interrupted instruction (a crash's faulting one), 0 if not known.
  uintptr_t pc = 0;
};

/// Process-wide record of the sketch entry points now running (innermost last), and requests
/// to stop them. One thread runs every board (the simulator's); the signal handlers and the
/// wall-clock watchdog only read this and set the request flags.
class EntryMonitor {
 public:
  /// Marks one entry of `board` as running while in scope. Context: the simulator's thread.
  class Scope {
   public:
    Scope(SimBoard& board, SketchEntry entry, void (*escape)(int), const CodeRanges* code);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
  };

  /// Entries running now (0: the simulator's own code is running).
  static int depth() { return depth_; }
  static SimBoard* innermost_board();
  static SketchEntry innermost_entry();

  /// Asks the running sketch to stop, for `cause` (kHung or kInterrupted; `detail` as in
  /// EscapeRecord). Async-signal-safe.
  /// The next host call from the sketch escapes (see escape_if_requested), and a signal handler
  /// that finds the sketch's own code running escapes at once (try_escape_from_signal).
  static void request_stop(EscapeCause cause, int detail);
  /// The pending request (kNone if none); cleared by clear_request().
  static EscapeCause requested() { return static_cast<EscapeCause>(requested_.load(std::memory_order_relaxed)); }
  static int requested_detail() { return requested_detail_.load(std::memory_order_relaxed); }
  static void clear_request() { requested_.store(0, std::memory_order_relaxed); }

  /// After an entry returned by itself: if the watchdog asked to stop it (kHung) and the stop
  /// never reached it (the sketch waited in a library call such as sleep(), which the watchdog's
  /// signal cut short, and then returned without calling the simulator), records that stop as
  /// the entry's escape and returns true. Context: the simulator's thread, between entries.
  static bool adopt_unreached_hang();
  /// Called at the start of every host callback: escapes from the innermost entry if a stop was
  /// requested. Context: the simulator's thread, inside a sketch's call to the host.
  static void escape_if_requested();
  /// Escapes from the innermost entry for `cause` (filling the record first). Does not return
  /// while an entry runs; returns at once when none does.
  static void escape(EscapeCause cause);
  /// From a signal handler on the simulator's thread: if a sketch entry runs and `pc` is in its
  /// board's own code, records `cause` (and `signal` as its detail) and escapes; otherwise
  /// returns false.
  /// `anywhere` allows any pc while an entry runs (a crash: there is no going back to it).
  static bool try_escape_from_signal(uintptr_t pc, EscapeCause cause, int signal, bool anywhere);
  /// Fills the latest record's backtrace from the current stack, and `pc` as the interrupted
  /// instruction. Async-signal-safe once prepare_backtrace() has run.
  static void capture_backtrace(uintptr_t pc);
  /// Loads what capture_backtrace() needs, outside any signal handler.
  static void prepare_backtrace();
  /// The latest escape's record; reset by take_record().
  static EscapeRecord take_record();
  /// The sketch ended the program (exit(), abort()): records it. Context: a host callback.
  static void record_sketch_end(int how, int status);

  /// Counts progress: simulated time moved or an entry returned. The watchdog reads it.
  static void note_progress() {
    progress_.store(progress_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }
  static uint64_t progress() { return progress_.load(std::memory_order_relaxed); }

 private:
  struct Running {
    SimBoard* board;
    SketchEntry entry;
    void (*escape)(int);
    const CodeRanges* code;
  };
  static constexpr int kMaxDepth = 16;

  static Running running_[kMaxDepth];
  static volatile std::sig_atomic_t depth_;
  static std::atomic<int> requested_;
  static std::atomic<int> requested_detail_;
  static std::atomic<uint64_t> progress_;
  static EscapeRecord record_;
};

}  // namespace stepdance::sim
