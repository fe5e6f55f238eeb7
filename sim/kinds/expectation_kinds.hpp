// The expectation kinds: the built-in ones in the order messages list them, then any registered
// at run time (a test's own kind).
#pragma once

#include <string_view>
#include <vector>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

/// Every expectation kind, built-in first. Context: host, single thread.
const std::vector<const ExpectationKind*>& expectation_kinds();
/// The kind whose check key is `name`, or null.
const ExpectationKind* find_expectation_kind(std::string_view name);

/// The built-in kinds, in order (kinds/builtin_expectation_kinds.cpp: one line per kind).
std::vector<const ExpectationKind*> builtin_expectation_kinds();

/// Adds a kind for as long as it lives (a test's kind); the kind must outlive it.
class ScopedExpectationKind {
 public:
  explicit ScopedExpectationKind(const ExpectationKind& kind);
  ~ScopedExpectationKind();
  ScopedExpectationKind(const ScopedExpectationKind&) = delete;
  ScopedExpectationKind& operator=(const ScopedExpectationKind&) = delete;

 private:
  const ExpectationKind& kind_;
};

}  // namespace stepdance::sim
