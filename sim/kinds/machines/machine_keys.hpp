// Readers of keys several machine kinds share.
#pragma once

#include "scenario/table_reader.hpp"

namespace stepdance::sim {

/// Reads a number in (0, 10^6] `unit` into `target` (kept when absent or wrong).
inline void read_positive(scenario::TableReader& reader, std::string_view key, const char* unit, double& target) {
  if (const auto value = reader.number(key, scenario::NumberRange{0, 1000000, true, unit})) target = *value;
}

}  // namespace stepdance::sim
