// The scripted host client with lines far longer than any protocol sends: the board echoes a
// 25,001-byte line, the client waits for it with a pattern that libstdc++'s regex matcher runs by
// one recursion per character matched. Whole, such a line overflowed the stack (a crash before
// the fix); in 1,000-byte pieces it is matched, and the transcript holds every byte in order with
// each piece but the last marked.
#include <algorithm>
#include <string>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

constexpr size_t kLineBytes = 25001;
constexpr size_t kPieceBytes = 1000;

std::string long_line() { return std::string(kLineBytes, 'b'); }

std::string scenario_text() {
  return "duration_s = 0.3\n"
         "[[board]]\nname = \"board\"\nsketch = \"HostFeatures.ino\"\n"
         "[board.sockets]\nA = { device = \"stepper\" }\n"
         "[[host]]\nboard = \"board\"\ntranscript = \"host.txt\"\n"
         "[[host.step]]\nwait = \"^setup done\"\ntimeout_s = 0.1\n"
         "[[host.step]]\nsend = \"" +
         long_line() +
         "\\n\"\n"
         "[[host.step]]\nwait = \"(a|b)*b$\"\ntimeout_s = 0.1\n"
         "[output]\nsvg = \"\"\npng = \"\"\n";
}

/// The entries in one direction joined back together, and how many were marked cut.
struct Joined {
  std::string text;
  size_t pieces = 0;
  size_t cut = 0;
  size_t longest = 0;
};

Joined join(const HostClient& client, bool from_host, const std::string& starting_with) {
  Joined joined;
  bool inside = false;
  for (const HostClient::Entry& entry : client.transcript()) {
    if (entry.from_host != from_host) continue;
    if (!inside && entry.text.rfind(starting_with, 0) != 0) continue;
    inside = true;
    joined.text += entry.text;
    ++joined.pieces;
    joined.longest = std::max(joined.longest, entry.text.size());
    if (!entry.cut) break;
    ++joined.cut;
  }
  return joined;
}

class HostClientLongLinesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    simulation_ = create(parse(scenario_text(), source_path("tests/sim/assembly/fixtures/HostFeatures/scenario.toml")),
                         "host_client_long_lines", false);
    ASSERT_NE(simulation_, nullptr);
    simulation_->finish();
    client_ = simulation_->host_client("board");
    ASSERT_NE(client_, nullptr);
  }
  std::unique_ptr<Simulation> simulation_;
  const HostClient* client_ = nullptr;
};

TEST_F(HostClientLongLinesTest, TheEchoOfALongLineIsMatchedInPieces) {
  EXPECT_TRUE(client_->completed()) << client_->failure();
  const Joined echo = join(*client_, false, "echo: ");
  EXPECT_EQ(echo.text, "echo: " + long_line());
  const size_t bytes = kLineBytes + 6;  // "echo: " and the line
  EXPECT_EQ(echo.pieces, (bytes + kPieceBytes - 1) / kPieceBytes);
  EXPECT_EQ(echo.cut, echo.pieces - 1);
  EXPECT_EQ(echo.longest, kPieceBytes);
}

TEST_F(HostClientLongLinesTest, TheSentLineIsKeptInPiecesToo) {
  const Joined sent = join(*client_, true, "bbb");
  EXPECT_EQ(sent.text, long_line());
  EXPECT_EQ(sent.pieces, (kLineBytes + kPieceBytes - 1) / kPieceBytes);
  EXPECT_EQ(sent.cut, sent.pieces - 1);
}

TEST_F(HostClientLongLinesTest, TheTranscriptFileMarksEverySplit) {
  const std::string text = read_file(test_output_dir("host_client_long_lines") + "/host.txt");
  size_t marks = 0;
  for (size_t at = text.find("# the line above goes on"); at != std::string::npos;
       at = text.find("# the line above goes on", at + 1)) {
    ++marks;
  }
  // 25 cuts in the sent line (26 pieces), 25 in the echo (25,007 bytes: 26 pieces).
  EXPECT_EQ(marks, 50u);
}

}  // namespace
}  // namespace stepdance::sim::test
