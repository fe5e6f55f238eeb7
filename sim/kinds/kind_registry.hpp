// A list of kinds (device kinds, machine kinds): the built-in ones in order, then any registered
// at run time; looked up by their `type` name.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stepdance::sim {

/// Kinds with a `name` member. Context: host, single thread.
template <typename Kind>
class KindRegistry {
 public:
  explicit KindRegistry(std::vector<const Kind*> builtin) : kinds_(std::move(builtin)) {}

  const std::vector<const Kind*>& all() const { return kinds_; }

  /// The kind with this name, or null.
  const Kind* find(std::string_view name) const {
    for (const Kind* kind : kinds_) {
      if (kind->name == name) return kind;
    }
    return nullptr;
  }

  /// "\"a\", \"b\" or \"c\"", for the message of an unknown type.
  std::string names() const {
    std::string text;
    for (size_t i = 0; i < kinds_.size(); ++i) {
      if (i > 0) text += i + 1 == kinds_.size() ? " or " : ", ";
      text += "\"" + std::string(kinds_[i]->name) + "\"";
    }
    return text;
  }

  void add(const Kind& kind) { kinds_.push_back(&kind); }
  void remove(const Kind& kind) { kinds_.erase(std::remove(kinds_.begin(), kinds_.end(), &kind), kinds_.end()); }

 private:
  std::vector<const Kind*> kinds_;
};

}  // namespace stepdance::sim
