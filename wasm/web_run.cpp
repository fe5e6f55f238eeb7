// WebRun: scenario text → Simulation on precompiled boards, run in slices, viewed, finished.
#include "web_run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "assembly/run_result.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::web {

std::unique_ptr<WebRun> WebRun::open(const std::string& path, std::string_view text,
                                     std::shared_ptr<const PrecompiledBoards> boards, std::string& error) {
  const sim::scenario::LoadResult loaded = sim::scenario::parse_scenario(text, path);
  if (!loaded.ok()) {
    error = loaded.error_text();
    return nullptr;
  }
  std::unique_ptr<WebRun> run(new WebRun());
  sim::SimulationOptions options;
  options.boards = std::move(boards);
  options.write_vcd = false;
  WebRun* self = run.get();
  options.console = [self](const std::string& board, const std::string& line) { self->console_line(board, line); };
  sim::SimulationError failure;
  run->simulation_ = sim::Simulation::create(loaded.scenario, options, failure);
  if (!run->simulation_) {
    error = failure.message;
    return nullptr;
  }
  return run;
}

void WebRun::run_until(double end_s) {
  if (result_ || !std::isfinite(end_s)) return;
  const sim::SimTime end_ns = std::min(sim::from_seconds(std::max(end_s, 0.0)), simulation_->duration());
  if (end_ns > simulation_->now()) simulation_->run_until(end_ns);
}

double WebRun::now_s() const { return sim::to_seconds(simulation_->now()); }
double WebRun::duration_s() const { return sim::to_seconds(simulation_->duration()); }
bool WebRun::done() const {
  return result_.has_value() || simulation_->stopped() || simulation_->now() >= simulation_->duration();
}

const std::string& WebRun::finish() {
  if (!result_) {
    try {
      const sim::SimulationReport report = simulation_->finish();
      result_ = sim::run_result_json(*simulation_, report);
    } catch (const std::exception& failure) {
      result_ = nlohmann::json{{"error", failure.what()}}.dump() + "\n";
    }
  }
  return *result_;
}

std::string WebRun::hello() {
  if (!session_) session_ = std::make_unique<sim::view::ViewSession>(*simulation_, control_);
  return session_->hello();
}

std::optional<std::string> WebRun::update(double wall_s) {
  if (!session_) return std::nullopt;
  return session_->update(wall_s);
}

std::string WebRun::update_now() { return session_ ? session_->update_now() : std::string(); }

std::vector<std::string> WebRun::receive(std::string_view text) {
  if (!session_) return {};
  return session_->receive(text);
}

void WebRun::console_line(const std::string& board, const std::string& line) {
  if (!session_) return;
  const std::string text = line + "\n";
  session_->console_output(board, reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

}  // namespace stepdance::web
