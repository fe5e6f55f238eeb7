// QwiicTwistModel: the register map as SparkFun documents it, driven by turns and clicks.
#include "models/qwiic_twist_model.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "models/i2c_bus.hpp"

namespace stepdance::sim {
namespace {

std::vector<uint8_t> read_registers(QwiicTwistModel& twist, SimTime time, uint8_t first, size_t count) {
  const uint8_t select[] = {first};
  EXPECT_TRUE(twist.write(time, select, 1));
  std::vector<uint8_t> bytes(count);
  twist.read(time, bytes.data(), count);
  return bytes;
}

TEST(QwiicTwistModel, IdVersionAndCountLittleEndian) {
  QwiicTwistModel twist;
  twist.turn(from_seconds(1), -3, from_seconds(0.3));
  const auto before = read_registers(twist, from_seconds(0.5), 0x00, 7);
  EXPECT_EQ(before[0], 0x5C);
  EXPECT_EQ(before[2], 1);
  EXPECT_EQ(before[3], 2);
  EXPECT_EQ(before[5] | (before[6] << 8), 0);
  const auto after = read_registers(twist, from_seconds(2), 0x05, 4);
  EXPECT_EQ(static_cast<int16_t>(after[0] | (after[1] << 8)), -3);  // count
  EXPECT_EQ(static_cast<int16_t>(after[2] | (after[3] << 8)), -3);  // difference
}

TEST(QwiicTwistModel, DetentsSpreadEvenlyOverTheTurn) {
  QwiicTwistModel twist;
  twist.turn(from_seconds(1), 4, from_seconds(1));  // detents at 1.25, 1.5, 1.75, 2.0 s
  EXPECT_EQ(twist.count_at(from_seconds(1.3)), 1);
  EXPECT_EQ(twist.count_at(from_seconds(1.99)), 3);
  EXPECT_EQ(twist.count_at(from_seconds(2)), 4);
}

TEST(QwiicTwistModel, ClickLatchesUntilStatusIsWritten) {
  QwiicTwistModel twist;
  twist.click(from_seconds(1), from_seconds(0.1));
  EXPECT_EQ(read_registers(twist, from_seconds(1.05), 0x01, 1)[0], 0x02);  // held
  EXPECT_EQ(read_registers(twist, from_seconds(1.2), 0x01, 1)[0], 0x04);   // clicked
  const uint8_t clear[] = {0x01, 0x00};
  ASSERT_TRUE(twist.write(from_seconds(1.3), clear, 2));
  EXPECT_EQ(read_registers(twist, from_seconds(1.4), 0x01, 1)[0], 0x00);
}

// SparkFun's firmware 1.x (receiveEvent with its protection map): a status write replaces the
// moved (bit 0) and clicked (bit 2) bits; held (bit 1) follows the button alone.
TEST(QwiicTwistModel, StatusWriteReplacesMovedAndClickedAndLeavesHeld) {
  QwiicTwistModel twist;
  twist.press(from_seconds(1));
  const uint8_t zero[] = {0x01, 0x00};
  ASSERT_TRUE(twist.write(from_seconds(1.1), zero, 2));
  EXPECT_EQ(read_registers(twist, from_seconds(1.2), 0x01, 1)[0], 0x02);  // still held
  twist.release(from_seconds(1.3));
  const uint8_t held_and_moved[] = {0x01, 0x03};
  ASSERT_TRUE(twist.write(from_seconds(1.4), held_and_moved, 2));
  EXPECT_EQ(read_registers(twist, from_seconds(1.5), 0x01, 1)[0], 0x01);  // moved written, clicked cleared, not held
}

TEST(QwiicTwistModel, TimersCountMillisecondsSinceEvents) {
  QwiicTwistModel twist;
  twist.turn(from_seconds(1), 1, 0);
  twist.click(from_seconds(2), from_seconds(0.25));
  const auto timers = read_registers(twist, from_seconds(3), 0x09, 4);
  EXPECT_EQ(timers[0] | (timers[1] << 8), 2000);  // since the detent at 1 s
  EXPECT_EQ(timers[2] | (timers[3] << 8), 750);   // since the release at 2.25 s
}

TEST(QwiicTwistModel, WritesRunOnThroughRegistersAndInterruptFollowsEnables) {
  QwiicTwistModel twist;
  const uint8_t colour[] = {0x0D, 1, 2, 3};
  ASSERT_TRUE(twist.write(0, colour, sizeof colour));
  EXPECT_EQ(twist.register_at(0x0E), 2);
  const uint8_t enable[] = {0x04, 0x01};
  ASSERT_TRUE(twist.write(0, enable, sizeof enable));
  EXPECT_FALSE(twist.interrupt_active());
  twist.turn(from_seconds(1), 1, 0);
  twist.count_at(from_seconds(1));
  EXPECT_TRUE(twist.interrupt_active());
}

TEST(I2cBusModel, WireTimeCountsNineBitsPerByteAndMissingDevicesNack) {
  I2cBusModel bus;
  QwiicTwistModel twist;
  bus.attach(0x3F, &twist);
  const uint8_t select[] = {0x01};
  uint8_t bytes[12];
  SimTime wire_ns = 0;
  // Write 1 then read 12: START, 9 × (1 + 1), repeated START, 9 × (1 + 12), STOP = 138 bits.
  EXPECT_EQ(bus.transfer(0, 400000, 0x3F, select, 1, bytes, 12, &wire_ns), I2cOutcome::kOk);
  EXPECT_EQ(wire_ns, 138 * 2500);
  // A 33-byte write: START, 9 × 34, STOP = 308 bits = 770 µs.
  const std::vector<uint8_t> chunk(33, 0x40);
  EXPECT_EQ(bus.transfer(0, 400000, 0x3F, chunk.data(), chunk.size(), nullptr, 0, &wire_ns), I2cOutcome::kDataNack);
  EXPECT_EQ(wire_ns, 770000);
  EXPECT_EQ(bus.transfer(0, 400000, 0x3C, select, 1, nullptr, 0, &wire_ns), I2cOutcome::kAddressNack);
  EXPECT_EQ(wire_ns, 11 * 2500);
  bus.set_fault(I2cBusFault::kLineHeldLow);
  EXPECT_EQ(bus.transfer(0, 400000, 0x3F, select, 1, nullptr, 0, &wire_ns), I2cOutcome::kBusError);
}

}  // namespace
}  // namespace stepdance::sim
