// What one page has been sent of the run's state, so that updates carry only what changed.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace stepdance::sim::view {

/// The last value a page was sent of each part of the state (the pen, a motor, a board's
/// figures, a screen…), each under a key of the caller's choosing. An update asks changed() of
/// every part and carries only those that changed: a delta. forget() makes the next update
/// carry everything again (a page that asked for hello, an update that was lost). Memory: one
/// copy of the state's parts, whatever the run's length. Context: the session's thread.
class SentState {
 public:
  /// Whether `value` differs from what was last recorded under `key` (true for a new key);
  /// when it does, records `value` as sent.
  bool changed(const std::string& key, const nlohmann::json& value);
  /// Forgets every part: each one's next changed() is true.
  void forget() { sent_.clear(); }
  /// Parts recorded (tests).
  size_t size() const { return sent_.size(); }

 private:
  std::map<std::string, nlohmann::json> sent_;
};

}  // namespace stepdance::sim::view
