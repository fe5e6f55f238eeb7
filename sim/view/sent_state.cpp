// SentState: a page's last-sent copy of each part of the state.
#include "view/sent_state.hpp"

namespace stepdance::sim::view {

bool SentState::changed(const std::string& key, const nlohmann::json& value) {
  const auto found = sent_.find(key);
  if (found != sent_.end() && found->second == value) return false;
  sent_[key] = value;
  return true;
}

}  // namespace stepdance::sim::view
