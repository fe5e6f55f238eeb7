// Which Host and Origin headers the bridge accepts.
#include "serve/origin_policy.hpp"

#include <gtest/gtest.h>

namespace stepdance::cli::serve {
namespace {

TEST(OriginPolicy, OnlyThePagesOwnOriginOnLoopbackNames) {
  const OriginPolicy policy("127.0.0.1", 8001, {});
  EXPECT_TRUE(policy.origin_allowed("http://127.0.0.1:8001", "127.0.0.1:8001"));
  EXPECT_TRUE(policy.origin_allowed("http://localhost:8001", "localhost:8001"));
  EXPECT_FALSE(policy.origin_allowed("http://evil.example", "127.0.0.1:8001"));
  EXPECT_FALSE(policy.origin_allowed("http://localhost:8001", "127.0.0.1:8001"));  // not the page's own
  EXPECT_FALSE(policy.origin_allowed("", "127.0.0.1:8001"));                       // no Origin at all
  EXPECT_FALSE(policy.origin_allowed("http://127.0.0.1:8002", "127.0.0.1:8001"));
}

TEST(OriginPolicy, ARebindingHostNameIsRefused) {
  const OriginPolicy policy("127.0.0.1", 8001, {});
  EXPECT_FALSE(policy.host_allowed("attacker.example:8001"));
  EXPECT_FALSE(policy.origin_allowed("http://attacker.example:8001", "attacker.example:8001"));
  EXPECT_FALSE(policy.host_allowed("127.0.0.1:8002"));
  EXPECT_FALSE(policy.host_allowed("127.0.0.1"));
  EXPECT_TRUE(policy.host_allowed("[::1]:8001"));
}

TEST(OriginPolicy, AllowedOriginsAreComparedExactly) {
  const OriginPolicy policy("0.0.0.0", 8001, {"http://192.168.1.5:8001"});
  EXPECT_TRUE(policy.origin_allowed("http://192.168.1.5:8001", "192.168.1.5:8001"));
  EXPECT_FALSE(policy.origin_allowed("http://192.168.1.50:8001", "192.168.1.50:8001"));
  EXPECT_FALSE(policy.host_allowed("0.0.0.0:8001"));
}

}  // namespace
}  // namespace stepdance::cli::serve
