// The run's token in a WebSocket upgrade's URL (the live view), and none needed without one (serve).
#include "serve/web_server.hpp"

#include <gtest/gtest.h>

namespace stepdance::cli::serve {
namespace {

WebServerContent with_token(const std::string& token) {
  WebServerContent content;
  content.token = token;
  return content;
}

TEST(WebServerToken, TheUpgradeMustCarryTheRunsTokenExactly) {
  boost::asio::io_context io;
  const WebServer server(io, "127.0.0.1", 0, {}, {}, with_token("0123abcd"));
  EXPECT_TRUE(server.token_allowed("/ws?token=0123abcd"));
  EXPECT_TRUE(server.token_allowed("/ws?x=1&token=0123abcd"));
  EXPECT_FALSE(server.token_allowed("/ws"));
  EXPECT_FALSE(server.token_allowed("/ws?token="));
  EXPECT_FALSE(server.token_allowed("/ws?token=0123abc"));    // a prefix
  EXPECT_FALSE(server.token_allowed("/ws?token=0123abcde"));  // longer
  EXPECT_FALSE(server.token_allowed("/ws?xtoken=0123abcd"));
}

TEST(WebServerToken, WithoutATokenEveryUpgradeTargetPasses) {
  boost::asio::io_context io;
  const WebServer server(io, "127.0.0.1", 0, {}, {});
  EXPECT_TRUE(server.token_allowed("/ws"));
  EXPECT_EQ(server.content().find_asset, &find_web_asset);
}

}  // namespace
}  // namespace stepdance::cli::serve
