// Block order derived from the BlockPort graph: hand-built graphs, a cycle, and a sketch whose
// blocks are begun consumers first.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/block.hpp"
#include "stepdance/core/block_order.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/motion/scaling_filter.hpp"
#include "stepdance/motion/velocity_generator.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

// A node with one input and one output port, named for the checks.
class Node : public Block {
 public:
  explicit Node(const char* name) : name_(name) {
    input.begin(&in_, BLOCKPORT_INPUT, this);
    output.begin(&out_, BLOCKPORT_OUTPUT, this);
  }
  const char* type_name() const override { return name_; }
  BlockPort input;
  BlockPort output;

 private:
  const char* name_;
  DecimalPosition in_ = 0;
  DecimalPosition out_ = 0;
};

std::vector<std::string> names(Block* const* blocks, size_t count) {
  std::vector<std::string> out;
  for (size_t i = 0; i < count; ++i) out.push_back(blocks[i]->type_name());
  return out;
}

using Names = std::vector<std::string>;

TEST(BlockOrder, ProducersComeBeforeConsumersWhateverTheBeginOrder) {
  Node a("a"), b("b"), c("c");
  a.output.map(&b.input);  // a pushes into b
  c.input.map(&b.output);  // c pulls from b
  Block* blocks[] = {&c, &b, &a};
  char cycle[64];
  ASSERT_TRUE(order_by_graph(blocks, 3, cycle, sizeof(cycle)));
  EXPECT_EQ(names(blocks, 3), (Names{"a", "b", "c"}));
  EXPECT_STREQ(cycle, "");
}

TEST(BlockOrder, IndependentBlocksKeepTheirBeginOrder) {
  Node a("a"), b("b"), c("c"), d("d");
  d.output.map(&b.input);  // only d → b; a and c are free
  Block* blocks[] = {&a, &b, &c, &d};
  char cycle[64];
  ASSERT_TRUE(order_by_graph(blocks, 4, cycle, sizeof(cycle)));
  // Stable: a first (free, begun first); b waits for d; c and d keep their relative order.
  EXPECT_EQ(names(blocks, 4), (Names{"a", "c", "d", "b"}));
}

TEST(BlockOrder, DiamondRunsTheSourceFirstAndTheSinkLast) {
  Node source("source"), left("left"), right("right"), sink("sink");
  source.output.map(&left.input);
  right.input.map(&source.output);
  left.output.map(&sink.input);
  sink.input.map(&right.output);  // the sink's one input peer is right; left still pushes in
  Block* blocks[] = {&sink, &right, &left, &source};
  char cycle[64];
  ASSERT_TRUE(order_by_graph(blocks, 4, cycle, sizeof(cycle)));
  EXPECT_EQ(names(blocks, 4), (Names{"source", "right", "left", "sink"}));
}

TEST(BlockOrder, PortsOfBlocksOutsideTheListAreIgnored) {
  Node a("a"), b("b"), outside("outside");
  b.output.map(&outside.input);
  outside.output.map(&a.input);  // b → outside → a, but outside runs in another stage
  Block* blocks[] = {&a, &b};
  char cycle[64];
  ASSERT_TRUE(order_by_graph(blocks, 2, cycle, sizeof(cycle)));
  EXPECT_EQ(names(blocks, 2), (Names{"a", "b"}));
}

TEST(BlockOrder, ACycleKeepsTheBeginOrderAndNamesItsBlocks) {
  Node a("a"), b("b"), c("c"), free("free");
  a.output.map(&b.input);
  b.output.map(&a.input);  // a ↔ b
  c.input.map(&b.output);  // c after the cycle: cannot be placed either
  Block* blocks[] = {&c, &free, &b, &a};
  char cycle[64];
  EXPECT_FALSE(order_by_graph(blocks, 4, cycle, sizeof(cycle)));
  EXPECT_EQ(names(blocks, 4), (Names{"c", "free", "b", "a"}));
  EXPECT_STREQ(cycle, "cycle, begin() order kept: c, b, a");
}

TEST(BlockOrder, CycleNamesAreTruncatedNotOverrun) {
  Node a("a-long-block-name"), b("b-long-block-name");
  a.output.map(&b.input);
  b.output.map(&a.input);
  Block* blocks[] = {&a, &b};
  char cycle[20];
  EXPECT_FALSE(order_by_graph(blocks, 2, cycle, sizeof(cycle)));
  EXPECT_EQ(std::string(cycle), std::string("cycle, begin() order kept: a").substr(0, 19));
}

TEST(BlockOrder, ADestroyedPortLeavesTheGraph) {
  Node a("a"), b("b");
  {
    Node gone("gone");
    gone.output.map(&a.input);
    a.output.map(&gone.input);
  }
  // a.output still points at a destroyed port: it must not be followed; nothing else links a, b.
  a.output.map(nullptr);
  Block* blocks[] = {&b, &a};
  char cycle[64];
  ASSERT_TRUE(order_by_graph(blocks, 2, cycle, sizeof(cycle)));
  EXPECT_EQ(names(blocks, 2), (Names{"b", "a"}));
}

class BlockOrderEngineTest : public test_support::EngineFixture {};

// Begun consumers first: without derived order the last filter would see the generator's move
// one frame late per hop (0 after the first frame).
TEST_F(BlockOrderEngineTest, ChainBegunBackwardsMovesInTheSameFrame) {
  VelocityGenerator generator;
  ScalingFilter1D doubling;
  ScalingFilter1D tripling;
  ASSERT_EQ(tripling.begin(), Status::kOk);
  ASSERT_EQ(doubling.begin(), Status::kOk);
  ASSERT_EQ(generator.begin(), Status::kOk);
  doubling.input.map(&generator.output);
  tripling.input.map(&doubling.output);
  doubling.set_ratio(2.0);
  tripling.set_ratio(3.0);
  generator.speed_units_per_sec = 1000.0f;  // 0.04 units per 40 µs frame
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(1);
  EXPECT_NEAR(tripling.output.read(ABSOLUTE), 0.04 * 2 * 3, 1e-9);
  hal_manual::run_frames(9);
  EXPECT_NEAR(tripling.output.read(ABSOLUTE), 10 * 0.04 * 2 * 3, 1e-9);
  EXPECT_EQ(warning_count(), 0u);
}

TEST_F(BlockOrderEngineTest, ACycleIsReportedOnceAtStartAndRunsInBeginOrder) {
  ScalingFilter1D first;
  ScalingFilter1D second;
  ASSERT_EQ(first.begin(), Status::kOk);
  ASSERT_EQ(second.begin(), Status::kOk);
  first.input.map(&second.output);
  second.input.map(&first.output);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(100);
  EXPECT_EQ(warning_count(), 1u);
  FaultReport report;
  ASSERT_TRUE(recent_fault_report(0, report));
  EXPECT_EQ(report.reason, FaultReason::kBadConfiguration);
  EXPECT_STREQ(report.detail, "cycle, begin() order kept: ScalingFilter1D, ScalingFilter1D");
  EXPECT_STREQ(report.source, "pre-channel stage registry");
  EXPECT_EQ(fault_reason(), FaultReason::kNone);  // a warning: motion goes on
}

}  // namespace
}  // namespace stepdance
