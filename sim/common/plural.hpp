// Counted nouns for messages: "1 pulse", "2 pulses".
#pragma once

#include <cstdint>
#include <string>

namespace stepdance::sim {

/// "<count> <singular>" for 1, else "<count> <plural>". Context: any.
inline std::string counted(uint64_t count, const std::string& singular, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

}  // namespace stepdance::sim
