// EntryMonitor: the running entries, stop requests and escape records.
#include "board/host/entry_monitor.hpp"

namespace stepdance::sim {

EntryMonitor::Running EntryMonitor::running_[kMaxDepth];
volatile std::sig_atomic_t EntryMonitor::depth_ = 0;
std::atomic<int> EntryMonitor::requested_{0};
std::atomic<int> EntryMonitor::requested_detail_{0};
std::atomic<uint64_t> EntryMonitor::progress_{0};
EscapeRecord EntryMonitor::record_;

const char* describe(SketchEntry entry) {
  switch (entry) {
    case SketchEntry::kSetup: return "setup()";
    case SketchEntry::kLoop: return "loop()";
    case SketchEntry::kFrameTick: return "the frame timer interrupt (the engine and IntervalTimer callbacks)";
    case SketchEntry::kKhzTick: return "the kilohertz timer interrupt (the engine and IntervalTimer callbacks)";
    case SketchEntry::kCapture: return "an input port's capture interrupt";
    case SketchEntry::kFirmware: return "the firmware image";
  }
  return "?";
}

EntryMonitor::Scope::Scope(SimBoard& board, SketchEntry entry, void (*escape)(int), const CodeRanges* code) {
  // Deeper nesting than kMaxDepth cannot happen (a board allows 16 itself); it is not tracked.
  if (depth_ < kMaxDepth) running_[depth_] = Running{&board, entry, escape, code};
  std::atomic_signal_fence(std::memory_order_release);  // a handler that sees the depth sees the entry
  depth_ = depth_ + 1;
}

EntryMonitor::Scope::~Scope() {
  depth_ = depth_ - 1;
  std::atomic_signal_fence(std::memory_order_release);
  note_progress();
}

SimBoard* EntryMonitor::innermost_board() {
  const int depth = depth_;
  return depth > 0 && depth <= kMaxDepth ? running_[depth - 1].board : nullptr;
}

SketchEntry EntryMonitor::innermost_entry() {
  const int depth = depth_;
  return depth > 0 && depth <= kMaxDepth ? running_[depth - 1].entry : SketchEntry::kLoop;
}

void EntryMonitor::request_stop(EscapeCause cause, int detail) {
  requested_detail_.store(detail, std::memory_order_relaxed);
  int expected = 0;
  requested_.compare_exchange_strong(expected, static_cast<int>(cause), std::memory_order_relaxed);
}

void EntryMonitor::escape_if_requested() {
  const EscapeCause cause = requested();
  if (cause == EscapeCause::kNone || depth_ == 0) return;
  record_.detail = requested_detail_.load(std::memory_order_relaxed);
  escape(cause);
}

bool EntryMonitor::adopt_unreached_hang() {
  if (requested() != EscapeCause::kHung) return false;
  record_.cause = EscapeCause::kHung;
  record_.detail = requested_detail_.load(std::memory_order_relaxed);
  return true;
}

void EntryMonitor::escape(EscapeCause cause) {
  const int depth = depth_;
  if (depth == 0 || depth > kMaxDepth) return;
  record_.cause = cause;
  running_[depth - 1].escape(static_cast<int>(cause));
}

bool EntryMonitor::try_escape_from_signal(uintptr_t pc, EscapeCause cause, int signal, bool anywhere) {
  const int depth = depth_;
  if (depth == 0 || depth > kMaxDepth) return false;
  const Running& running = running_[depth - 1];
  if (!anywhere && (running.code == nullptr || !running.code->contains(pc))) return false;
  record_.detail = signal;
  escape(cause);
  return true;
}

EscapeRecord EntryMonitor::take_record() {
  EscapeRecord record = record_;
  record_ = EscapeRecord{};
  return record;
}

void EntryMonitor::record_sketch_end(int how, int status) {
  record_.end_how = how;
  record_.end_status = status;
}

}  // namespace stepdance::sim
