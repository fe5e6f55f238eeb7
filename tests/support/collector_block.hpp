// A test block whose input adds up everything pushed into it (pre-channel stage).
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"

namespace stepdance::test_support {

/// Register it after the block under test so it sees that block's pushes in the same frame.
class Collector : public Block {
 public:
  void begin() {
    input.begin(&position, BLOCKPORT_UNDEFINED, this);
    register_in(Stage::kPreChannel);
  }
  void run() override { input.update(); }
  /// The change received in the last frame, in world units.
  double last_change() const { return input.read(INCREMENTAL); }
  BlockPort input;
  DecimalPosition position = 0;
};

}  // namespace stepdance::test_support
