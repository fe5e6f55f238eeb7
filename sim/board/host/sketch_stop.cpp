// SketchStop: naming what stopped a sketch, and where.
#include "board/host/sketch_stop.hpp"

#include <cxxabi.h>
#include <dlfcn.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "board/abi/board_abi.h"

namespace stepdance::sim {
namespace {

std::string signal_text(int signal) {
  switch (signal) {
    case SIGSEGV: return "SIGSEGV (invalid memory access, or the stack overflowed)";
    case SIGBUS: return "SIGBUS (misaligned or unmapped memory access)";
    case SIGFPE: return "SIGFPE (arithmetic fault: an integer division by zero?)";
    case SIGILL: return "SIGILL (illegal instruction: a function that returns no value?)";
    case SIGABRT: return "SIGABRT (abort from the C++ runtime: an uncaught exception or failed check?)";
    case SIGTRAP: return "SIGTRAP (a trap instruction)";
    case SIGINT: return "interrupted (SIGINT)";
    case SIGTERM: return "terminated (SIGTERM)";
    default: return "signal " + std::to_string(signal);
  }
}

std::string end_text(int how, int status) {
  switch (how) {
    case STEPDANCE_END_EXIT: return "exit(" + std::to_string(status) + ")";
    case STEPDANCE_END_QUICK_EXIT: return "_exit(" + std::to_string(status) + ")";
    default: return "abort()";
  }
}

std::string what_happened(const EscapeRecord& record) {
  switch (record.cause) {
    case EscapeCause::kCrashed: return signal_text(record.detail);
    case EscapeCause::kEnded: return end_text(record.end_how, record.end_status) + " called";
    case EscapeCause::kHung: return "has not returned for " + std::to_string(record.detail) + " s of wall time";
    case EscapeCause::kInterrupted: return signal_text(record.detail);
    case EscapeCause::kRunOver:
    case EscapeCause::kNone: break;
  }
  return "stopped";
}

std::string demangled(const char* name) {
  int status = 0;
  char* readable = abi::__cxa_demangle(name, nullptr, nullptr, &status);
  std::string text = status == 0 && readable != nullptr ? readable : name;
  std::free(readable);
  return text;
}

std::string library_frame_text(void* address) {
  const auto pc = reinterpret_cast<uintptr_t>(address);
  char where[64];
  Dl_info info{};
  if (dladdr(address, &info) == 0 || info.dli_fname == nullptr) {
    std::snprintf(where, sizeof where, "%p", address);
    return where;
  }
  const std::string module = std::filesystem::path(info.dli_fname).filename().string();
  std::snprintf(where, sizeof where, "+0x%lx",
                static_cast<unsigned long>(pc - reinterpret_cast<uintptr_t>(info.dli_fbase)));
  return (info.dli_sname != nullptr ? demangled(info.dli_sname) + " " : std::string()) + "(" + module + where + ")";
}

// The range [first, end) of frames that are the sketch's side of the stack, innermost first:
// from the interrupted instruction (the frames before it are the signal handler's) to the
// sketch's outermost frame in its own code, leaving out the board's entry wrapper
// (EntryGuard::run) and the simulator's frames beyond it.
std::pair<int, int> sketch_frame_range(const EscapeRecord& record, const BoardLibrary* library) {
  int first = 0;
  for (int i = 0; i < record.frame_count; ++i) {
    if (reinterpret_cast<uintptr_t>(record.frames[i]) == record.pc) {
      first = i;
      break;
    }
  }
  int end = record.frame_count;
  if (library == nullptr) return {first, end};
  int last_board_frame = -1;
  for (int i = first; i < record.frame_count; ++i) {
    if (library->code().contains(reinterpret_cast<uintptr_t>(record.frames[i]))) last_board_frame = i;
  }
  if (last_board_frame > first) end = last_board_frame;
  if (last_board_frame == first) end = first + 1;
  return {first, end};
}

// Consecutive equal frames (deep recursion) become one line and a count.
std::vector<std::string> collapse_repeats(const std::vector<std::string>& frames) {
  std::vector<std::string> out;
  int repeats = 0;
  for (const std::string& frame : frames) {
    if (!out.empty() && frame == out.back()) {
      ++repeats;
      continue;
    }
    if (repeats > 0) out.push_back("… the same frame " + std::to_string(repeats) + " more times");
    repeats = 0;
    out.push_back(frame);
  }
  if (repeats > 0) out.push_back("… the same frame " + std::to_string(repeats) + " more times");
  return out;
}

std::vector<std::string> sketch_frames(const EscapeRecord& record, const BoardLibrary* library,
                                       const BoardSource* source) {
  const auto [first, end] = sketch_frame_range(record, library);
  std::vector<uintptr_t> offsets;
  for (int i = first; i < end; ++i) {
    const auto pc = reinterpret_cast<uintptr_t>(record.frames[i]);
    // A return address points after its call, so one byte back is inside the call; the
    // interrupted instruction is itself.
    if (library != nullptr && library->code().contains(pc))
      offsets.push_back(pc - library->load_base() - (i == first ? 0 : 1));
  }
  std::vector<std::string> symbols(offsets.size());
  if (library != nullptr && source != nullptr) symbols = source->symbols(library->path(), offsets);
  symbols.resize(offsets.size());
  std::vector<std::string> frames;
  size_t next_symbol = 0;
  for (int i = first; i < end; ++i) {
    const auto pc = reinterpret_cast<uintptr_t>(record.frames[i]);
    if (library == nullptr || !library->code().contains(pc)) {
      frames.push_back(library_frame_text(record.frames[i]));
      continue;
    }
    char where[48];
    std::snprintf(where, sizeof where, "sketch+0x%lx", static_cast<unsigned long>(offsets[next_symbol]));
    const std::string& symbol = symbols[next_symbol++];
    frames.push_back(symbol.empty() ? std::string(where) : symbol);
  }
  return collapse_repeats(frames);
}

}  // namespace

std::string SketchStop::message() const {
  char at[48];
  std::snprintf(at, sizeof at, " at t = %.6f s", to_seconds(time_ns));
  if (cause == EscapeCause::kHung) return "board '" + board + "': " + describe(entry) + " " + what + at;
  return "board '" + board + "': " + what + " in " + describe(entry) + at;
}

SketchStop describe_stop(const EscapeRecord& record, const std::string& board, SketchEntry entry, SimTime time_ns,
                         const BoardLibrary* library, const BoardSource* source) {
  SketchStop stop;
  stop.cause = record.cause;
  stop.board = board;
  stop.entry = entry;
  stop.time_ns = time_ns;
  stop.what = what_happened(record);
  if (record.cause == EscapeCause::kCrashed) stop.backtrace = sketch_frames(record, library, source);
  return stop;
}

}  // namespace stepdance::sim
