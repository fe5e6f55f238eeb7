// `stepdance decode`: per-axis step counts, rejected pulses and frame statistics of a VCD capture.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace stepdance::cli {

/// Options of `stepdance decode`.
struct DecodeCommandOptions {
  std::string capture_path;
  std::string step_wire;  ///< empty: every *STEP/*DIR pair in the file
  std::string dir_wire;
  std::string mode = "stepdance";      ///< "stepdance" or "step_dir"
  std::string axis = "X";              ///< the signal STEP_DIR pulses count as
  std::string frame_period_us = "40";  ///< the sender's frame period: how pulses group into frames
  bool json = false;
};

/// Adds the `decode` subcommand to `app`, filling `options` when it is parsed.
CLI::App& add_decode_command(CLI::App& app, DecodeCommandOptions& options);

/// Runs the decode and prints the report on stdout; errors go to stderr as `file:line: message`.
/// Returns kExitOk, or kExitBadInput for an unreadable capture or a wire that is not there.
int run_decode_command(const DecodeCommandOptions& options);

}  // namespace stepdance::cli
