// PtyPort: what the client has not read yet, which the live run waits on (run_live).
#include "pty_port.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdint.h>
#include <unistd.h>

#include <string>

namespace stepdance::cli {
namespace {

TEST(PtyPort, CountsTheBytesTheClientHasNotReadYet) {
  PtyPort port;
  const int client = open(port.path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(client, 0);
  EXPECT_EQ(port.unread_by_client(), 0u);
  const uint8_t reply[] = {'o', 'k', '\r', '\n', 'o', 'k', '\r', '\n'};
  port.write_to_client(reply, sizeof reply);
  // The kernel hands written bytes to the terminal's read queue a moment later.
  for (int i = 0; i < 1000 && port.unread_by_client() < 8u; ++i) usleep(1000);
  EXPECT_EQ(port.unread_by_client(), 8u);
  char got[4];
  ASSERT_EQ(read(client, got, sizeof got), 4);
  EXPECT_EQ(port.unread_by_client(), 4u);
  ASSERT_EQ(read(client, got, sizeof got), 4);
  EXPECT_EQ(port.unread_by_client(), 0u);
  close(client);
}

// The kernel moves bytes written to the master into the terminal's read queue a moment later (a
// work item; on a loaded machine, milliseconds later). A count taken in that moment used to say 0,
// and the live run went on as if the client had read its `ok`s. Every write must count at once.
TEST(PtyPort, CountsBytesJustWrittenAtOnce) {
  PtyPort port;
  const int client = open(port.path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(client, 0);
  const uint8_t reply[] = {'o', 'k', '\r', '\n'};
  int counted_late = 0;
  for (int i = 0; i < 5000; ++i) {
    port.write_to_client(reply, sizeof reply);
    if (port.unread_by_client() != sizeof reply) ++counted_late;
    char got[sizeof reply];
    // The client's read waits for the same kernel work, so it always gets the four bytes.
    ASSERT_EQ(read(client, got, sizeof got), static_cast<ssize_t>(sizeof got));
  }
  EXPECT_EQ(counted_late, 0);
  close(client);
}

// The other way needs no help: a read of the master that finds nothing runs the same kernel work
// before it answers, so a line the client has written is taken at once (docs/gcode.md relies on
// it: the live run never advances past a line it could have read).
TEST(PtyPort, TakesBytesTheClientJustWroteAtOnce) {
  PtyPort port;
  const int client = open(port.path().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(client, 0);
  const char line[] = "G1 X1\n";
  int taken_late = 0;
  for (int i = 0; i < 5000; ++i) {
    ASSERT_EQ(write(client, line, sizeof line - 1), static_cast<ssize_t>(sizeof line - 1));
    std::string taken;
    port.read_from_client(taken, 4096);
    if (taken != line) ++taken_late;
    for (int tries = 0; tries < 1000 && taken.size() < sizeof line - 1; ++tries) port.read_from_client(taken, 4096);
  }
  EXPECT_EQ(taken_late, 0);
  close(client);
}

}  // namespace
}  // namespace stepdance::cli
