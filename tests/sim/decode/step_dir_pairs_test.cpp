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

}  // namespace
}  // namespace stepdance::sim
