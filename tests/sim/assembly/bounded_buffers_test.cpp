// Every buffer between a board and the outside has a stated capacity and says what it drops:
// the console kept for inspection, unfinished console lines, a host client's transcript and its
// unread lines (the live terminals are tested in tests/cli/live/live_containment_test.py).
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

std::string fixture(const std::string& name) { return source_path("tests/sim/assembly/fixtures/Bounded/" + name); }

/// What `println("chatter line N")` puts on the wire: the text, N's digits and "\r\n".
uint64_t chatter_bytes_through(uint64_t last_line) {
  uint64_t total = 0;
  for (uint64_t n = 0; n <= last_line; ++n) total += 13 + std::to_string(n).size() + 2;
  return total;
}

TEST(BoundedBuffers, AnUnfinishedConsoleLineIsShownAfterAQuietInterval) {
  std::vector<std::pair<SimTime, std::string>> lines;
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = test_output_dir("bounded_progress");
  std::unique_ptr<Simulation> simulation;
  options.console = [&](const std::string&, const std::string& line) { lines.push_back({simulation->now(), line}); };
  SimulationError error;
  simulation = Simulation::create(load(fixture("Progress")), options, error);
  ASSERT_NE(simulation, nullptr) << error.message;
  simulation->finish();
  ASSERT_EQ(lines.size(), 2u);
  // Printed at 0 without a newline, shown 100 ms later; the rest of the line at 1 s, with it.
  EXPECT_EQ(lines[0], (std::pair<SimTime, std::string>{100 * kMillisecond, "progress: 50%"}));
  EXPECT_EQ(lines[1], (std::pair<SimTime, std::string>{1000 * kMillisecond, " done"}));
}

TEST(BoundedBuffers, TheConsoleKeptForInspectionIsItsNewest64KiB) {
  auto simulation = create(load(fixture("Chatter")), "bounded_chatter", false);
  ASSERT_NE(simulation, nullptr);
  simulation->run_until(500 * kMillisecond);
  const SimBoard& board = *simulation->board("driver");
  const std::string& text = board.console().text();
  // The text ends with the last line printed; everything up to it was printed once.
  const size_t last_start = text.rfind("chatter line ", text.size() - 3);
  ASSERT_NE(last_start, std::string::npos);
  const uint64_t last_line = std::stoull(text.substr(last_start + 13));
  EXPECT_GT(last_line, 200000u);  // 100 lines a pass, a pass every 200 µs, for 0.5 s
  EXPECT_LE(text.size(), 2u * BoardConsole::kTextBytes);
  EXPECT_GE(text.size(), BoardConsole::kTextBytes);
  EXPECT_EQ(text.size() + board.console().text_dropped_bytes(), chatter_bytes_through(last_line));
}

TEST(BoundedBuffers, AHostTranscriptKeepsItsFirstLinesAndCountsTheRest) {
  const std::string text = "duration_s = 1\n[[board]]\nname = \"driver\"\nsketch = \"" + fixture("Chatter") +
                           "/Chatter.ino\"\nmodule = \"driver\"\n"
                           "[[host]]\nboard = \"driver\"\n"
                           "[[host.step]]\nwait = \"never printed\"\ntimeout_s = 0.6\n";
  auto simulation = create(parse(text, fixture("Chatter") + "/host.toml"), "bounded_transcript", false);
  ASSERT_NE(simulation, nullptr);
  simulation->finish();
  const HostClient& host = *simulation->host_client("driver");
  ASSERT_FALSE(host.failure().empty());  // the wait timed out, as it should
  // 500,000 lines a second for 1 s: the transcript keeps the first 100,000, counts the others.
  EXPECT_EQ(host.transcript().size(), HostClient::kTranscriptEntries);
  EXPECT_GT(host.transcript_lines_not_kept(), 390000u);
  // The wait step read every line while it ran; after it failed, none were kept unread.
  EXPECT_EQ(host.unread_lines_dropped(), 0u);
}

}  // namespace
}  // namespace stepdance::sim::test
