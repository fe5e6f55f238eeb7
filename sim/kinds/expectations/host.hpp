// Expectation kind "host": host = "board" with reply = "regex" (count, within_ms, after) or
// replies = ["regex", …] in order — the lines a host client received; or completed = true — the
// client ran all its steps without a timeout.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

/// The client's board; the regexes of received lines that must arrive in this order (one regex:
/// at least one such line, or exactly `count`); `within` bounds the time from the first sent line
/// matching `after` (or the client's start) to the first match. Or `completed`.
struct HostCheck {
  std::string board;
  bool completed = false;
  std::vector<std::string> replies;
  std::optional<int64_t> count;
  std::optional<SimTime> within;
  std::string after;
};

const ExpectationKind& host_expectation();

}  // namespace stepdance::sim
