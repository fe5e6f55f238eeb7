// STEP/DIR wire pairing by name suffix, and wire lookup by full or bare name.
#include "decode/step_dir_pairs.hpp"

#include <cctype>

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

std::vector<StepDirPair> find_step_dir_pairs(const VcdCapture& capture) {
  std::vector<StepDirPair> pairs;
  const std::vector<VcdWire>& wires = capture.wires;
  for (size_t step = 0; step < wires.size(); ++step) {
    if (wires[step].width != 1 || !ends_with_step(wires[step].name)) continue;
    const std::string prefix = wires[step].name.substr(0, wires[step].name.size() - 4);
    for (size_t dir = 0; dir < wires.size(); ++dir) {
      const VcdWire& candidate = wires[dir];
      if (candidate.width != 1 || candidate.scope != wires[step].scope) continue;
      if (candidate.name.size() != prefix.size() + 3 || candidate.name.compare(0, prefix.size(), prefix) != 0) continue;
      if (!iequals(candidate.name.substr(prefix.size()), "DIR")) continue;
      pairs.push_back(StepDirPair{make_label(wires[step], prefix), step, dir});
      break;
    }
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
  std::string all;
  for (const VcdWire& wire : capture.wires) all += (all.empty() ? "" : ", ") + wire.full_name();
  lookup.error = "no wire named '" + name + "' (wires: " + (all.empty() ? "none" : all) + ")";
  return lookup;
}

}  // namespace stepdance::sim
