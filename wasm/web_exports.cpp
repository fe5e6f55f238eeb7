// The module's C entry points, called from JavaScript (stepdance_sim.js wraps them).
//
// One run at a time per module instance (a Web Worker holds one). Strings returned stay valid
// until the next call; the JavaScript side copies them at once.
#include <emscripten/emscripten.h>

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "scenario/load_scenario.hpp"
#include "web_run.hpp"

namespace {

using stepdance::web::PrecompiledBoards;
using stepdance::web::WebRun;

std::shared_ptr<PrecompiledBoards>& boards() {
  static auto registry = std::make_shared<PrecompiledBoards>();
  return registry;
}
std::unique_ptr<WebRun>& current_run() {
  static std::unique_ptr<WebRun> run;
  return run;
}
std::string& returned() {
  static std::string text;
  return text;
}
const char* give(std::string text) {
  returned() = std::move(text);
  return returned().c_str();
}

}  // namespace

extern "C" {

/// Registers a precompiled board: sketches in folders named `folder_name` load `library_path`.
EMSCRIPTEN_KEEPALIVE void stepdance_web_add_board(const char* folder_name, const char* library_path) {
  boards()->add(folder_name, library_path);
}

/// The sketch folders the scenario `text` (read as the file `path`) runs, as a JSON array of
/// names ("StepASketch"), so the caller fetches only their boards; {"error": …} when the
/// scenario does not read.
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_sketches(const char* path, const char* text) {
  const stepdance::sim::scenario::LoadResult loaded = stepdance::sim::scenario::parse_scenario(text, path);
  if (!loaded.ok()) return give(nlohmann::json{{"error", loaded.error_text()}}.dump());
  nlohmann::json names = nlohmann::json::array();
  for (const auto& board : loaded.scenario.boards) names.push_back(stepdance::web::sketch_folder_name(board.sketch));
  return give(names.dump());
}

/// Loads scenario `text` as the file `path` and builds its simulation, replacing any previous
/// run. Returns "" on success, else the errors (`file:line: message` lines).
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_open(const char* path, const char* text) {
  current_run().reset();
  std::string error;
  current_run() = WebRun::open(path, text, boards(), error);
  return give(current_run() ? std::string() : error);
}

/// Runs to `end_s` seconds of simulated time; returns the time reached (-1 without a run).
EMSCRIPTEN_KEEPALIVE double stepdance_web_run_until(double end_s) {
  if (!current_run()) return -1;
  current_run()->run_until(end_s);
  return current_run()->now_s();
}

/// {"now_s", "duration_s", "done", "paused", "speed"} of the current run ("null" without one).
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_state() {
  const auto& run = current_run();
  if (!run) return give("null");
  return give(nlohmann::json{{"now_s", run->now_s()},
                             {"duration_s", run->duration_s()},
                             {"done", run->done()},
                             {"paused", run->control().paused},
                             {"speed", run->control().speed}}
                  .dump());
}

/// Runs to the end and returns the run's result document (sim/assembly/run_result.hpp).
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_finish() {
  return give(current_run() ? current_run()->finish() : std::string("null"));
}

/// The view protocol (docs/simulator.md, "The view protocol"): the hello message.
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_hello() {
  return give(current_run() ? current_run()->hello() : std::string());
}

/// The update due at wall time `wall_s` (any monotonic origin), or "" if none is due.
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_update(double wall_s) {
  if (!current_run()) return give("");
  return give(current_run()->update(wall_s).value_or(""));
}

/// The update due now, whatever the time.
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_update_now() {
  return give(current_run() ? current_run()->update_now() : std::string());
}

/// A page's message; returns the replies as a JSON array of message texts.
EMSCRIPTEN_KEEPALIVE const char* stepdance_web_receive(const char* text) {
  nlohmann::json replies = nlohmann::json::array();
  if (current_run()) {
    for (std::string& reply : current_run()->receive(text)) replies.push_back(std::move(reply));
  }
  return give(replies.dump());
}

/// Ends the current run (unloading its boards).
EMSCRIPTEN_KEEPALIVE void stepdance_web_close() { current_run().reset(); }

}  // extern "C"
