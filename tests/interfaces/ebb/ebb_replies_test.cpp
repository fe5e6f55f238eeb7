// EbbReplies on its own: the two syntaxes and the error lines, byte for byte as ebb-protocol.md
// "Framing" gives them (legacy "OK\r\n", future "<CMD>[,data]\n", "SM,!4 Err: Missing parameter(s)").
#include <gtest/gtest.h>

#include <string>

#include "stepdance/interfaces/ebb/ebb_replies.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance::ebb {
namespace {

class EbbRepliesTest : public ::testing::Test {
 protected:
  std::string flushed() {
    replies.flush(link);
    return link.take();
  }

  EbbReplies replies;
  test_support::FakeByteStream link;
};

TEST_F(EbbRepliesTest, LegacyOkDataAndEndingsAreTheEbbsOwn) {
  replies.set_command("QP");
  replies.ok();
  EXPECT_EQ(flushed(), "OK\r\n");
  replies.data("1", true, "\n\r");  // QP's legacy line ends LF CR, then its OK line
  EXPECT_EQ(flushed(), "1\n\rOK\r\n");
  replies.data("EBB", false);
  EXPECT_EQ(flushed(), "EBB\r\n");
  replies.set_acks(false);  // CU,1,0: the OK line becomes a bare line ending
  replies.ok();
  replies.data("7", true);
  EXPECT_EQ(flushed(), "\r\n7\r\n\r\n");
}

TEST_F(EbbRepliesTest, FutureSyntaxNamesTheCommandInEveryReply) {
  ASSERT_TRUE(replies.switch_syntax(true));
  EXPECT_EQ(flushed(), "\n");  // CU,10,1 answers its own half in the new syntax
  replies.set_command("SM");
  replies.ok();
  EXPECT_EQ(flushed(), "SM\n");
  replies.error(EbbError::kMissing);
  EXPECT_EQ(flushed(), "SM,!4 Err: Missing parameter(s)\n");  // ebb-protocol.md's own example
  replies.set_command("QS");
  replies.data("12,-3", true, "\n\r");  // neither the legacy ending nor an OK in this syntax
  EXPECT_EQ(flushed(), "QS,12,-3\n");
  EXPECT_TRUE(replies.future_syntax());
}

TEST_F(EbbRepliesTest, SwitchingBackAnswersHalfInEachSyntaxAndSwitchingToTheSameDoesNothing) {
  replies.set_command("CU");
  EXPECT_FALSE(replies.switch_syntax(false));  // already legacy: the caller replies OK itself
  EXPECT_EQ(flushed(), "");
  ASSERT_TRUE(replies.switch_syntax(true));
  EXPECT_FALSE(replies.switch_syntax(true));
  flushed();
  ASSERT_TRUE(replies.switch_syntax(false));
  EXPECT_EQ(flushed(), "CUOK\r\n");
  replies.reset();
  EXPECT_FALSE(replies.future_syntax());
  EXPECT_TRUE(replies.acks());
}

TEST_F(EbbRepliesTest, EveryErrorLineAndItsCount) {
  replies.set_command("XM");
  replies.error(EbbError::kRateTooHigh, '2');
  replies.error(EbbError::kNeedComma, 'x');
  replies.error(EbbError::kInvalid);
  replies.error(EbbError::kExtra);
  replies.error(EbbError::kAlarm);
  EXPECT_EQ(flushed(),
            "!0 Err: <axis2> step rate too high\r\n"
            "!5 Err: Need comma next, found: 'x'\r\n"
            "!6 Err: Invalid parameter value\r\n"
            "!7 Err: Extra parameter\r\n"
            "!9 Err: Alarm raised: motor moves refused until it is cleared\r\n");
  EXPECT_EQ(replies.errors(), 5u);
}

// 'Z' is 0x5A and 'q' 0x71 (ASCII): the echo shows each byte of the name in hex.
TEST_F(EbbRepliesTest, AnUnknownCommandIsEchoedWithItsBytesInHex) {
  replies.set_command("Zq");
  replies.error(EbbError::kUnknownCommand);
  EXPECT_EQ(flushed(), "!8 Err: Unknown command 'Zq:5A71'\r\n");
  ASSERT_TRUE(replies.switch_syntax(true));
  flushed();
  replies.set_command("");  // an overlong line has no command to name
  replies.error(EbbError::kOverrun);
  EXPECT_EQ(flushed(), "!3 Err: RX Buffer overrun\n");
}

TEST_F(EbbRepliesTest, ParameterErrorsAreRepliedOnlyWhenThereIsOne) {
  replies.set_command("SC");
  EbbParameters good(",4,100", 6);
  int64_t value = 0;
  good.integer(0, 255, true, value);
  good.integer(0, 65535, true, value);
  ASSERT_TRUE(good.finish());
  EXPECT_FALSE(replies.parameter_error(good));
  EbbParameters extra(",4,100,9", 8);
  extra.integer(0, 255, true, value);
  extra.integer(0, 65535, true, value);
  extra.finish();
  EXPECT_TRUE(replies.parameter_error(extra));
  EXPECT_EQ(flushed(), "!7 Err: Extra parameter\r\n");
  EXPECT_EQ(replies.errors(), 1u);
}

// A command is taken only while its largest reply (160 bytes) fits in the 512-byte ring: with 400
// bytes waiting for a slow host, 112 are left and the next line must wait.
TEST_F(EbbRepliesTest, TheLargestReplyMustFitBeforeALineIsTaken) {
  EXPECT_TRUE(replies.reserve_largest());
  const std::string block(100, 'x');
  for (int i = 0; i < 4; ++i) replies.send(block.c_str());
  EXPECT_FALSE(replies.reserve_largest());
  link.write_room = 48;  // the host takes 48 bytes: 160 free now
  replies.flush(link);
  EXPECT_TRUE(replies.reserve_largest());
  EXPECT_EQ(replies.dropped(), 0u);
}

}  // namespace
}  // namespace stepdance::ebb
