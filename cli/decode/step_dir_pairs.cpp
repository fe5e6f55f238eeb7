// STEP/DIR wire pairing by name suffix, and wire lookup by full or bare name.
#include "decode/step_dir_pairs.hpp"

#include <cctype>
#include <functional>
#include <string_view>
#include <unordered_map>

namespace stepdance::sim {
namespace {

bool iequals(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

bool ends_with_step(const std::string& name) {
  return name.size() >= 4 && iequals(name.substr(name.size() - 4), "STEP");
}

std::string make_label(const VcdWire& step, std::string prefix) {
  while (!prefix.empty() && (prefix.back() == '_' || prefix.back() == '.')) prefix.pop_back();
  if (prefix.empty()) return step.scope.empty() ? "STEP" : step.scope;
  return step.scope.empty() ? prefix : step.scope + "." + prefix;
}

}  // namespace

namespace {

/// The key a *DIR wire is found by: its scope and its name without the suffix (DIR or STEP).
/// Views into the wires: a string per wire would take as much memory again as the names.
struct PairKey {
  std::string_view scope;
  std::string_view prefix;
  bool operator==(const PairKey& other) const { return scope == other.scope && prefix == other.prefix; }
};

PairKey pair_key(const VcdWire& wire, size_t suffix_length) {
  return {wire.scope, std::string_view(wire.name).substr(0, wire.name.size() - suffix_length)};
}

struct PairKeyHash {
  size_t operator()(const PairKey& key) const {
    const std::hash<std::string_view> hash;
    return hash(key.scope) * 31 + hash(key.prefix);
  }
};

}  // namespace

std::vector<StepDirPair> find_step_dir_pairs(const VcdCapture& capture) {
  const std::vector<VcdWire>& wires = capture.wires;
  // One pass indexes the DIR wires (the first of a name wins), one pass pairs: linear in wires.
  std::unordered_map<PairKey, size_t, PairKeyHash> dirs;
  for (size_t dir = 0; dir < wires.size(); ++dir) {
    const VcdWire& wire = wires[dir];
    if (wire.width != 1 || wire.name.size() < 3 || !iequals(wire.name.substr(wire.name.size() - 3), "DIR")) continue;
    dirs.emplace(pair_key(wire, 3), dir);
  }
  std::vector<StepDirPair> pairs;
  for (size_t step = 0; step < wires.size(); ++step) {
    if (wires[step].width != 1 || !ends_with_step(wires[step].name)) continue;
    const auto dir = dirs.find(pair_key(wires[step], 4));
    if (dir == dirs.end()) continue;
    const std::string prefix = wires[step].name.substr(0, wires[step].name.size() - 4);
    pairs.push_back(StepDirPair{make_label(wires[step], prefix), step, dir->second});
  }
  return pairs;
}

WireLookup find_wire(const VcdCapture& capture, const std::string& name) {
  WireLookup lookup;
  for (size_t i = 0; i < capture.wires.size(); ++i) {
    if (capture.wires[i].full_name() == name) {
      lookup.ok = true;
      lookup.index = i;
      return lookup;
    }
  }
  std::string matches;
  size_t count = 0;
  for (size_t i = 0; i < capture.wires.size(); ++i) {
    if (capture.wires[i].name != name) continue;
    if (count++ == 0) lookup.index = i;
    matches += (matches.empty() ? "" : ", ") + capture.wires[i].full_name();
  }
  if (count == 1) {
    lookup.ok = true;
    return lookup;
  }
  if (count > 1) {
    lookup.error = "'" + name + "' is ambiguous: " + matches;
    return lookup;
  }
  constexpr size_t kListed = 20;  // a capture may have thousands of wires
  std::string all;
  for (size_t i = 0; i < capture.wires.size() && i < kListed; ++i) {
    all += (all.empty() ? "" : ", ") + capture.wires[i].full_name();
  }
  if (capture.wires.size() > kListed) all += " and " + std::to_string(capture.wires.size() - kListed) + " more";
  lookup.error = "no wire named '" + name + "' (wires: " + (all.empty() ? "none" : all) + ")";
  return lookup;
}

}  // namespace stepdance::sim
