// The `stepdance` command: simulate scenarios, decode captures, serve a web control page.
#include <CLI/CLI.hpp>

#include "decode_command.hpp"
#include "exit_codes.hpp"
#include "serve/serve_command.hpp"
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return report_parse_error(app, error, argc, argv);
  }
  if (sim_command.parsed()) return run_sim_command(sim);
  if (decode_command.parsed()) return run_decode_command(decode);
  if (serve_command.parsed()) return run_serve_command(serve);
  return kExitBadInput;
}
