// The `stepdance` command: simulate scenarios, decode captures, serve a web control page.
#include <CLI/CLI.hpp>

#include "decode_command.hpp"
#include "exit_codes.hpp"
#include "serve/board_runner.hpp"
#include "serve/serve_command.hpp"
#include "serve/sketch_runner.hpp"
#include "sim_command.hpp"
#include "usage.hpp"
#include "view/live_view_server.hpp"

int main(int argc, char** argv) {
  using namespace stepdance::cli;
  CLI::App app{"Stepdance host tools: run sketches on simulated boards, decode motion-stream captures."};
  app.require_subcommand(1);
  add_version_flag(app);
  SimCommandOptions sim;
  sim.make_view = [](stepdance::sim::Simulation& simulation, uint16_t port) -> std::unique_ptr<LiveView> {
    return std::make_unique<LiveViewServer>(simulation, port);
  };
  CLI::App& sim_command = add_sim_command(app, sim);
  DecodeCommandOptions decode;
  CLI::App& decode_command = add_decode_command(app, decode);
  ServeCommandOptions serve;
  CLI::App& serve_command = add_serve_command(app, serve);
  // The sketch server's child (serve/sketch_runner.hpp): not for people, so not in the help.
  serve::SketchRunnerOptions runner;
  CLI::App& runner_command = *app.add_subcommand("run-sketch", "")->group("");
  runner_command.add_option("--folder", runner.folder)->required();
  runner_command.add_option("--example", runner.example)->required();
  runner_command.add_option("--scenario", runner.scenario)->required();
  runner_command.add_option("--watchdog-s", runner.watchdog_s);
  runner_command.add_option("--cache", runner.cache_directory);
  runner_command.add_flag("--unconfined", runner.unconfined);
  // `stepdance serve <scenario>`'s board child (serve/board_runner.hpp), not in the help either.
  serve::BoardRunnerOptions board_runner;
  CLI::App& board_command = *app.add_subcommand("run-board", "")->group("");
  board_command.add_option("--scenario", board_runner.scenario)->required();
  board_command.add_option("--board", board_runner.board);
  board_command.add_option("--speed", board_runner.speed);
  board_command.add_option("--out", board_runner.output_directory);
  board_command.add_option("--cache", board_runner.cache_directory);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return report_parse_error(app, error, argc, argv);
  }
  if (sim_command.parsed()) return run_sim_command(sim);
  if (decode_command.parsed()) return run_decode_command(decode);
  if (serve_command.parsed()) return run_serve_command(serve);
  if (runner_command.parsed()) return serve::run_sketch_runner(runner);
  if (board_command.parsed()) return serve::run_board_runner(board_runner);
  return kExitBadInput;
}
