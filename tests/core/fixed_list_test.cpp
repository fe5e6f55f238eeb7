// FixedList: inline capacity, insertion order, refusal when full, order-keeping removal.
#include <gtest/gtest.h>

#include <vector>

#include "stepdance/core/fixed_list.hpp"

namespace stepdance {
namespace {

template <typename List>
std::vector<int> contents(const List& list) {
  return std::vector<int>(list.begin(), list.end());
}

template <typename List>
void fill(List& list, std::vector<int> values) {
  for (int value : values) ASSERT_EQ(list.push_back(value), Status::kOk) << value;
}

TEST(FixedList, StartsEmpty) {
  FixedList<int, 4> list;
  EXPECT_TRUE(list.empty());
  EXPECT_FALSE(list.full());
  EXPECT_EQ(list.size(), 0u);
  EXPECT_EQ(list.begin(), list.end());
  EXPECT_FALSE(list.contains(0));
}

TEST(FixedList, CapacityIsTheTemplateArgument) {
  EXPECT_EQ((FixedList<int, 1>::capacity()), 1u);
  EXPECT_EQ((FixedList<int, 4>::capacity()), 4u);
  EXPECT_EQ((FixedList<int, 48>::capacity()), 48u);
}

TEST(FixedList, KeepsInsertionOrder) {
  FixedList<int, 4> list;
  fill(list, {30, 10, 20});
  EXPECT_EQ(contents(list), (std::vector<int>{30, 10, 20}));
  EXPECT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0], 30);
  EXPECT_EQ(list[2], 20);
  EXPECT_TRUE(list.contains(10));
  EXPECT_FALSE(list.contains(40));
}

TEST(FixedList, FullListRefusesAndKeepsItsContents) {
  FixedList<int, 3> list;
  fill(list, {1, 2, 3});
  EXPECT_TRUE(list.full());
  EXPECT_EQ(list.push_back(4), Status::kFull);
  EXPECT_EQ(list.push_back(5), Status::kFull);
  EXPECT_EQ(list.size(), 3u);
  EXPECT_EQ(contents(list), (std::vector<int>{1, 2, 3}));
  EXPECT_FALSE(list.contains(4));
}

TEST(FixedList, CapacityOneHoldsExactlyOne) {
  FixedList<int, 1> list;
  EXPECT_EQ(list.push_back(7), Status::kOk);
  EXPECT_EQ(list.push_back(8), Status::kFull);
  EXPECT_EQ(contents(list), std::vector<int>{7});
}

TEST(FixedList, RemoveKeepsTheOrderOfTheRest) {
  FixedList<int, 5> list;
  fill(list, {1, 2, 3, 4, 5});
  EXPECT_TRUE(list.remove(3));  // middle
  EXPECT_EQ(contents(list), (std::vector<int>{1, 2, 4, 5}));
  EXPECT_TRUE(list.remove(1));  // first
  EXPECT_EQ(contents(list), (std::vector<int>{2, 4, 5}));
  EXPECT_TRUE(list.remove(5));  // last
  EXPECT_EQ(contents(list), (std::vector<int>{2, 4}));
  EXPECT_FALSE(list.remove(9));  // absent
  EXPECT_EQ(contents(list), (std::vector<int>{2, 4}));
  EXPECT_FALSE(list.full());
}

TEST(FixedList, RemoveTakesOnlyTheFirstEqualElement) {
  FixedList<int, 4> list;
  fill(list, {7, 8, 7, 9});
  EXPECT_TRUE(list.remove(7));
  EXPECT_EQ(contents(list), (std::vector<int>{8, 7, 9}));
}

TEST(FixedList, RoomFreedByRemoveCanBeReused) {
  FixedList<int, 3> list;
  fill(list, {1, 2, 3});
  EXPECT_TRUE(list.remove(2));
  EXPECT_EQ(list.push_back(4), Status::kOk);
  EXPECT_EQ(contents(list), (std::vector<int>{1, 3, 4}));
  EXPECT_EQ(list.push_back(5), Status::kFull);
}

TEST(FixedList, ClearEmptiesAndAllowsRefill) {
  FixedList<int, 2> list;
  fill(list, {1, 2});
  list.clear();
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(list.size(), 0u);
  EXPECT_FALSE(list.contains(1));
  fill(list, {3, 4});
  EXPECT_EQ(contents(list), (std::vector<int>{3, 4}));
}

TEST(FixedList, HoldsPointers) {
  int a = 0, b = 0, c = 0;
  FixedList<int*, 3> list;
  ASSERT_EQ(list.push_back(&a), Status::kOk);
  ASSERT_EQ(list.push_back(&b), Status::kOk);
  ASSERT_EQ(list.push_back(&c), Status::kOk);
  EXPECT_TRUE(list.remove(&b));
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], &a);
  EXPECT_EQ(list[1], &c);
}

}  // namespace
}  // namespace stepdance
