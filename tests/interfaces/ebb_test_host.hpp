// A test host for the EBB emulation: an Eibotboard on a fake serial link, commands and replies.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance::test_support {

/// Runs the engine one loop pass and one frame at a time and talks to the board as a client.
class EbbHost {
 public:
  explicit EbbHost(FakeByteStream& link) : link_(link) {}

  /// One loop pass, then one frame.
  void step() {
    dance_loop();
    hal_manual::run_frames(1);
  }
  /// Sends a command and returns every reply byte that arrived once the first did.
  std::string exchange(const std::string& command) {
    link_.take();
    link_.send(command);
    dance_loop();
    for (int i = 0; i < 1'000'000 && link_.from_board.empty(); ++i) step();
    return link_.take();
  }
  /// Writes `command` and reads one line, up to and including "\n", as pyserial's readline().
  std::string send_and_read_line(const std::string& command) {
    link_.send(command);
    return read_line();
  }
  /// Reads one line as pyserial's readline() does, running frames while it waits.
  std::string read_line() {
    for (int i = 0; i < 10'000'000; ++i) {
      pending_ += link_.take();
      const size_t end = pending_.find('\n');
      if (end != std::string::npos) {
        const std::string line = pending_.substr(0, end + 1);
        pending_.erase(0, end + 1);
        return line;
      }
      step();
    }
    ADD_FAILURE() << "no reply line";
    return "";
  }

 private:
  FakeByteStream& link_;
  std::string pending_;
};

}  // namespace stepdance::test_support
