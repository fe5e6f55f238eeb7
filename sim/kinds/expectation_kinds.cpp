// The expectation kind registry: the built-in list plus kinds registered at run time.
#include "kinds/expectation_kinds.hpp"

#include <algorithm>

#include "kinds/kind_registry.hpp"

namespace stepdance::sim {
namespace {

KindRegistry<ExpectationKind>& registry() {
  static KindRegistry<ExpectationKind> kinds(builtin_expectation_kinds());
  return kinds;
}

}  // namespace

bool ExpectationKind::has_key(std::string_view key) const {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

const std::vector<const ExpectationKind*>& expectation_kinds() { return registry().all(); }

const ExpectationKind* find_expectation_kind(std::string_view name) { return registry().find(name); }

void ExpectationRegistry::add(const ExpectationKind& kind) { registry().add(kind); }

void ExpectationRegistry::remove(const ExpectationKind& kind) { registry().remove(kind); }

}  // namespace stepdance::sim
