// Block registration and the default deep read.
#include "stepdance/core/block.hpp"

#include "stepdance/core/block_port.hpp"
#include "stepdance/core/engine.hpp"

namespace stepdance {

void Block::unregister(Block* block) { engine().remove(block); }

double Block::absolute_value(BlockPort& port) { return port.read(ABSOLUTE); }

Status Block::register_in(Stage stage) { return engine().add(stage, this); }

}  // namespace stepdance
