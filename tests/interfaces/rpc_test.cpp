// RPC as a host sees it: the original's reply format, ids, every error, parameters, blocks, index.
#include "stepdance/interfaces/rpc/rpc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

int hellos = 0;
void hello() { ++hellos; }
double add(double a, double b) { return a + b; }
int8_t small(int8_t value) { return value; }
bool is_positive(float value) { return value > 0; }
const char* echo(const char* text) { return text; }
int sum6(int a, int b, int c, int d, int e, int f) { return a + b + c + d + e + f; }

class RpcTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    hellos = 0;
    ASSERT_EQ(rpc.begin(&host), Status::kOk);
    rpc.enroll("hello", hello);
    rpc.enroll("add", add);
    rpc.enroll("small", small);
    rpc.enroll("is_positive", is_positive);
    rpc.enroll("echo", echo);
    rpc.enroll("sum6", sum6);
    rpc.enroll("gain", gain);
    rpc.enroll("count", count);
    rpc.enroll("armed", armed);
    ASSERT_EQ(tbi.begin(), Status::kOk);
    rpc.enroll("tbi", tbi);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  std::string call(const std::string& line) {
    host.take();
    host.send(line + "\n");
    dance_loop();
    return host.take();
  }

  test_support::FakeByteStream host;
  RPC rpc;
  double gain = 1.5;
  int count = 7;
  bool armed = false;
  TimeBasedInterpolator tbi;
};

TEST_F(RpcTest, RepliesInTheOriginalFormatWithOptionalIds) {
  EXPECT_EQ(call(R"({"name": "hello"})"), "{\"result\":\"ok\"}\r\n");
  EXPECT_EQ(hellos, 1);
  EXPECT_EQ(call(R"({"name":"add","args":[2, 0.5]})"), "{\"result\":\"ok\",\"return\":2.5}\r\n");
  EXPECT_EQ(call(R"({"name":"add","args":[2,3],"id":17})"), "{\"result\":\"ok\",\"return\":5,\"id\":17}\r\n");
  EXPECT_EQ(call(R"({"id":"a\"b","name":"hello","args":[]})"), "{\"result\":\"ok\",\"id\":\"a\\\"b\"}\r\n");
  EXPECT_EQ(call(R"({"name":"is_positive","args":[-1]})"), "{\"result\":\"ok\",\"return\":false}\r\n");
  EXPECT_EQ(call(R"({"name":"echo","args":["pen \"up\""]})"), "{\"result\":\"ok\",\"return\":\"pen \\\"up\\\"\"}\r\n");
  EXPECT_EQ(call(R"({"name":"sum6","args":[1,2,3,4,5,6]})"), "{\"result\":\"ok\",\"return\":21}\r\n");
  EXPECT_EQ(call(""), "");  // blank lines are ignored
}

TEST_F(RpcTest, ParametersReadWithNoArgumentAndWriteWithOne) {
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":1.5}\r\n");
  EXPECT_EQ(call(R"({"name":"gain","args":[-2.25]})"), "{\"result\":\"ok\"}\r\n");
  EXPECT_EQ(gain, -2.25);
  EXPECT_EQ(call(R"({"name":"count","args":[42]})"), "{\"result\":\"ok\"}\r\n");
  EXPECT_EQ(count, 42);
  EXPECT_EQ(call(R"({"name":"armed","args":[true]})"), "{\"result\":\"ok\"}\r\n");
  EXPECT_TRUE(armed);
  EXPECT_EQ(call(R"({"name":"count"})"), "{\"result\":\"ok\",\"return\":42}\r\n");
}

