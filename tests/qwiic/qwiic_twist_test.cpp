// QwiicTwist: every transfer checked against the Qwiic Twist register map (addresses, widths,
// little-endian order), with a register file written here from that map.
#include "stepdance/qwiic/qwiic_twist.hpp"

#include <gtest/gtest.h>

#include <array>
#include <functional>

#include "qwiic/qwiic_fixture.hpp"
#include "support/collector_block.hpp"

namespace stepdance {
namespace {

using Bytes = std::vector<uint8_t>;

// A Twist as its register map describes it: 0x00 ID = 5Ch, 0x01 status, 0x02..03 version,
// 0x04 interrupt enables, 0x05 count (int16 LE), 0x07 difference, 0x09 / 0x0B ms since
// movement / button, 0x0D..0F red green blue, 0x10/12/14 connect (int16 LE), 0x16 timeout,
// 0x18 address. A write's first byte selects the register; later bytes go to the next ones.
// Status as SparkFun's firmware 1.x keeps it: a write replaces the moved (bit 0) and clicked
// (bit 2) bits and leaves the held bit (1) alone; a press toggles held, a release toggles it
// back and sets clicked.
struct FakeTwist {
  static constexpr uint8_t kMoved = 0x01, kHeld = 0x02, kClicked = 0x04;
  std::array<uint8_t, 0x20> registers{};
  std::function<void()> after_status_read;  // the hand, between a poll and the next transfer
  FakeTwist() {
    registers[0x00] = 0x5C;
    registers[0x02] = 1;
    registers[0x03] = 2;
  }
  void set_count(int16_t count) {
    registers[0x05] = static_cast<uint8_t>(count & 0xFF);
    registers[0x06] = static_cast<uint8_t>((count >> 8) & 0xFF);
  }
  void press() { registers[0x01] |= kHeld; }
  void release() { registers[0x01] = static_cast<uint8_t>((registers[0x01] & ~kHeld) | kClicked); }
  void store(uint8_t reg, uint8_t value) {
    if (reg == 0x01) value = static_cast<uint8_t>((registers[0x01] & kHeld) | (value & (kMoved | kClicked)));
    registers[reg] = value;
  }
  hal::I2cResult answer(const hal_manual::I2cRecord& transfer, uint8_t* read, uint16_t read_length) {
    if (transfer.address != 0x3F) return hal::I2cResult::kAddressNack;
    if (transfer.written.empty()) return hal::I2cResult::kOk;
    uint8_t reg = transfer.written[0];
    for (size_t i = 1; i < transfer.written.size(); ++i) store(reg++, transfer.written[i]);
    reg = transfer.written[0];
    for (uint16_t i = 0; i < read_length; ++i) read[i] = registers[reg++];
    if (read_length > 0 && transfer.written[0] == 0x01 && after_status_read) after_status_read();
    return hal::I2cResult::kOk;
  }
};

class QwiicTwistTest : public test_support::QwiicFixture {
 protected:
  void SetUp() override {
    QwiicFixture::SetUp();
    hal_manual::i2c_set_responder(
        [this](const hal_manual::I2cRecord& t, uint8_t* read, uint16_t n) { return fake.answer(t, read, n); });
  }
  // Begins the knob and runs until its first poll has been read.
  void start(QwiicTwist& knob) {
    ASSERT_EQ(knob.begin(QWIIC_1), Status::kOk);
    loop_passes(3);
    ASSERT_EQ(knob.state(), QwiicTwist::State::kReady);
    loop_passes(100);  // 20 ms: the first poll
    ASSERT_GE(knob.polls(), 1u);
  }
  FakeTwist fake;
};

TEST_F(QwiicTwistTest, IdentifiesThenPollsRegisters01Through0C) {
  QwiicTwist knob;
  start(knob);
  const auto& log = hal_manual::i2c_log();
  EXPECT_EQ(log[0].address, 0x3F);
  EXPECT_EQ(log[0].written, Bytes{0x00});  // ID register
  EXPECT_EQ(log[0].read_length, 1);
  EXPECT_EQ(log[1].written, Bytes{0x01});  // status …
  EXPECT_EQ(log[1].read_length, 12);       // … through 0x0C (ms since the button)
  EXPECT_EQ(knob.firmware_version(), 0x0102);
}

TEST_F(QwiicTwistTest, CountsDetentsAcrossThe16BitWrap) {
  QwiicTwist knob;
  fake.set_count(32765);
  start(knob);
  EXPECT_EQ(knob.count(), 0);
  fake.set_count(-32766);  // 32765 → 32767 → −32768 → −32766: five detents forward
  loop_passes(100);
  EXPECT_EQ(knob.count(), 5);
  fake.set_count(32760);  // back over the wrap: −32766 → −32768 → 32767 → 32760 is ten
  loop_passes(100);
  EXPECT_EQ(knob.count(), -5);
}

// Writes to the status register that a poll sent since `before`.
std::vector<Bytes> status_writes(size_t before) {
  std::vector<Bytes> writes;
  for (size_t i = before; i < hal_manual::i2c_log().size(); ++i) {
    const auto& transfer = hal_manual::i2c_log()[i];
    if (transfer.read_length == 0 && !transfer.written.empty() && transfer.written[0] == 0x01)
      writes.push_back(transfer.written);
  }
  return writes;
}

TEST_F(QwiicTwistTest, ClickIsCountedOnceAndItsLatchClearedByWritingStatus) {
  QwiicTwist knob;
  start(knob);
  int callbacks = 0;
  static int* seen = nullptr;
  seen = &callbacks;
  knob.set_callback_on_click([] { ++*seen; });
  fake.registers[0x01] = 0x04 | 0x01;  // clicked, moved, the button up
  const size_t before = hal_manual::i2c_log().size();
  loop_passes(100);
  EXPECT_EQ(knob.clicks(), 1u);
  EXPECT_EQ(callbacks, 1);
  EXPECT_FALSE(knob.pressed());
  EXPECT_EQ(status_writes(before), std::vector<Bytes>{Bytes({0x01, 0x00})});
  EXPECT_EQ(fake.registers[0x01], 0x00);
  loop_passes(100);
  EXPECT_EQ(knob.clicks(), 1u);
}

// The bug: the knob turned with the button held; the poll saw "moved, held"; the button came
// up before the clearing write, whose 0 in the clicked bit wiped the click. No write may go out
// while the poll saw the button held (the release, which sets clicked, may come any moment).
TEST_F(QwiicTwistTest, AClickReleasedBetweenThePollAndTheClearIsCounted) {
  QwiicTwist knob;
  start(knob);
  fake.registers[0x01] = 0x01 | 0x02;  // moved, held
  fake.after_status_read = [this] {
    fake.release();
    fake.after_status_read = nullptr;
  };
  loop_passes(300);  // three polls
  EXPECT_EQ(knob.clicks(), 1u);
  EXPECT_FALSE(knob.pressed());
  EXPECT_EQ(fake.registers[0x01], 0x00);  // cleared once the button was seen up
}

// A click latched while the button is already down again for the next click: counted once at
// once, the latch kept while the button is held, and the release seen later is the second click.
TEST_F(QwiicTwistTest, TwoClicksInOneLatchWhileHeldAreBothCounted) {
  QwiicTwist knob;
  start(knob);
  fake.registers[0x01] = 0x04 | 0x02;  // clicked, held (pressed again)
  const size_t before = hal_manual::i2c_log().size();
  loop_passes(300);
  EXPECT_EQ(knob.clicks(), 1u);
  EXPECT_TRUE(knob.pressed());
  EXPECT_TRUE(status_writes(before).empty());  // nothing cleared under a held button
  fake.release();
  loop_passes(300);
  EXPECT_EQ(knob.clicks(), 2u);
  EXPECT_EQ(fake.registers[0x01], 0x00);
  loop_passes(300);
  EXPECT_EQ(knob.clicks(), 2u);
}

TEST_F(QwiicTwistTest, RegisterWritesFollowTheMap) {
  QwiicTwist knob;
  start(knob);
  const size_t before = hal_manual::i2c_log().size();
  ASSERT_EQ(knob.set_color(10, 20, 30), Status::kOk);
  ASSERT_EQ(knob.connect_color(-1, 2, 0x0304), Status::kOk);
  ASSERT_EQ(knob.enable_interrupts(true, true), Status::kOk);
  ASSERT_EQ(knob.set_turn_interrupt_timeout_ms(0x0250), Status::kOk);
  EXPECT_EQ(knob.set_register_count(0), Status::kFull);  // four are waiting
  loop_passes(20);
  std::vector<Bytes> writes;
  for (size_t i = before; i < hal_manual::i2c_log().size(); ++i) {
    if (hal_manual::i2c_log()[i].read_length == 0) writes.push_back(hal_manual::i2c_log()[i].written);
  }
  ASSERT_EQ(writes.size(), 4u);
  EXPECT_EQ(writes[0], (Bytes{0x0D, 10, 20, 30}));
  EXPECT_EQ(writes[1], (Bytes{0x10, 0xFF, 0xFF, 0x02, 0x00, 0x04, 0x03}));
  EXPECT_EQ(writes[2], (Bytes{0x04, 0x03}));
  EXPECT_EQ(writes[3], (Bytes{0x16, 0x50, 0x02}));
  EXPECT_EQ(fake.registers[0x0E], 20);
}

TEST_F(QwiicTwistTest, SettingTheRegisterCountMovesNothing) {
  QwiicTwist knob;
  fake.set_count(40);
  start(knob);
  fake.set_count(43);
  loop_passes(100);
  ASSERT_EQ(knob.count(), 3);
  ASSERT_EQ(knob.set_register_count(1000), Status::kOk);
  loop_passes(100);
  EXPECT_EQ(knob.count(), 3);
  fake.set_count(998);
  loop_passes(100);
  EXPECT_EQ(knob.count(), 1);
}

TEST_F(QwiicTwistTest, OutputCarriesDetentsIntoTheFrame) {
  QwiicTwist knob;
  test_support::Collector sink;
  start(knob);
  knob.set_ratio(1.0, 24);  // one turn = 1 unit
  sink.begin();
  knob.output.map(&sink.input);
  ASSERT_EQ(dance_start(), Status::kOk);
  fake.set_count(12);
  loop_passes(100);
  hal_manual::run_frames(2);
  EXPECT_DOUBLE_EQ(sink.position, 0.5);
}

TEST_F(QwiicTwistTest, WrongDeviceAndMissingDeviceAreReported) {
  fake.registers[0x00] = 0x42;
  QwiicTwist knob;
  ASSERT_EQ(knob.begin(QWIIC_1), Status::kOk);
  loop_passes(10);
  EXPECT_EQ(knob.state(), QwiicTwist::State::kWrongDevice);
  EXPECT_EQ(hal_manual::take_console_output(),
            "QwiicTwist: QWIIC1 address 63: not a Qwiic Twist (id 66), retrying every second\r\n");
  QwiicTwist absent;
  ASSERT_EQ(absent.begin(QWIIC_1, 0x30), Status::kOk);
  loop_passes(10);
  EXPECT_EQ(absent.state(), QwiicTwist::State::kFailed);
  EXPECT_EQ(absent.last_result(), hal::I2cResult::kAddressNack);
}

}  // namespace
}  // namespace stepdance
