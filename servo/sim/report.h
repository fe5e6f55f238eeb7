// report.h: prints each failed check of the simavr harness and counts them for the exit status.
#pragma once

#include <iostream>
#include <string>

namespace servo_sim {

class Report {
 public:
  // Starts a named group of checks (one scenario).
  void begin(const std::string& scenario) {
    scenario_ = scenario;
    std::cout << "[ RUN      ] " << scenario << '\n';
  }

  // Ends the current scenario, printing whether all of its checks passed.
  void end() {
    std::cout << (scenario_failures_ == 0 ? "[       OK ] " : "[  FAILED  ] ") << scenario_ << '\n';
    scenario_failures_ = 0;
  }

  // Records a failure unless expected == actual.
  template <typename T>
  bool equal(const std::string& what, T expected, T actual) {
    if (expected == actual) {
      return true;
    }
    fail(what + ": expected " + std::to_string(expected) + ", got " + std::to_string(actual));
    return false;
  }

  // Records a failure with detail unless condition holds.
  bool that(const std::string& what, bool condition, const std::string& detail = "") {
    if (!condition) {
      fail(detail.empty() ? what : what + ": " + detail);
    }
    return condition;
  }

  void fail(const std::string& message) {
    std::cout << "  FAIL " << scenario_ << ": " << message << '\n';
    ++scenario_failures_;
    ++total_failures_;
  }

  int failures() const { return total_failures_; }

 private:
  std::string scenario_;
  int scenario_failures_ = 0;
  int total_failures_ = 0;
};

}  // namespace servo_sim
