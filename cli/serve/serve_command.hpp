// `stepdance serve`: a web control page for a board, bridged over WebSocket to its serial line.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace stepdance::cli {

/// Options of `stepdance serve`.
struct ServeCommandOptions {
  std::string target;                        ///< a serial device, or a scenario / example folder
  std::string host = "127.0.0.1";            ///< address to listen on
  std::string port = "8001";                 ///< 0: any free port (announced); checked as ranges::kTcpPort
  std::vector<std::string> allowed_origins;  ///< other web origins that may connect
  std::string baud = "115200";               ///< serial device only; checked as ranges::kBaudRate
  std::string board;                         ///< simulation: the board to bridge (default the first)
  std::string speed;                         ///< simulation: simulated seconds per wall second ("" = 1)
  std::string output_directory;              ///< simulation: write the outputs here instead
  std::string cache_directory;               ///< simulation: compiled sketch cache
  bool unconfined = false;                   ///< sketch server: run the pages' sketches unconfined
};

/// Adds the `serve` subcommand to `app`, filling `options` when it is parsed.
CLI::App& add_serve_command(CLI::App& app, ServeCommandOptions& options);

/// Serves until SIGINT or SIGTERM; a simulation then writes its outputs. Announces
/// `serving http://<host>:<port>/ for <board>` on stdout (flushed) once listening. Returns
/// kExitOk, kExitBadInput (bad options, scenario or sketch) or kExitFailure.
int run_serve_command(const ServeCommandOptions& options);

}  // namespace stepdance::cli
