// Edge lists as (time, level) pairs, so tests compare and print them without an Edge operator==.
#pragma once

#include <utility>
#include <vector>

#include "common/edges.hpp"

namespace stepdance::sim::test {

using EdgePairs = std::vector<std::pair<SimTime, bool>>;

inline EdgePairs pairs(const EdgeList& edges) {
  EdgePairs out;
  for (const Edge& edge : edges) out.emplace_back(edge.time, edge.level);
  return out;
}

}  // namespace stepdance::sim::test
