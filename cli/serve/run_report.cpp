// The reports of runs that ended early, in the page's `file:line: message` form.
#include "serve/run_report.hpp"

#include <string.h>
#include <sys/wait.h>

#include <regex>

#include "exit_codes.hpp"

namespace stepdance::cli::serve {
namespace {

const char* cause_name(sim::EscapeCause cause) {
  switch (cause) {
    case sim::EscapeCause::kCrashed: return "crashed";
    case sim::EscapeCause::kEnded: return "ended";
    case sim::EscapeCause::kHung: return "hung";
    default: return "interrupted";
  }
}

}  // namespace

std::string relative_to(std::string text, const std::string& folder) {
  const std::string prefix = folder + "/";
  for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
    text.erase(at, prefix.size());
  return text;
}

nlohmann::json ended_message(const sim::SketchStop& stop, const std::string& example_folder) {
  // addr2line's "function at /path/Sketch.ino:12" (sketch_builder.cpp), or a frame it could not name.
  static const std::regex kFrame(R"(^(.*) at (\S+):(\d+)(?: \(discriminator \d+\))?$)");
  std::string located;
  std::string frames;
  for (const std::string& frame : stop.backtrace) {
    std::smatch match;
    const std::string text = relative_to(frame, example_folder);
    if (!std::regex_match(text, match, kFrame)) {
      frames += "  " + text + "\n";
      continue;
    }
    const std::string place = match[2].str() + ":" + match[3].str();
    if (located.empty()) located = place;
    frames += place + ": in " + match[1].str() + "\n";
  }
  const std::string head = (located.empty() ? "" : located + ": ") + stop.message() + "\n";
  return {{"type", "ended"}, {"cause", cause_name(stop.cause)}, {"text", head + frames}};
}

int stop_exit_status(const sim::SimulationReport& report) {
  if (!report.sketch_stop) return report.all_expectations_met() ? kExitOk : kExitExpectationFailed;
  switch (report.sketch_stop->cause) {
    case sim::EscapeCause::kHung: return kExitSketchHung;
    case sim::EscapeCause::kCrashed:
    case sim::EscapeCause::kEnded: return kExitSketchFailed;
    default: return kExitExpectationFailed;
  }
}

std::string process_end_text(int status) {
  if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    if (code == kExitSketchHung)
      return "the run's process ended: a sketch hung and could not be stopped (exit status 6)";
    return "the run's process ended with exit status " + std::to_string(code) + " before its result";
  }
  if (!WIFSIGNALED(status)) return "the run's process ended before its result";
  const int signal = WTERMSIG(status);
  std::string why;
  if (signal == SIGXCPU) why = ": it reached its CPU time limit";
  if (signal == SIGXFSZ) why = ": it wrote past the file-size limit (64 MB)";
  if (signal == SIGKILL) why = ": killed (its CPU time limit, memory, or the server ending it)";
  const char* name = sigabbrev_np(signal);
  return std::string("the run's process was ended by SIG") + (name != nullptr ? name : "?") + why;
}

}  // namespace stepdance::cli::serve
