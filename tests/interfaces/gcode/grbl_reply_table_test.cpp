// Grbl 1.1h's reply table: every line of grbl/replies.txt (invalid and edge-case lines with the
// replies Grbl 1.1h gives, written from its source) fed to a GCodeInterface on the manual board.
// Where Stepdance answers otherwise on purpose the file says so, and docs/gcode.md's table of
// differences must name the same key.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

constexpr int kFramesPerExchange = 20;

std::string read_text(const std::string& relative_path) {
  std::ifstream file(std::string(STEPDANCE_SOURCE_DIR) + "/" + relative_path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// `\r`, `\n`, `\t`, `\xNN` and `\\` in a line of the file.
std::string unescape(const std::string& text) {
  std::string bytes;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\' || i + 1 == text.size()) {
      bytes += text[i];
      continue;
    }
    const char code = text[++i];
    if (code == 'r') bytes += '\r';
    if (code == 'n') bytes += '\n';
    if (code == 't') bytes += '\t';
    if (code == '\\') bytes += '\\';
    if (code == 'x') {
      bytes += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    }
  }
  return bytes;
}

/// One expected reply line: exact, or a regular expression.
struct Expected {
  std::string text;
  bool pattern = false;
  bool matches(const std::string& line) const {
    return pattern ? std::regex_search(line, std::regex(text)) : line == text;
  }
};

/// One exchange of the file: what is sent, Grbl's reply and, where it differs, ours.
struct Case {
  int line_number = 0;
  std::string send;
  std::vector<Expected> grbl, ours;
  std::string differs;
};

class GrblReplyTable : public test_support::EngineFixture {
 protected:
  void TearDown() override {
    gcode.reset();
    EngineFixture::TearDown();
  }
  void fresh_board() {
    gcode.reset();
    test_support::reset_global_state();
    host = std::make_unique<test_support::FakeByteStream>();
    gcode = std::make_unique<GCodeInterface>();
    ASSERT_EQ(gcode->begin(host.get()), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
    run(kFramesPerExchange);
    host->take();  // the welcome
  }
  void run(int frames) {
    for (int i = 0; i < frames; ++i) {
      dance_loop();
      hal_manual::run_frames(1);
    }
  }
  std::vector<std::string> exchange(const std::string& bytes) {
    host->send(bytes);
    run(kFramesPerExchange);
    std::vector<std::string> lines;
    std::string replies = host->take();
    for (size_t end = replies.find("\r\n"); end != std::string::npos; end = replies.find("\r\n")) {
      lines.push_back(replies.substr(0, end));
      replies.erase(0, end + 2);
    }
    EXPECT_EQ(replies, "") << "a reply without its CR LF";
    return lines;
  }
  void check(const Case& c, const std::string& docs) {
    const std::vector<Expected>& expected = c.ours.empty() ? c.grbl : c.ours;
    const std::vector<std::string> got = exchange(c.send);
    std::string shown;
    for (const std::string& line : got) shown += "  " + line + "\n";
    ASSERT_EQ(got.size(), expected.size()) << "replies.txt:" << c.line_number << " got\n" << shown;
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_TRUE(expected[i].matches(got[i])) << "replies.txt:" << c.line_number << " reply " << i << ": got "
                                               << got[i] << ", expected " << expected[i].text;
    }
    if (c.ours.empty()) return;
    EXPECT_NE(c.differs, "") << "replies.txt:" << c.line_number << ": `=` lines need an @differs key";
    EXPECT_NE(docs.find("| `" + c.differs + "` |"), std::string::npos)
        << "replies.txt:" << c.line_number << ": docs/gcode.md has no row `" << c.differs << "`";
  }

  std::unique_ptr<test_support::FakeByteStream> host;
  std::unique_ptr<GCodeInterface> gcode;
};

TEST_F(GrblReplyTable, EveryLineGetsGrbl11hsReplyOrADocumentedDifference) {
  const std::string docs = read_text("docs/gcode.md");
  std::istringstream file(read_text("tests/interfaces/gcode/grbl/replies.txt"));
  ASSERT_FALSE(file.str().empty());
  fresh_board();
  Case current;
  bool open = false;
  int cases = 0, line_number = 0;
  auto finish = [&] {
    if (open) check(current, docs);
    cases += open ? 1 : 0;
    open = false;
  };
  for (std::string line; std::getline(file, line);) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    const std::string rest = line.find(' ') == std::string::npos ? "" : line.substr(line.find(' ') + 1);
    const std::string tag = line.substr(0, line.find(' '));
    if (tag == ">" || tag == ">>" || tag == "@new" || tag == "@frames") finish();
    if (tag == ">" || tag == ">>") {
      current = Case{line_number, unescape(rest) + (tag == ">" ? "\n" : ""), {}, {}, ""};
      open = true;
    } else if (tag == "@new") {
      fresh_board();
    } else if (tag == "@frames") {
      run(std::stoi(rest));
    } else if (tag == "@differs") {
      current.differs = rest;
    } else if (tag == "<" || tag == "<~") {
      current.grbl.push_back({rest, tag == "<~"});
    } else if (tag == "=" || tag == "=~") {
      current.ours.push_back({rest, tag == "=~"});
    } else {
      ADD_FAILURE() << "replies.txt:" << line_number << ": unknown line " << line;
    }
  }
  finish();
  EXPECT_GE(cases, 90);
}

// limits.c limits_soft_check on a moving machine: a feed hold brings it to rest within the
// acceleration limit (short of the move's end, the position kept), then the queue is dropped,
// ALARM:2; a reset then finds it at rest, so no ALARM:3 follows.
TEST_F(GrblReplyTable, ASoftLimitWhileMovingStopsThePathFirst) {
  fresh_board();
  EXPECT_EQ(exchange("$22=1\n$20=1\nG1 X50 F600\n"), (std::vector<std::string>{"ok", "ok", "ok"}));
  run(5000);  // 0.2 s: well under way at 10 mm/s, 5 s from the end
  ASSERT_GT(gcode->interpolator().current_speed(), 0.0);
  host->send("G0 X400\n");
  std::string replies;
  for (int frames = 0; frames < 100000 && replies.find("[MSG:Reset to continue]") == std::string::npos; ++frames) {
    run(1);
    replies += host->take();
  }
  EXPECT_EQ(replies, "ALARM:2\r\n[MSG:Reset to continue]\r\n");
  const double stopped_x = gcode->output_x.read_absolute();
  EXPECT_GT(stopped_x, 1.0);
  EXPECT_LT(stopped_x, 10.0);
  run(5000);
  EXPECT_TRUE(gcode->interpolator().is_idle());
  EXPECT_DOUBLE_EQ(gcode->output_x.read_absolute(), stopped_x);  // the rest of the job was dropped
  EXPECT_EQ(exchange("G0 X1\n"), std::vector<std::string>{});
  EXPECT_EQ(exchange("\x18"),
            (std::vector<std::string>{"ok", "", "Grbl 1.1h ['$' for help]", "[MSG:'$H'|'$X' to unlock]"}));
}

}  // namespace
}  // namespace stepdance
