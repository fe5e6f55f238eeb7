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
/// A sketch crashed (a signal in its code) or ended the program (exit(), abort()): the run
/// stopped there, its outputs were written and its expectations were not checked.
constexpr int kExitSketchFailed = 5;
/// A sketch ran past the watchdog's wall-clock budget without simulated time moving.
constexpr int kExitSketchHung = 6;
/// A batch run cut short by SIGINT or SIGTERM exits with 128 + the signal's number (130, 143),
/// after writing its outputs.
constexpr int kExitSignalBase = 128;

}  // namespace stepdance::cli
