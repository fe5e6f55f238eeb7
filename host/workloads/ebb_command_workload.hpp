// EBB commands one at a time through a real Eibotboard on the manual backend, for the loop-pass
// benchmark (bench/measure_target_loop.sh ebb): the recorded saxi plot of
// examples/AxiDrawWave/saxi-plot.ebb, over and over. Each measured loop pass reads, parses,
// executes, answers and queues exactly one command; the frames that run the queued move until the
// board is idle again are not measured.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "axidraw_plot_commands.hpp"  // generated: kAxiDrawPlotCommands (cmake/embed_text.cmake)
#include "hal_manual.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance::workloads {

/// The plotter software's side: one recorded command (with its CR) offered at a time, the next
/// only after release_next(); the board's replies are dropped. Context: loop.
class OneCommandAtATime final : public ByteStream {
 public:
  size_t bytes_available() override { return offered_ ? end_ - next_ : 0; }
  int read_byte() override {
    if (bytes_available() == 0) return -1;
    const char c = kAxiDrawPlotCommands[next_++];
    return c == '\n' ? '\r' : static_cast<uint8_t>(c);  // EBB clients end commands with CR
  }
  size_t write_bytes(const uint8_t*, size_t length) override { return length; }
  size_t write_space() override { return 512; }

  /// Offers the next command (the first again after the last). Returns false if the previous
  /// one has not been read whole.
  bool release_next() {
    if (offered_ && next_ < end_) return false;
    if (kAxiDrawPlotCommands[end_] == '\0') end_ = 0;
    next_ = end_;
    while (kAxiDrawPlotCommands[end_] != '\0' && kAxiDrawPlotCommands[end_] != '\n') ++end_;
    if (kAxiDrawPlotCommands[end_] == '\n') ++end_;
    offered_ = true;
    ++commands_;
    return true;
  }
  /// Commands offered so far.
  uint32_t commands() const { return commands_; }

 private:
  size_t next_ = 0;
  size_t end_ = 0;
  bool offered_ = false;
  uint32_t commands_ = 0;
};

/// A bare Eibotboard (its outputs unconnected: the frame runs its executor only).
class EbbCommandWorkload {
 public:
  EbbCommandWorkload() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    board.begin(&link);
    dance_start();
    link.release_next();
  }
  /// The measured part: one loop pass of the link, which takes the offered command.
  void loop_pass() { board.loop(); }
  /// Unmeasured: frames until the board is idle, then the next command is offered.
  void between_passes() {
    for (uint32_t frame = 0; frame < kFrameLimit && !board.is_idle(); ++frame) engine().run_frame();
    if (!link.release_next()) ++unread_;
  }
  /// Commands offered.
  uint32_t units() const { return link.commands(); }
  /// A command left unread by its pass, or refused by the board: the figures would be wrong.
  bool failed() const { return unread_ != 0 || board.errors_replied() != 0; }

  static constexpr uint32_t kFrameLimit = 10000000;
  OneCommandAtATime link;
  Eibotboard board;
  uint32_t unread_ = 0;
};

}  // namespace stepdance::workloads
