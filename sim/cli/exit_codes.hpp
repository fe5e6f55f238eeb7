// Exit statuses of the `stepdance` command.
#pragma once

namespace stepdance::cli {

/// Everything worked and every expectation held.
constexpr int kExitOk = 0;
/// The simulation ran into a runtime failure (a sketch did not build, an output could not be written).
constexpr int kExitFailure = 1;
/// Bad input: command-line usage, a scenario or capture file that is wrong (`file:line: message`).
constexpr int kExitBadInput = 2;
/// The scenario ran, but one of its [[expect]] checks failed.
constexpr int kExitExpectationFailed = 3;
/// `stepdance decode`: the capture ends mid-stream; what it holds was decoded and reported.
constexpr int kExitTruncatedCapture = 4;

}  // namespace stepdance::cli