TEST_F(RpcTest, EveryErrorIsAJsonReplyWithACodeAndChangesNothing) {
  auto error = [](int code, const std::string& message, const std::string& id = "") {
    return "{\"result\":\"error\",\"error\":\"" + message + "\",\"code\":" + std::to_string(code) +
           (id.empty() ? "" : ",\"id\":" + id) + "}\r\n";
  };
  EXPECT_EQ(call("{\"name\": \"hello\""), error(1, "malformed JSON request"));
  EXPECT_EQ(call("not json at all"), error(1, "malformed JSON request"));
  EXPECT_EQ(call(R"({"args":[1]})"), error(2, "request has no \\\"name\\\" string"));
  EXPECT_EQ(call(R"({"name":"add","args":[[1],2]})"),
            error(3, "too many arguments, or an argument that is not a number, string, boolean or null"));
  EXPECT_EQ(call(R"({"name":"nothing","id":5})"), error(10, "Unknown Function or Parameter", "5"));
  EXPECT_EQ(call(R"({"name":"add","args":[1]})"), error(11, "wrong number of arguments"));
  EXPECT_EQ(call(R"({"name":"add","args":[1,"two"]})"), error(12, "wrong argument type"));
  EXPECT_EQ(call(R"({"name":"small","args":[300]})"), error(13, "argument out of range"));
  EXPECT_EQ(call(R"({"name":"count","args":[1e20]})"), error(13, "argument out of range"));
  EXPECT_EQ(call(R"({"name":"count","args":[1,2]})"), error(11, "a parameter takes no argument (read) or one (write)"));
  EXPECT_EQ(call("{\"name\":\"hello\",\"args\":[\"" + std::string(600, 'x') + "\"]}"), error(14, "line too long"));
  EXPECT_EQ(count, 7);
  EXPECT_EQ(hellos, 0);
  EXPECT_EQ(call(R"({"name":"hello"})"), "{\"result\":\"ok\"}\r\n");  // and all is well after
}

TEST_F(RpcTest, IndexListsExactlyTheEnrolledNames) {
  const std::string index = call(R"({"name":"__index__","id":1})");
  ASSERT_EQ(index.substr(0, 25), "{\"result\":\"ok\",\"return\":{");
  EXPECT_EQ(index.substr(index.size() - 11), "},\"id\":1}\r\n");
  for (const char* name : {"\"hello\":\"function\"", "\"gain\":\"parameter\"", "\"tbi.add_move\":\"function\"",
                           "\"tbi.speed_override\":\"parameter\"", "\"tbi.output_x.read\":\"function\""}) {
    EXPECT_NE(index.find(name), std::string::npos) << name;
  }
  size_t entries = 0;
  for (size_t at = index.find("\":\""); at != std::string::npos; at = index.find("\":\"", at + 1)) ++entries;
  EXPECT_EQ(entries, rpc.enrolled() + 1);  // each name once, plus "result":"ok"
}

TEST_F(RpcTest, DescribeGivesEachNameItsArgumentAndReturnTypes) {
  const std::string described = call(R"({"name":"__describe__","id":"d"})");
  ASSERT_EQ(described.substr(0, 25), "{\"result\":\"ok\",\"return\":{");
  EXPECT_EQ(described.substr(described.size() - 13), "},\"id\":\"d\"}\r\n");
  // The letters follow the C++ declarations at the top of this file and in the planner's header.
  for (const char* entry : {"\"hello\":\"function - v\"", "\"add\":\"function nn n\"", "\"small\":\"function i i\"",
                            "\"is_positive\":\"function n b\"", "\"echo\":\"function s s\"",
                            "\"sum6\":\"function iiiiii i\"", "\"gain\":\"parameter n\"", "\"count\":\"parameter i\"",
                            "\"armed\":\"parameter b\"", "\"tbi.add_move\":\"function innnnnnn i\"",
                            "\"tbi.output_x.read\":\"function - n\"", "\"tbi.output_x.reset_deep\":\"function n v\""}) {
    EXPECT_NE(described.find(entry), std::string::npos) << entry << " in " << described;
  }
  size_t entries = 0;
  for (size_t at = described.find("\":\""); at != std::string::npos; at = described.find("\":\"", at + 1)) ++entries;
  EXPECT_EQ(entries, rpc.enrolled() + 2);  // each name once, plus "result":"ok" and "id":"d"
}

TEST_F(RpcTest, APlainClientNeverSeesAnEvent) {
  EXPECT_EQ(call(R"({"name":"hello"})"), "{\"result\":\"ok\"}\r\n");
  gain = 9.0;
  report_fault(FaultLevel::kWarning, FaultReason::kRefused, "test", "a refusal");
  for (int pass = 0; pass < 5; ++pass) {
    hal_manual::advance_us(RPC::kMinEventIntervalUs);
    dance_loop();
  }
  EXPECT_EQ(host.take(), "");
}

