// The board's child: the simulation, its link and the channel on one event loop, contained.
#include "serve/board_runner.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <nlohmann/json.hpp>

#include "board/host/entry_monitor.hpp"
#include "containment.hpp"
#include "exit_codes.hpp"
#include "scenario/load_scenario.hpp"
#include "serve/run_channel.hpp"
#include "serve/run_report.hpp"
#include "serve/simulated_board_link.hpp"
#include "simulator_hooks.hpp"

namespace stepdance::cli::serve {
namespace {

namespace net = boost::asio;
using nlohmann::json;

/// A served simulation runs until interrupted; this bounds it (a year of simulated time).
constexpr double kServeDurationS = 365.0 * 86400.0;
/// How often the child looks at the channel and at requests to stop.
constexpr std::chrono::milliseconds kLookPeriod{5};

std::string text_of(const json& message) { return message.dump(-1, ' ', false, json::error_handler_t::replace); }

/// The simulation for the scenario, or null after printing why not (`exit_code` set).
std::unique_ptr<sim::Simulation> make_simulation(const BoardRunnerOptions& options, std::string& board,
                                                 int& exit_code) {
  sim::scenario::LoadResult loaded = sim::scenario::load_scenario(options.scenario);
  if (!loaded.ok()) {
    std::cerr << loaded.error_text();
    exit_code = kExitBadInput;
    return nullptr;
  }
  if (!loaded.scenario.hosts.empty() || !loaded.scenario.expectations.empty()) {
    std::cerr << "serve: the page is the host here: the scenario's [[host]] scripts and [[expect]] checks are "
                 "left out\n";
    loaded.scenario.hosts.clear();
    loaded.scenario.expectations.clear();
  }
  board = options.board.empty() ? loaded.scenario.boards.front().name : options.board;
  sim::SimulationOptions sim_options;
  plug_front_end(sim_options, options.cache_directory);
  sim_options.duration = sim::from_seconds(kServeDurationS);
  sim_options.write_vcd = false;  // hours of interactive use would make it huge
  if (!options.output_directory.empty()) sim_options.output_directory = options.output_directory;
  sim::SimulationError error;
  auto simulation = sim::Simulation::create(loaded.scenario, sim_options, error);
  if (!simulation) {
    std::cerr << error.message << (error.message.empty() || error.message.back() != '\n' ? "\n" : "");
    exit_code = error.kind == sim::SimulationError::kBadInput ? kExitBadInput : kExitFailure;
  }
  return simulation;
}

/// Until the server goes, a stop is asked (SIGTERM through the Containment) or the sketch stops:
/// the server's bytes to the board.
void look(net::steady_timer& timer, RunChannel& channel, SimulatedBoardLink& link, sim::Simulation& simulation,
          net::io_context& io) {
  timer.expires_after(kLookPeriod);
  timer.async_wait([&](const boost::system::error_code& error) {
    if (error) return;
    const bool open = channel.receive(0, [&](std::string_view text) {
      const json message = json::parse(text, nullptr, false);
      if (message.is_object() && message.contains("send") && message["send"].is_string()) link.send(message["send"]);
    });
    if (!open || simulation.stopped() || sim::EntryMonitor::requested() != sim::EscapeCause::kNone) return io.stop();
    look(timer, channel, link, simulation, io);
  });
}

// The end: the outputs written, a stopped sketch reported (stderr and the server), the files named.
int finish(sim::Simulation& simulation, RunChannel& channel) {
  simulation.end_now();
  const sim::SimulationReport report = simulation.finish();
  if (report.sketch_stop) {
    std::ostringstream text;
    text << report.sketch_stop->message() << "\n";
    for (size_t i = 0; i < report.sketch_stop->backtrace.size(); ++i) {
      text << "  #" << i << " " << report.sketch_stop->backtrace[i] << "\n";
    }
    std::cerr << text.str();
    channel.send(
        text_of(json{{"ended", {{"cause", ended_message(*report.sketch_stop, "")["cause"]}, {"text", text.str()}}}}));
  }
  channel.send(text_of(json{{"wrote", report.files}}));
  return stop_exit_status(report);
}

}  // namespace

int run_board_runner(const BoardRunnerOptions& options) {
  RunChannel channel(options.channel_fd);
  try {
    std::string board;
    int exit_code = kExitOk;
    std::unique_ptr<sim::Simulation> simulation = make_simulation(options, board, exit_code);
    if (!simulation) return exit_code;
    net::io_context io;
    SimulatedBoardLink link(io, *simulation, board, options.speed);
    link.on_line([&channel](std::string_view line) { channel.send(text_of(json{{"line", std::string(line)}})); });
    link.on_drawing([&channel](const json& update) { channel.send(text_of(update)); });
    channel.send(text_of(json{{"hello", link.machine_description()}}));
    Containment containment(options.watchdog_s);
    net::steady_timer timer(io);
    look(timer, channel, link, *simulation, io);
    io.run();
    link.stop();
    return finish(*simulation, channel);
  } catch (const std::exception& failure) {
    std::cerr << "serve: " << failure.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace stepdance::cli::serve
