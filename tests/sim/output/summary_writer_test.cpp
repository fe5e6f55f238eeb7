// Summary writer: exact JSON text with sorted keys, wall time last, extra fields, errors.
#include <gtest/gtest.h>

#include <stdexcept>

#include "output/summary_writer.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

RunSummary sample_summary() {
  RunSummary summary;
  summary.simulated_time = 2500 * kMillisecond;
  summary.boards["driver"].frame_overruns = 0;
  summary.boards["basic"].frame_overruns = 3;
  PortSummary out;
  out.pulses[SIGNAL_X] = {120, 4};
  out.pulses[SIGNAL_E] = {0, 1};
  out.carried = 7;
  summary.ports["basic:OUT_A"] = out;
  PortSummary in;
  in.is_input = true;
  in.pulses[SIGNAL_X] = {119, 4};
  in.pulses.too_short = 2;
  in.pulses.too_long = 1;
  summary.ports["driver:IN_A"] = in;
  summary.extra["strokes"] = 3;
  summary.extra["expectations"] = {{"failed", 0}, {"passed", 2}};
  return summary;
}

constexpr char kZeroCounts[] = R"("R": {
          "forward": 0,
          "reverse": 0
        },
        "T": {
          "forward": 0,
          "reverse": 0
        },)";

std::string expected_text(const std::string& wall_time) {
  return std::string(R"({
  "boards": {
    "basic": {
      "frame_overruns": 3
    },
    "driver": {
      "frame_overruns": 0
    }
  },
  "expectations": {
    "failed": 0,
    "passed": 2
  },
  "ports": {
    "basic:OUT_A": {
      "carried": 7,
      "pulses": {
        "E": {
          "forward": 0,
          "reverse": 1
        },
        )") +
         kZeroCounts + R"(
        "X": {
          "forward": 120,
          "reverse": 4
        },
        "Y": {
          "forward": 0,
          "reverse": 0
        },
        "Z": {
          "forward": 0,
          "reverse": 0
        }
      }
    },
    "driver:IN_A": {
      "pulses": {
        "E": {
          "forward": 0,
          "reverse": 0
        },
        )" +
         kZeroCounts + R"(
        "X": {
          "forward": 119,
          "reverse": 4
        },
        "Y": {
          "forward": 0,
          "reverse": 0
        },
        "Z": {
          "forward": 0,
          "reverse": 0
        }
      },
      "rejected": {
        "too_long": 1,
        "too_short": 2
      }
    }
  },
  "simulated_time_s": 2.5,
  "strokes": 3)" +
         wall_time + "\n}\n";
}

TEST(SummaryWriter, ExactTextWithoutWallTime) { EXPECT_EQ(summary_text(sample_summary()), expected_text("")); }

TEST(SummaryWriter, WallTimeIsTheLastKey) {
  RunSummary summary = sample_summary();
  summary.wall_time_s = 0.125;
  EXPECT_EQ(summary_text(summary), expected_text(",\n  \"wall_time_s\": 0.125"));
  summary.extra["zebra"] = 1;
  const std::string text = summary_text(summary);
  EXPECT_LT(text.find("\"zebra\""), text.find("\"wall_time_s\""));
}

TEST(SummaryWriter, WritesTheFile) {
  const std::string path = test::temp_path("summary.json");
  write_summary(path, sample_summary());
  EXPECT_EQ(test::read_text(path), expected_text(""));
  EXPECT_THROW(write_summary("/nonexistent-dir/summary.json", sample_summary()), std::runtime_error);
}

TEST(SummaryWriter, ExtraFieldsMayNotReplaceFixedOnes) {
  RunSummary summary;
  summary.extra["ports"] = 1;
  EXPECT_THROW(summary_json(summary), std::invalid_argument);
  summary.extra = {{"wall_time_s", 1}};
  EXPECT_THROW(summary_json(summary), std::invalid_argument);
  summary.extra = nlohmann::json::array();
  EXPECT_THROW(summary_json(summary), std::invalid_argument);
}

TEST(SummaryWriter, EmptySummary) {
  EXPECT_EQ(summary_text(RunSummary{}), "{\n  \"boards\": {},\n  \"ports\": {},\n  \"simulated_time_s\": 0.0\n}\n");
}

}  // namespace
}  // namespace stepdance::sim
