// Serial, SerialUSB1/2 and Serial1..8: which stream backs each, discarding, waiting for room,
// and Serial as a stepdance::ByteStream.
#include <gtest/gtest.h>

#include <string>

#include "arduino_fixture.hpp"

namespace {

using stepdance::arduino_backend::SerialPortId;
using stepdance::arduino_manual::delay_calls;
using stepdance::arduino_manual::feed_serial;
using stepdance::arduino_manual::take_serial_output;
using stepdance::hal_manual::take_console_output;

class SerialPortsTest : public stepdance::test_support::ArduinoFixture {};

TEST_F(SerialPortsTest, SerialIsTheConsole) {
  Serial.begin(115200);
  EXPECT_TRUE(static_cast<bool>(Serial));
  EXPECT_TRUE(Serial.dtr());
  EXPECT_EQ(Serial.print("load: "), 6u);
  EXPECT_EQ(Serial.println(0.25), 6u);
  EXPECT_EQ(take_console_output(), "load: 0.25\r\n");
  EXPECT_EQ(Serial.availableForWrite(), 1 << 20);  // the manual console's room
}

TEST_F(SerialPortsTest, OtherPortsUseTheBackendStreams) {
  SerialUSB1.begin(9600);
  SerialUSB1.println("debug");
  Serial1.print(12, HEX);
  Serial8.write('!');
  EXPECT_EQ(take_serial_output(SerialPortId::kUsb1), "debug\r\n");
  EXPECT_EQ(take_serial_output(SerialPortId::kUart1), "C");
  EXPECT_EQ(take_serial_output(SerialPortId::kUart8), "!");
  EXPECT_EQ(take_console_output(), "");  // nothing leaked onto the console
  feed_serial(SerialPortId::kUart2, "z");
  EXPECT_EQ(Serial2.available(), 1);
  EXPECT_EQ(Serial2.read(), 'z');
  EXPECT_EQ(Serial3.available(), 0);
}

TEST_F(SerialPortsTest, AnUnconnectedPortDiscardsWritesAndHasNothingToRead) {
  stepdance::arduino_manual::set_serial_connected(SerialPortId::kUart3, false);
  EXPECT_EQ(Serial3.print("lost"), 4u);  // reported as written
  EXPECT_EQ(Serial3.available(), 0);
  EXPECT_EQ(Serial3.read(), -1);
  EXPECT_EQ(Serial3.peek(), -1);
  EXPECT_TRUE(static_cast<bool>(Serial3));
  EXPECT_EQ(delay_calls(), 0u);
}

TEST_F(SerialPortsTest, AFullPortWaitsThenDropsTheRest) {
  // Room for 3 bytes: "hel" goes through at once, then the write waits 100 steps of 1 ms of
  // board time for room that never comes and gives up, dropping "lo".
  stepdance::arduino_manual::set_serial_write_space(SerialPortId::kUart4, 3);
  EXPECT_EQ(Serial4.print("hello"), 3u);
  EXPECT_EQ(take_serial_output(SerialPortId::kUart4), "hel");
  EXPECT_EQ(delay_calls(), 100u);
  EXPECT_EQ(stepdance::hal::micros_now(), 100000u);
}

TEST_F(SerialPortsTest, SerialIsAlsoAByteStreamSharingThePeekedByte) {
  stepdance::ByteStream& stream = Serial;
  stepdance::hal_manual::feed_console("qr");
  EXPECT_EQ(Serial.peek(), 'q');
  EXPECT_EQ(stream.bytes_available(), 2u);
  EXPECT_EQ(stream.read_byte(), 'q');
  EXPECT_EQ(Serial.read(), 'r');
  EXPECT_EQ(stream.read_byte(), -1);
  const uint8_t reply[2] = {'o', 'k'};
  EXPECT_EQ(stream.write_bytes(reply, 2), 2u);
  EXPECT_EQ(stream.write_space(), 1u << 20);
  EXPECT_EQ(take_console_output(), "ok");
}

TEST_F(SerialPortsTest, ResetDropsAPeekedByte) {
  stepdance::hal_manual::feed_console("x");
  EXPECT_EQ(Serial.peek(), 'x');
  stepdance::arduino::reset_state();
  EXPECT_EQ(Serial.available(), 0);
  EXPECT_EQ(Serial.read(), -1);
}

}  // namespace
