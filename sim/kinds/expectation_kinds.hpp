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

/// The run-time side of the list: a test adds its own kind with a ScopedKind<ExpectationRegistry>.
struct ExpectationRegistry {
  using Kind = ExpectationKind;
  static void add(const ExpectationKind& kind);
  static void remove(const ExpectationKind& kind);
};

}  // namespace stepdance::sim
