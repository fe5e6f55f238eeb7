// SD and File over the manual backend's in-memory storage.
#include <gtest/gtest.h>

#include <string>

#include "SD.h"
#include "arduino_fixture.hpp"

namespace {

class SdTest : public stepdance::test_support::ArduinoFixture {};

std::string read_all(File& file) {
  std::string text;
  while (file.available()) text += static_cast<char>(file.read());
  return text;
}

TEST_F(SdTest, WhatIsPrintedToAFileReadsBack) {
  ASSERT_TRUE(SD.begin(BUILTIN_SDCARD));
  File out = SD.open("log.txt", FILE_WRITE);
  ASSERT_TRUE(out);
  EXPECT_STREQ(out.name(), "log.txt");
  out.print("x=");
  out.println(12.5, 1);
  out.close();
  EXPECT_FALSE(out);
  File in = SD.open("log.txt");
  ASSERT_TRUE(in);
  EXPECT_EQ(in.peek(), 'x');
  EXPECT_EQ(read_all(in), "x=12.5\r\n");
  EXPECT_EQ(in.read(), -1);
  EXPECT_EQ(in.write('z'), 0u);  // opened for reading
}

TEST_F(SdTest, FileWriteAppendsAndFileWriteBeginStartsAfresh) {
  for (const char* line : {"one", "two"}) {
    File out = SD.open("data.txt", FILE_WRITE);
    out.print(line);
    out.close();
  }
  File in = SD.open("data.txt");
  EXPECT_EQ(read_all(in), "onetwo");
  in.close();
  File again = SD.open("data.txt", FILE_WRITE_BEGIN);
  again.print("3");
  again.close();
  in = SD.open("data.txt");
  EXPECT_EQ(read_all(in), "3");
}

TEST_F(SdTest, BlockReadsCrossTheBufferAndStopAtTheEnd) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += static_cast<char>('a' + i % 26);
  File out = SD.open("long.bin", FILE_WRITE);
  EXPECT_EQ(out.write(reinterpret_cast<const uint8_t*>(text.data()), text.size()), 200u);
  out.close();
  File in = SD.open("long.bin");
  char buffer[300] = {};
  EXPECT_EQ(in.read(buffer, 150), 150);
  EXPECT_EQ(in.read(buffer + 150, 150), 50);
  EXPECT_EQ(std::string(buffer, 200), text);
}

TEST_F(SdTest, BadNamesAndModesGiveAClosedFile) {
  EXPECT_FALSE(SD.open(nullptr));
  EXPECT_FALSE(SD.open("x.txt", 7));
  EXPECT_FALSE(SD.open(std::string(80, 'n').c_str(), FILE_WRITE));
  File closed;
  EXPECT_FALSE(closed);
  EXPECT_EQ(closed.read(), -1);
  EXPECT_EQ(closed.available(), 0);
  closed.close();
  EXPECT_FALSE(SD.remove("x.txt"));
}

}  // namespace
