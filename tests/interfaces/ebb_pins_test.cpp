// PD, PO, PI, PC and PG as EBB firmware 2.8 documents them (evil-mad/EggBot docs/ebb.html), and
// the motor-enable query the AxiDraw software makes with PI (plotink ebb_motion.query_enable_motors).
#include <gtest/gtest.h>

#include <string>

#include "interfaces/ebb_test_host.hpp"

namespace stepdance {
namespace {

class EbbPinsTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(ebb.begin(&link), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  std::string exchange(const std::string& text) { return host.exchange(text); }
  void settle() {
    for (int i = 0; i < 10; ++i) host.step();
  }

  /// plotink's query_enable_motors, restated: PI,E,0 and PI,C,1 read the active-low enables,
  /// PI,E,2 / PI,E,1 / PI,A,6 read MS1 / MS2 / MS3; the result is in EM's numbering (0 = off,
  /// 1 = 1/16 … 5 = full step). It splits each reply at "PI," and strips the line ending.
  std::pair<int, int> query_enable_motors() {
    auto level = [this](const char* query) {
      const std::string reply = host.send_and_read_line(query);  // PI has no OK line
      const size_t at = reply.find("PI,");
      EXPECT_NE(at, std::string::npos) << reply;
      std::string value = reply.substr(at + 3);
      while (!value.empty() && (value.back() == '\r' || value.back() == '\n')) value.pop_back();
      return value;
    };
    const bool enable_1 = level("PI,E,0\r") == "0";
    const bool enable_2 = level("PI,C,1\r") == "0";
    const bool ms_1 = level("PI,E,2\r") == "1";
    const bool ms_2 = level("PI,E,1\r") == "1";
    const bool ms_3 = level("PI,A,6\r") == "1";
    int resolution = 5;
    if (ms_1 && ms_2 && ms_3) {
      resolution = 1;
    } else if (ms_1 && ms_2) {
      resolution = 2;
    } else if (ms_2) {
      resolution = 3;
    } else if (ms_1) {
      resolution = 4;
    }
    return {enable_1 ? resolution : 0, enable_2 ? resolution : 0};
  }

  test_support::FakeByteStream link;
  Eibotboard ebb;
  test_support::EbbHost host{link};
};

TEST_F(EbbPinsTest, TheAxiDrawSoftwareReadsTheMotorEnablesAndResolutionWithPi) {
  EXPECT_EQ(query_enable_motors(), std::make_pair(0, 0));  // power-on: drivers off
  for (int mode = 1; mode <= 5; ++mode) {
    SCOPED_TRACE(mode);
    ASSERT_EQ(exchange("EM," + std::to_string(mode) + "," + std::to_string(mode) + "\r"), "OK\r\n");
    settle();
    EXPECT_EQ(query_enable_motors(), std::make_pair(mode, mode));
  }
  ASSERT_EQ(exchange("EM,2,0\r"), "OK\r\n");  // 1/8, motor 2 off
  settle();
  EXPECT_EQ(query_enable_motors(), std::make_pair(2, 0));
  ASSERT_EQ(exchange("EM,0,1\r"), "OK\r\n");  // motor 1 off, the mode stays 1/8
  settle();
  EXPECT_EQ(query_enable_motors(), std::make_pair(0, 2));
  ASSERT_EQ(exchange("SM,10,5,5\r"), "OK\r\n");  // "motor movement commands … enable both motors"
  for (int i = 0; i < 400; ++i) host.step();
  EXPECT_EQ(query_enable_motors(), std::make_pair(2, 2));
  ASSERT_EQ(exchange("ES,1\r"), "0\n\rOK\r\n");  // ES,1 disables both drivers
  settle();
  EXPECT_EQ(query_enable_motors(), std::make_pair(0, 0));
}

TEST_F(EbbPinsTest, PiRepliesInBothSyntaxesWithoutOk) {
  // "Response (legacy mode; default): PI,Value<CR><NL>", "(future mode): PI,Value<NL>".
  EXPECT_EQ(exchange("PI,E,0\r"), "PI,1\r\n");  // motor 1 disabled: its enable pin is high
  EXPECT_EQ(exchange("pi,e,0\r"), "PI,1\r\n");  // case-insensitive, port letter included
  ASSERT_EQ(exchange("CU,10,1\r"), "\n");
  EXPECT_EQ(exchange("PI,E,0\r"), "PI,1\n");
  EXPECT_EQ(exchange("PO,B,3,1\r"), "PO\n");
  EXPECT_EQ(exchange("PD,B,3,0\r"), "PD\n");
  EXPECT_EQ(exchange("PC,100,150\r"), "PC\n");
  EXPECT_EQ(exchange("PI,B\r"), "PI,!4 Err: Missing parameter(s)\n");
}

TEST_F(EbbPinsTest, OutputPinsReadBackWhatPoWroteOnceTheyAreOutputs) {
  // The AxiDraw software's B3 output (use_b3_out): PO,B,3,state then PD,B,3,0, then PO.
  EXPECT_EQ(exchange("PO,B,3,1\r"), "OK\r\n");
  EXPECT_EQ(exchange("PI,B,3\r"), "PI,0\r\n");  // "PO … will not change a pin's direction"
  EXPECT_EQ(exchange("PD,B,3,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("PI,B,3\r"), "PI,1\r\n");
  EXPECT_EQ(exchange("PO,B,3,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("PI,B,3\r"), "PI,0\r\n");
  EXPECT_EQ(exchange("PO,C,7,1\r"), "OK\r\n");  // the documentation's examples
  EXPECT_EQ(exchange("PD,C,7,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("PI,C,7\r"), "PI,1\r\n");
  EXPECT_EQ(exchange("PD,C,7,1\r"), "OK\r\n");  // an input again: nothing drives it
  EXPECT_EQ(exchange("PI,C,7\r"), "PI,0\r\n");
  EXPECT_EQ(exchange("R\r"), "OK\r\n");  // reset: every pin an input again
  settle();
  EXPECT_EQ(exchange("PI,B,3\r"), "PI,0\r\n");
}

TEST_F(EbbPinsTest, ThePenPinsFollowThePenAsExecuted) {
  // RB4, the pen-lift solenoid output, is high while the pen is down; RB1 carries the servo's
  // pulses and reads low between them.
  EXPECT_EQ(exchange("PI,B,4\r"), "PI,0\r\n");
  ASSERT_EQ(exchange("SP,0\r"), "OK\r\n");
  settle();
  EXPECT_EQ(exchange("PI,B,4\r"), "PI,1\r\n");
  EXPECT_EQ(exchange("PI,B,1\r"), "PI,0\r\n");
  ASSERT_EQ(exchange("SP,1\r"), "OK\r\n");
  settle();
  EXPECT_EQ(exchange("PI,B,4\r"), "PI,0\r\n");
}

TEST_F(EbbPinsTest, BadPinCommandsGetTheDocumentedErrorsAndChangeNothing) {
  EXPECT_EQ(exchange("PI,F,0\r"), "!6 Err: Invalid parameter value\r\n");    // ports A … E
  EXPECT_EQ(exchange("PI,B,8\r"), "!6 Err: Invalid parameter value\r\n");    // pins 0 … 7
  EXPECT_EQ(exchange("PO,B,3,2\r"), "!6 Err: Invalid parameter value\r\n");  // value 0 or 1
  EXPECT_EQ(exchange("PD,B,3,2\r"), "!6 Err: Invalid parameter value\r\n");  // direction 0 or 1
  EXPECT_EQ(exchange("PI,B\r"), "!4 Err: Missing parameter(s)\r\n");
  EXPECT_EQ(exchange("PO,B,3\r"), "!4 Err: Missing parameter(s)\r\n");
  EXPECT_EQ(exchange("PI,BB,3\r"), "!5 Err: Need comma next, found: 'B'\r\n");
  EXPECT_EQ(exchange("PC,100\r"), "!4 Err: Missing parameter(s)\r\n");  // Length0 and Period0 required
  EXPECT_EQ(exchange("PC,70000,1\r"), "!6 Err: Invalid parameter value\r\n");
  EXPECT_EQ(exchange("PC,12,123,0,0,2000,10000\r"), "OK\r\n");  // the documentation's example
  EXPECT_EQ(exchange("PG,1\r"), "OK\r\n");
  EXPECT_EQ(exchange("PG,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("PD,B,3,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("PI,B,3\r"), "PI,0\r\n");  // the refused PO,B,3,2 wrote nothing
}

}  // namespace
}  // namespace stepdance
