// Inside a board's shared object: entry points the simulator can leave early (StepdanceBoardV1).
#pragma once

#include <setjmp.h>

namespace stepdance::sim_runtime {

/// How deep entry points may nest: loop() → delay() → a frame tick → … Deeper entries run
/// unguarded (the simulator then cannot leave them early); no sketch comes near.
constexpr int kMaxEntryNesting = 16;

/// Whether the entries that come often (frame and kHz ticks, captured pulses: tens of thousands
/// a simulated second) are guarded too. Not in the WebAssembly build: there every sigsetjmp goes
/// through JavaScript (emscripten 3.1.6's setjmp), which halved the simulation's speed, and only
/// exit() and abort() escape (there is no watchdog thread), so they leave the enclosing guarded
/// entry (loop() or setup() around a delay()) or, outside one, stop the module.
#ifdef __EMSCRIPTEN__
constexpr bool kGuardFrequentEntries = false;
#else
constexpr bool kGuardFrequentEntries = true;
#endif

/// The escape points of the entries now running, innermost last. Context: the simulator's thread.
class EntryGuard {
 public:
  /// Runs `body` as one entry point: returns 0 when it returned, or the code escape() was given.
  template <typename Body>
  static int run(Body body) {
    if (depth_ >= kMaxEntryNesting) {
      body();
      return 0;
    }
    const int level = depth_++;
    // No signal mask is saved (that would be a system call per frame); the host unblocks what a
    // signal handler blocked after an escape through it.
    const int code = sigsetjmp(points_[level], 0);
    if (code == 0) body();
    depth_ = level;
    return code;
  }

  /// Runs `body` as an entry point that comes often: as run() does, or unguarded (returning 0)
  /// where kGuardFrequentEntries says so.
  template <typename Body>
  static int run_frequent(Body body) {
    if constexpr (kGuardFrequentEntries) {
      return run(body);
    } else {
      body();
      return 0;
    }
  }

  /// Leaves the innermost entry with `code` (made non-zero); does nothing outside every entry.
  static void escape(int code);
  /// Entries now running.
  static int depth() { return depth_; }

 private:
  static sigjmp_buf points_[kMaxEntryNesting];
  static volatile int depth_;
};

}  // namespace stepdance::sim_runtime
