// STEP/DIR wire pairing by name and wire lookup by full or bare name.
#include <gtest/gtest.h>

#include "decode/step_dir_pairs.hpp"

namespace stepdance::sim {
namespace {

VcdCapture wires_named(const std::vector<std::pair<std::string, std::string>>& names) {
  VcdCapture capture;
  for (const auto& [scope, name] : names) {
    VcdWire wire;
    wire.scope = scope;
    wire.name = name;
    capture.wires.push_back(wire);
  }
  return capture;
}

const VcdCapture kCapture = wires_named({{"driver", "OUT_A_DIR"},
                                         {"driver", "OUT_A_STEP"},
                                         {"driver", "OUT_B_STEP"},
                                         {"basic", "OUT_A_STEP"},
                                         {"basic", "OUT_A_DIR"},
                                         {"", "step"},
                                         {"", "Dir"},
                                         {"analyzer", "STEP"},
                                         {"analyzer", "DIR"},
                                         {"libsigrok", "D0"},
                                         {"libsigrok", "D1"}});

TEST(StepDirPairs, PairsStepWiresWithTheDirOfTheSameScopeAndPrefix) {
  const std::vector<StepDirPair> pairs = find_step_dir_pairs(kCapture);
  ASSERT_EQ(pairs.size(), 4u);
  EXPECT_EQ(pairs[0].label, "driver.OUT_A");
  EXPECT_EQ(pairs[0].step, 1u);
  EXPECT_EQ(pairs[0].dir, 0u);
  EXPECT_EQ(pairs[1].label, "basic.OUT_A");
  EXPECT_EQ(pairs[1].step, 3u);
  EXPECT_EQ(pairs[1].dir, 4u);
  EXPECT_EQ(pairs[2].label, "STEP");
  EXPECT_EQ(pairs[2].step, 5u);
  EXPECT_EQ(pairs[2].dir, 6u);
  EXPECT_EQ(pairs[3].label, "analyzer");
  EXPECT_EQ(pairs[3].step, 7u);
  EXPECT_EQ(pairs[3].dir, 8u);
}

TEST(StepDirPairs, VectorsAreNotPaired) {
  VcdCapture capture = wires_named({{"", "X_STEP"}, {"", "X_DIR"}});
  capture.wires[1].width = 2;
  EXPECT_TRUE(find_step_dir_pairs(capture).empty());
}

TEST(StepDirPairs, FindsWiresByFullOrUniqueBareName) {
  const WireLookup full = find_wire(kCapture, "basic.OUT_A_STEP");
  ASSERT_TRUE(full.ok);
  EXPECT_EQ(full.index, 3u);
  const WireLookup bare = find_wire(kCapture, "D1");
  ASSERT_TRUE(bare.ok);
  EXPECT_EQ(bare.index, 10u);
}

TEST(StepDirPairs, AmbiguousAndUnknownNamesExplainThemselves) {
  const WireLookup ambiguous = find_wire(kCapture, "OUT_A_STEP");
  EXPECT_FALSE(ambiguous.ok);
  EXPECT_EQ(ambiguous.error, "'OUT_A_STEP' is ambiguous: driver.OUT_A_STEP, basic.OUT_A_STEP");
  const WireLookup unknown = find_wire(wires_named({{"libsigrok", "D0"}, {"", "D1"}}), "D2");
  EXPECT_FALSE(unknown.ok);
  EXPECT_EQ(unknown.error, "no wire named 'D2' (wires: libsigrok.D0, D1)");
  EXPECT_EQ(find_wire(VcdCapture{}, "D0").error, "no wire named 'D0' (wires: none)");
}

TEST(StepDirPairs, TwoHundredThousandWiresPairInLinearTime) {
  // 100,000 pairs, DIR declared after its STEP, in reverse order of the STEPs: pairing each STEP
  // by scanning every wire took about a minute; an index makes it one pass (the test runner's
  // timeout is the bound, not a timed assertion).
  constexpr size_t kPairs = 100000;
  std::vector<std::pair<std::string, std::string>> names;
  for (size_t pair = 0; pair < kPairs; ++pair) names.push_back({"wide", "P" + std::to_string(pair) + "_STEP"});
  for (size_t pair = kPairs; pair-- > 0;) names.push_back({"wide", "P" + std::to_string(pair) + "_DIR"});
  const std::vector<StepDirPair> pairs = find_step_dir_pairs(wires_named(names));
  ASSERT_EQ(pairs.size(), kPairs);
  for (size_t pair = 0; pair < kPairs; pair += 9999) {
    EXPECT_EQ(pairs[pair].step, pair);
    EXPECT_EQ(pairs[pair].dir, 2 * kPairs - 1 - pair);  // P<pair>_DIR sits at 2N − 1 − pair
    EXPECT_EQ(pairs[pair].label, "wide.P" + std::to_string(pair));
  }
}

TEST(StepDirPairs, AMissingWireInAWideCaptureListsTheFirstTwenty) {
  std::vector<std::pair<std::string, std::string>> names;
  for (int wire = 0; wire < 25; ++wire) names.push_back({"", "w" + std::to_string(wire)});
  const WireLookup lookup = find_wire(wires_named(names), "nope");
  EXPECT_FALSE(lookup.ok);
  std::string first_twenty;
  for (int wire = 0; wire < 20; ++wire) first_twenty += (wire == 0 ? "w" : ", w") + std::to_string(wire);
  EXPECT_EQ(lookup.error, "no wire named 'nope' (wires: " + first_twenty + " and 5 more)");
}

}  // namespace
}  // namespace stepdance::sim
