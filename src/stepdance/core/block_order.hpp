// Stage order from the BlockPort graph: a block that feeds another runs before it.
#pragma once

#include <stddef.h>

namespace stepdance {

class Block;

/// Most blocks one call can order (every stage registry is smaller).
constexpr size_t kMaxOrderedBlocks = 64;

/// Reorders `blocks[0..count)` so that producers come before their consumers, keeping the given
/// (begin()) order between blocks that do not depend on each other: a stable topological sort.
///
/// An edge A → B exists when a port begun with parent A is mapped to a port of B and data flows
/// from A to B: A's port is an OUTPUT (A pushes), or B's port is an INPUT while A's direction is
/// undefined; the reverse when A's port is an INPUT (A pulls from B). Ports of blocks outside the
/// list are ignored (other stages run in stage order anyway).
///
/// On a cycle the list is left exactly as given and the blocks that could not be placed (those
/// on or after a cycle) are written, by type name after "cycle, begin() order kept:", into
/// `cycle_names` (truncated to
/// `names_capacity`, always terminated). Returns false on a cycle or when count exceeds
/// kMaxOrderedBlocks (then nothing changes and the names say so). Context: loop, engine stopped.
bool order_by_graph(Block** blocks, size_t count, char* cycle_names, size_t names_capacity);

}  // namespace stepdance