TEST_F(RpcTest, ASubscribedValueIsSentNowAndWhenItChanges) {
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":["gain"],"id":5})"),
            "{\"result\":\"ok\",\"id\":5}\r\n{\"event\":\"changed\",\"name\":\"gain\",\"value\":1.5}\r\n");
  hal_manual::advance_us(RPC::kMinEventIntervalUs);
  dance_loop();
  EXPECT_EQ(host.take(), "");  // unchanged: nothing
  gain = 2.25;
  dance_loop();
  EXPECT_EQ(host.take(), "{\"event\":\"changed\",\"name\":\"gain\",\"value\":2.25}\r\n");
  gain = 3.0;  // within kMinEventIntervalUs of the last event: held back, then sent
  dance_loop();
  EXPECT_EQ(host.take(), "");
  hal_manual::advance_us(RPC::kMinEventIntervalUs);
  dance_loop();
  EXPECT_EQ(host.take(), "{\"event\":\"changed\",\"name\":\"gain\",\"value\":3}\r\n");
  EXPECT_EQ(call(R"({"name":"__unsubscribe__","args":["gain"]})"), "{\"result\":\"ok\"}\r\n");
  gain = 4.0;
  hal_manual::advance_us(RPC::kMinEventIntervalUs);
  dance_loop();
  EXPECT_EQ(host.take(), "");
}

TEST_F(RpcTest, FaultEventsGoOnlyToAHostThatAskedForThem) {
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":["__faults__"]})"), "{\"result\":\"ok\"}\r\n");
  report_fault(FaultLevel::kWarning, FaultReason::kRefused, "test", "a refusal");
  dance_loop();  // delivers the report to the RPC
  dance_loop();
  EXPECT_EQ(host.take(), "{\"event\":\"fault\",\"level\":\"" + std::string(to_string(FaultLevel::kWarning)) +
                             "\",\"reason\":\"" + to_string(FaultReason::kRefused) +
                             "\",\"source\":\"test\",\"detail\":\"a refusal\",\"sequence\":1}\r\n");
  EXPECT_EQ(call(R"({"name":"__unsubscribe__"})"), "{\"result\":\"ok\"}\r\n");
  report_fault(FaultLevel::kWarning, FaultReason::kRefused, "test", "another");
  dance_loop();
  dance_loop();
  EXPECT_EQ(host.take(), "");
}

TEST_F(RpcTest, OnlyParametersAndReadersCanBeSubscribed) {
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":["hello"],"id":1})"),
            "{\"result\":\"error\",\"error\":\"not a parameter or reader\",\"code\":15,\"id\":1}\r\n");
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":["nope"],"id":2})"),
            "{\"result\":\"error\",\"error\":\"Unknown Function or Parameter\",\"code\":10,\"id\":2}\r\n");
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":[1],"id":3})"),
            "{\"result\":\"error\",\"error\":\"wrong argument type\",\"code\":12,\"id\":3}\r\n");
  EXPECT_EQ(hellos, 0);  // refusing it did not call it
  // A port's read is a reader; the table holds kMaxSubscriptions names.
  const char* readers[] = {"gain",
                           "count",
                           "armed",
                           "tbi.output_x.read",
                           "tbi.output_y.read",
                           "tbi.output_z.read",
                           "tbi.speed_override",
                           "tbi.slots_remaining"};
  static_assert(sizeof(readers) / sizeof(readers[0]) == RPC::kMaxSubscriptions);
  for (const char* name : readers) {
    const std::string reply = call(std::string(R"({"name":"__subscribe__","args":[")") + name + R"("]})");
    EXPECT_EQ(reply.substr(0, 17), "{\"result\":\"ok\"}\r\n") << name << ": " << reply;
  }
  EXPECT_EQ(call(R"({"name":"__subscribe__","args":["tbi.output_e.read"],"id":4})"),
            "{\"result\":\"error\",\"error\":\"too many subscriptions\",\"code\":16,\"id\":4}\r\n");
}

TEST_F(RpcTest, BlocksAreCallableByTheirDottedNames) {
  EXPECT_EQ(call(R"({"name":"tbi.add_move","args":[1, 50, 10, 0, 0, 0, 0, 0]})"),
            "{\"result\":\"ok\",\"return\":127}\r\n");  // the planner's slots left
  EXPECT_EQ(call(R"({"name":"tbi.is_idle"})"), "{\"result\":\"ok\",\"return\":false}\r\n");
  for (int i = 0; i < 25000; ++i) {
    dance_loop();
    hal_manual::run_frames(1);
  }
  EXPECT_EQ(call(R"({"name":"tbi.output_x.read"})"), "{\"result\":\"ok\",\"return\":10}\r\n");
  EXPECT_EQ(call(R"({"name":"tbi.speed_override","args":[0.5]})"), "{\"result\":\"ok\"}\r\n");
  EXPECT_EQ(static_cast<float>(tbi.speed_overide), 0.5f);
}

