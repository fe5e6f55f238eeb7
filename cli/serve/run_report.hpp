// What the sketch server tells a page about a run that ended early: a stopped sketch (from the
// child's Containment) or a child process that ended without a result (from its wait status).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "assembly/simulation.hpp"
#include "board/host/sketch_stop.hpp"

namespace stepdance::cli::serve {

/// `text` with every mention of `folder`/ left out, so the page sees the file names it sent.
std::string relative_to(std::string text, const std::string& folder);

/// {"type": "ended", "cause": "crashed"|"ended"|"hung"|"interrupted", "text": lines}: the stop's
/// message at the sketch's line where the backtrace names one ("Sketch.ino:12: board 'b': …"),
/// then one line per frame ("Sketch.ino:12: in setup()"), file names relative to `example_folder`.
nlohmann::json ended_message(const sim::SketchStop& stop, const std::string& example_folder);

/// The exit status `stepdance sim` gives a run with this report (docs/simulator.md).
int stop_exit_status(const sim::SimulationReport& report);

/// One sentence for a child that ended with wait status `status` before its result: a signal
/// named (SIGXCPU: "its CPU time limit", SIGXFSZ: "the file-size limit", SIGKILL: …) or the exit status.
std::string process_end_text(int status);

}  // namespace stepdance::cli::serve
