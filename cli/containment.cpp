// Containment: signal handlers and the wall-clock watchdog around a simulation.
#include "containment.hpp"

#include <pthread.h>
#include <signal.h>
#include <ucontext.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "board/host/entry_monitor.hpp"
#include "board/host/sim_board.hpp"
#include "exit_codes.hpp"

namespace stepdance::cli {
namespace {

using sim::EntryMonitor;
using sim::EscapeCause;

constexpr int kCrashSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP};
constexpr int kStopSignals[] = {SIGINT, SIGTERM};
/// The watchdog's nudge to the simulation thread: "look whether the sketch's code is running".
constexpr int kPokeSignal = SIGUSR2;
constexpr auto kWatchPeriod = std::chrono::milliseconds(50);

pthread_t simulation_thread;
/// A stack of its own for the handlers, so a stack overflow in a sketch can be reported.
alignas(16) char handler_stack[1 << 16];
struct sigaction saved_crash[sizeof kCrashSignals / sizeof kCrashSignals[0]];
struct sigaction saved_stop[sizeof kStopSignals / sizeof kStopSignals[0]];
struct sigaction saved_poke;
stack_t saved_stack;

uintptr_t interrupted_pc(void* context) {
  const auto* state = static_cast<const ucontext_t*>(context);
#if defined(__x86_64__)
  return static_cast<uintptr_t>(state->uc_mcontext.gregs[REG_RIP]);
#elif defined(__aarch64__)
  return static_cast<uintptr_t>(state->uc_mcontext.pc);
#else
  (void)state;
  return 0;  // unknown: stops then reach the sketch at its next call into the simulator
#endif
}

bool on_simulation_thread() { return pthread_equal(pthread_self(), simulation_thread) != 0; }

// A crash in a sketch's entry point leaves it (there is no going back into code that faulted);
// anywhere else it is the simulator's own, and ends the process as it would have.
void on_crash(int signal, siginfo_t*, void* context) {
  if (on_simulation_thread() && EntryMonitor::depth() > 0) {
    EntryMonitor::capture_backtrace(interrupted_pc(context));
    EntryMonitor::try_escape_from_signal(interrupted_pc(context), EscapeCause::kCrashed, signal, true);
  }
  ::signal(signal, SIG_DFL);
  raise(signal);
}

void on_stop(int signal, siginfo_t*, void* context) {
  EntryMonitor::request_stop(EscapeCause::kInterrupted, signal);
  if (!on_simulation_thread()) {
    pthread_kill(simulation_thread, kPokeSignal);
    return;
  }
  EntryMonitor::try_escape_from_signal(interrupted_pc(context), EscapeCause::kInterrupted, signal, false);
}

void on_poke(int, siginfo_t*, void* context) {
  const EscapeCause cause = EntryMonitor::requested();
  if (cause == EscapeCause::kNone) return;
  EntryMonitor::try_escape_from_signal(interrupted_pc(context), cause, EntryMonitor::requested_detail(), false);
}

void install(int signal, void (*handler)(int, siginfo_t*, void*), int flags, struct sigaction* saved) {
  struct sigaction action {};
  action.sa_sigaction = handler;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK | flags;
  sigemptyset(&action.sa_mask);
  sigaction(signal, &action, saved);
}

// What the watchdog says when a stop cannot reach the sketch, before it ends the process.
[[noreturn]] void end_process(EscapeCause cause, double waited_s) {
  const sim::SimBoard* board = EntryMonitor::innermost_board();
  std::fprintf(stderr,
               "board '%s': %s could not be stopped within %.0f s (it is inside a system or library call); "
               "ending without writing the outputs\n",
               board != nullptr ? board->name().c_str() : "?", sim::describe(EntryMonitor::innermost_entry()),
               waited_s);
  std::fflush(stderr);
  _exit(cause == EscapeCause::kInterrupted ? 128 + EntryMonitor::requested_detail() : kExitSketchHung);
}

}  // namespace

Containment::Containment(double hang_budget_s, double grace_s) : hang_budget_s_(hang_budget_s), grace_s_(grace_s) {
  simulation_thread = pthread_self();
  EntryMonitor::clear_request();
  EntryMonitor::prepare_backtrace();
  stack_t stack{};
  stack.ss_sp = handler_stack;
  stack.ss_size = sizeof handler_stack;
  sigaltstack(&stack, &saved_stack);
  // SA_NODEFER: an escape jumps out of the handler, so nothing may stay blocked behind it.
  for (size_t i = 0; i < sizeof kCrashSignals / sizeof kCrashSignals[0]; ++i) {
    install(kCrashSignals[i], &on_crash, SA_NODEFER, &saved_crash[i]);
  }
  for (size_t i = 0; i < sizeof kStopSignals / sizeof kStopSignals[0]; ++i) {
    install(kStopSignals[i], &on_stop, SA_NODEFER, &saved_stop[i]);
  }
  install(kPokeSignal, &on_poke, SA_NODEFER, &saved_poke);
  // The watchdog blocks the stop signals, so they reach the simulation thread.
  sigset_t blocked;
  sigset_t previous;
  sigemptyset(&blocked);
  sigaddset(&blocked, SIGINT);
  sigaddset(&blocked, SIGTERM);
  sigaddset(&blocked, kPokeSignal);
  pthread_sigmask(SIG_BLOCK, &blocked, &previous);
  watchdog_ = std::thread([this] { watch(); });
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

Containment::~Containment() {
  done_ = true;
  watchdog_.join();
  for (size_t i = 0; i < sizeof kCrashSignals / sizeof kCrashSignals[0]; ++i)
    sigaction(kCrashSignals[i], &saved_crash[i], nullptr);
  for (size_t i = 0; i < sizeof kStopSignals / sizeof kStopSignals[0]; ++i)
    sigaction(kStopSignals[i], &saved_stop[i], nullptr);
  sigaction(kPokeSignal, &saved_poke, nullptr);
  sigaltstack(&saved_stack, nullptr);
}

// Every 50 ms: has simulated time moved (or an entry returned) while a sketch runs? After the
// budget without, ask it to stop. While a stop is pending and the sketch's code still runs, nudge
// the simulation thread; past the grace period, end the process.
void Containment::watch() {
  using Clock = std::chrono::steady_clock;
  uint64_t last_progress = EntryMonitor::progress();
  Clock::time_point last_change = Clock::now();
  Clock::time_point requested_at{};
  bool pending = false;
  while (!done_) {
    std::this_thread::sleep_for(kWatchPeriod);
    const Clock::time_point now = Clock::now();
    const bool in_sketch = EntryMonitor::depth() > 0;
    const uint64_t progress = EntryMonitor::progress();
    if (progress != last_progress || !in_sketch) {
      last_progress = progress;
      last_change = now;
    }
    if (EntryMonitor::requested() == EscapeCause::kNone && in_sketch &&
        std::chrono::duration<double>(now - last_change).count() >= hang_budget_s_) {
      EntryMonitor::request_stop(EscapeCause::kHung, static_cast<int>(hang_budget_s_ + 0.5));
    }
    const EscapeCause requested = EntryMonitor::requested();
    if (requested == EscapeCause::kNone || !in_sketch) continue;
    if (!pending) {
      pending = true;
      requested_at = now;
    }
    const double waited_s = std::chrono::duration<double>(now - requested_at).count();
    if (waited_s > grace_s_) end_process(requested, waited_s);
    pthread_kill(simulation_thread, kPokeSignal);
  }
}

}  // namespace stepdance::cli