TEST_F(RpcTest, NumbersComeBackWithNineSignificantDigits) {
  gain = 0.1;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":0.1}\r\n");
  gain = -1234.5678;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":-1234.5678}\r\n");
  gain = 0.000012345;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":1.2345e-5}\r\n");
  gain = 2.5e20;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":2.5e20}\r\n");
  gain = 1.0 / 3.0;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":0.333333333}\r\n");
}

TEST_F(RpcTest, EveryNumberComesBackAsAJsonNumber) {
  // Fractions from 10^9 up were sent as `ovf`, and numbers below 10^-307 with a broken mantissa
  // (the smallest double as `infe-324`). Whole digits are kept from 10^9 up (rounded half away
  // from zero, as below 10^9); below 0.001 nine significant digits with an exponent.
  gain = 1234567890.25;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":1234567890}\r\n");
  gain = -12345678901234.5;
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":-12345678901235}\r\n");
  gain = 4.9406564584124654e-324;  // the smallest subnormal double, 2^-1074
  EXPECT_EQ(call(R"({"name":"gain"})"), "{\"result\":\"ok\",\"return\":4.94065646e-324}\r\n");
  // Every magnitude: a JSON number that reads back within half a unit of the ninth digit.
  const std::regex json_number(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE]-?[0-9]+)?)");
  for (int power = -320; power <= 300; power += 7) {
    for (double mantissa : {1.0, 1.23456789012, -4.4444444449, 9.99999999}) {
      gain = mantissa * std::pow(10.0, power);
      const std::string reply = call(R"({"name":"gain"})");
      const std::string prefix = "{\"result\":\"ok\",\"return\":";
      ASSERT_EQ(reply.substr(0, prefix.size()), prefix) << gain;
      const std::string number = reply.substr(prefix.size(), reply.size() - prefix.size() - 3);
      EXPECT_TRUE(std::regex_match(number, json_number)) << gain << " -> " << number;
      const double back = std::strtod(number.c_str(), nullptr);
      EXPECT_LE(std::fabs(back - gain), 5.0001e-9 * std::fabs(gain) + 4.95e-324) << gain << " -> " << number;
    }
  }
}

// A Channel enrolls the names the original's Channel::enroll gives it, with the original's
// argument types: set_ratio(float, float), set_upper/lower_limit(DecimalPosition),
// disable/enable_upper/lower…, enable_filtering(uint16_t), the parameter current_position and
// the ports input_target_position and input_target_position2 (sic).
class RpcChannelTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(rpc.begin(&host), Status::kOk);
    ASSERT_EQ(channel.begin(), Status::kOk);
    rpc.enroll("channel_a", channel);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  std::string call(const std::string& line) {
    host.take();
    host.send(line + "\n");
    dance_loop();
    return host.take();
  }

  test_support::FakeByteStream host;
  RPC rpc;
  Channel channel;
};

TEST_F(RpcChannelTest, EnrollsTheOriginalsNamesWithTheirSignatures) {
  std::string describe;
  host.send("{\"name\":\"__describe__\"}\n");
  for (int pass = 0; pass < 8; ++pass) dance_loop();
  describe = host.take();
  const std::string expected =
      "{\"result\":\"ok\",\"return\":{"
      "\"channel_a.set_ratio\":\"function nn v\","
      "\"channel_a.set_upper_limit\":\"function n v\","
      "\"channel_a.set_lower_limit\":\"function n v\","
      "\"channel_a.disable_upper_limit\":\"function - v\","
      "\"channel_a.disable_lower_limit\":\"function - v\","
      "\"channel_a.disable\":\"function - v\","
      "\"channel_a.enable\":\"function - v\","
      "\"channel_a.disable_filtering\":\"function - v\","
      "\"channel_a.enable_filtering\":\"function i v\","
      "\"channel_a.current_position\":\"parameter n\","
      "\"channel_a.input_target_position.read\":\"function - n\","
      "\"channel_a.input_target_position.read_deep\":\"function - n\","
      "\"channel_a.input_target_position.reset_deep\":\"function n v\","
      "\"channel_a.input_target_position2.read\":\"function - n\","
      "\"channel_a.input_target_position2.read_deep\":\"function - n\","
      "\"channel_a.input_target_position2.reset_deep\":\"function n v\""
      "}}\r\n";
  EXPECT_EQ(describe, expected);
  EXPECT_EQ(rpc.enroll_failures(), 0u);
}

