// The bridge's pairing: ids rewritten per tab and restored, the in-flight window, per-tab queues,
// errors for bad requests, timeouts, and lines that answer nothing.
#include "serve/request_router.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace stepdance::cli::serve {
namespace {

using nlohmann::json;

class RouterTest : public ::testing::Test {
 protected:
  RequestRouter make(RouterLimits limits = {}) {
    return RequestRouter(
        limits, [this](const std::string& line) { board.push_back(line); },
        [this](ClientId client, const std::string& message) { tabs.emplace_back(client, json::parse(message)); });
  }
  /// The board's side: answers the request `line` with `result` under the id it carried.
  static std::string answer(const std::string& line, const std::string& result) {
    return R"({"result":"ok","return":)" + result + R"(,"id":)" + json::parse(line)["id"].dump() + "}";
  }

  std::vector<std::string> board;
  std::vector<std::pair<ClientId, json>> tabs;
  Clock::time_point t0{};
};

TEST_F(RouterTest, TwoTabsUsingTheSameIdEachGetTheirOwnReply) {
  RequestRouter router = make();
  router.add_client(1);
  router.add_client(2);
  router.from_client(1, R"({"name":"tally","id":1})", t0);
  router.from_client(2, R"({"name":"tally","id":1})", t0);
  ASSERT_EQ(board.size(), 2u);
  const json first = json::parse(board[0]);
  const json second = json::parse(board[1]);
  EXPECT_NE(first["id"], second["id"]);  // the bridge's own ids on the line
  EXPECT_EQ(board[0].back(), '\n');
  router.from_board(answer(board[1], "20"), t0);  // answered out of order
  router.from_board(answer(board[0], "10"), t0);
  ASSERT_EQ(tabs.size(), 2u);
  EXPECT_EQ(tabs[0], std::make_pair(ClientId{2}, json::parse(R"({"result":"ok","return":20,"id":1})")));
  EXPECT_EQ(tabs[1], std::make_pair(ClientId{1}, json::parse(R"({"result":"ok","return":10,"id":1})")));
}

TEST_F(RouterTest, AnyJsonIdComesBackAndNoIdStaysAbsent) {
  RequestRouter router = make();
  router.add_client(1);
  router.from_client(1, R"({"name":"a","id":{"tab":"x","n":[1,2]}})", t0);
  router.from_client(1, R"({"name":"b"})", t0);
  router.from_board(answer(board[0], "1"), t0);
  router.from_board(answer(board[1], "2"), t0);
  ASSERT_EQ(tabs.size(), 2u);
  EXPECT_EQ(tabs[0].second["id"], json::parse(R"({"tab":"x","n":[1,2]})"));
  EXPECT_FALSE(tabs[1].second.contains("id"));
}

TEST_F(RouterTest, BadRequestsAreAnsweredHereWithTheBoardsCodes) {
  RequestRouter router = make();
  router.add_client(1);
  router.from_client(1, "{not json", t0);
  router.from_client(1, R"({"args":[1],"id":4})", t0);
  router.from_client(1, R"({"name":")" + std::string(600, 'x') + R"(","id":5})", t0);
  EXPECT_TRUE(board.empty());
  ASSERT_EQ(tabs.size(), 3u);
  EXPECT_EQ(tabs[0].second["code"], 1);
  EXPECT_EQ(tabs[1].second["code"], 2);
  EXPECT_EQ(tabs[1].second["id"], 4);
  EXPECT_EQ(tabs[2].second["code"], 14);
  EXPECT_EQ(router.counters().refused, 3u);
}

TEST_F(RouterTest, AFloodingTabFillsOnlyItsOwnQueueAndTheOtherTabIsServedNext) {
  RouterLimits limits;
  limits.max_in_flight = 2;
  limits.max_queued_per_client = 5;
  RequestRouter router = make(limits);
  router.add_client(1);
  router.add_client(2);
  for (int i = 0; i < 20; ++i) router.from_client(1, R"({"name":"flood","id":)" + std::to_string(i) + "}", t0);
  // 2 on the line, 5 waiting, 13 refused at once with their ids.
  EXPECT_EQ(board.size(), 2u);
  EXPECT_EQ(router.counters().dropped, 13u);
  ASSERT_EQ(tabs.size(), 13u);
  EXPECT_EQ(tabs.front().second["code"], kBridgeQueueFull);
  EXPECT_EQ(tabs.front().second["id"], 7);
  router.from_client(2, R"({"name":"calm","id":1})", t0);
  router.from_board(answer(board[0], "0"), t0);  // one slot frees: the calm tab goes first
  ASSERT_EQ(board.size(), 3u);
  EXPECT_EQ(json::parse(board[2])["name"], "calm");
}

TEST_F(RouterTest, UnansweredRequestsTimeOutAndFreeTheirSlot) {
  RouterLimits limits;
  limits.max_in_flight = 1;
  RequestRouter router = make(limits);
  router.add_client(1);
  router.from_client(1, R"({"name":"lost","id":"a"})", t0);
  router.from_client(1, R"({"name":"next","id":"b"})", t0);
  EXPECT_EQ(board.size(), 1u);
  router.expire(t0 + limits.reply_timeout - std::chrono::milliseconds(1));
  EXPECT_TRUE(tabs.empty());
  router.expire(t0 + limits.reply_timeout);
  ASSERT_EQ(tabs.size(), 1u);
  EXPECT_EQ(tabs[0].second["code"], kBridgeNoReply);
  EXPECT_EQ(tabs[0].second["id"], "a");
  ASSERT_EQ(board.size(), 2u);
  EXPECT_EQ(json::parse(board[1])["name"], "next");
}

TEST_F(RouterTest, AReplyWithoutIdAnswersTheOldestRequest) {
  RequestRouter router = make();
  router.add_client(1);
  router.from_client(1, R"({"name":"first","id":"one"})", t0);
  router.from_client(1, R"({"name":"second","id":"two"})", t0);
  router.from_board(R"({"result":"error","error":"line too long","code":14})", t0);
  ASSERT_EQ(tabs.size(), 1u);
  EXPECT_EQ(tabs[0].second["id"], "one");
}

TEST_F(RouterTest, OtherBoardLinesGoToEveryTab) {
  RequestRouter router = make();
  router.add_client(1);
  router.add_client(2);
  router.from_board("hello from setup()", t0);
  router.from_board(R"({"event":"fault","level":"warning"})", t0);
  ASSERT_EQ(tabs.size(), 4u);
  EXPECT_EQ(tabs[0].second, json::parse(R"j({"console":"hello from setup()"})j"));
  EXPECT_EQ(tabs[3].second["event"], "fault");
  EXPECT_EQ(router.counters().board_lines, 2u);
}

TEST_F(RouterTest, RepliesForATabThatLeftAreDiscarded) {
  RequestRouter router = make();
  router.add_client(1);
  router.from_client(1, R"({"name":"x","id":1})", t0);
  router.remove_client(1);
  router.from_board(answer(board[0], "1"), t0);
  EXPECT_TRUE(tabs.empty());
}

}  // namespace
}  // namespace stepdance::cli::serve