TEST_F(RpcChannelTest, TheOriginalsSpellingEnrollsTheSameNames) {
  RPC other;
  channel.enroll(&other, "channel_b");  // as the original's Plugin::enroll(RPC*, name)
  EXPECT_EQ(other.enrolled(), 16u);
  EXPECT_EQ(other.enrolled(), rpc.enrolled());
}

TEST_F(RpcChannelTest, TheCallsActOnTheChannel) {
  const std::string ok = "{\"result\":\"ok\"}\r\n";
  EXPECT_EQ(call(R"({"name":"channel_a.set_ratio","args":[1, 80]})"), ok);    // 80 steps/mm
  EXPECT_EQ(call(R"({"name":"channel_a.set_upper_limit","args":[1]})"), ok);  // 1 mm = 80 steps
  channel.input_target_position.write(2.0, ABSOLUTE);                         // 160 steps away, one step per frame
  hal_manual::run_frames(300);
  EXPECT_EQ(call(R"({"name":"channel_a.current_position"})"), "{\"result\":\"ok\",\"return\":80}\r\n");
  EXPECT_EQ(call(R"({"name":"channel_a.disable_upper_limit"})"), ok);
  hal_manual::run_frames(300);
  EXPECT_EQ(call(R"({"name":"channel_a.current_position"})"), "{\"result\":\"ok\",\"return\":160}\r\n");
  EXPECT_EQ(call(R"({"name":"channel_a.input_target_position.read"})"), "{\"result\":\"ok\",\"return\":2}\r\n");

  EXPECT_EQ(call(R"({"name":"channel_a.disable"})"), ok);  // a disabled channel does not step
  channel.input_target_position.write(0.0, ABSOLUTE);
  hal_manual::run_frames(300);
  EXPECT_EQ(static_cast<double>(channel.current_position), 160.0);
  EXPECT_EQ(call(R"({"name":"channel_a.enable"})"), ok);
  hal_manual::run_frames(300);
  EXPECT_EQ(static_cast<double>(channel.current_position), 0.0);

  EXPECT_EQ(call(R"({"name":"channel_a.set_lower_limit","args":[-0.5]})"), ok);  // −40 steps
  channel.input_target_position.write(-1.0, ABSOLUTE);
  hal_manual::run_frames(300);
  EXPECT_EQ(static_cast<double>(channel.current_position), -40.0);
  EXPECT_EQ(call(R"({"name":"channel_a.disable_lower_limit"})"), ok);
  hal_manual::run_frames(300);
  EXPECT_EQ(static_cast<double>(channel.current_position), -80.0);

  EXPECT_EQ(call(R"({"name":"channel_a.current_position","args":[5]})"), ok);
  EXPECT_EQ(static_cast<double>(channel.current_position), 5.0);
  EXPECT_EQ(call(R"({"name":"channel_a.enable_filtering","args":[65536]})"),
            "{\"result\":\"error\",\"error\":\"argument out of range\",\"code\":13}\r\n");  // a uint16_t
  EXPECT_EQ(call(R"({"name":"channel_a.enable_filtering","args":[4]})"), ok);
  EXPECT_EQ(call(R"({"name":"channel_a.disable_filtering"})"), ok);
  EXPECT_EQ(call(R"({"name":"channel_a.input_target_position2.read"})"), "{\"result\":\"ok\",\"return\":0}\r\n");
}

TEST(RpcRegistry, OverflowIsRefusedCountedAndReported) {
  test_support::reset_global_state();
  RPC rpc;
  static double value = 0;
  char name[16];
  for (size_t i = 0; i < RPC::kMaxEntries + 3; ++i) {
    snprintf(name, sizeof name, "v%u", static_cast<unsigned>(i));  // newlib-nano has no %zu
    rpc.enroll(static_cast<const char*>(name), value);
  }
  EXPECT_EQ(rpc.enrolled(), RPC::kMaxEntries);
  EXPECT_EQ(rpc.enroll_failures(), 3u);
  EXPECT_EQ(warning_count(), 3u);
  test_support::reset_global_state();
}

}  // namespace
}  // namespace stepdance
