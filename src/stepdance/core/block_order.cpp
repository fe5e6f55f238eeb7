// Stable topological sort of a stage's blocks over the BlockPort mapping graph.
#include "stepdance/core/block_order.hpp"

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"

namespace stepdance {
namespace {

using Mask = uint64_t;
static_assert(kMaxOrderedBlocks <= 64, "one bit per block in a 64-bit mask");

int index_of(Block* const* blocks, size_t count, const Block* block) {
  if (block == nullptr) return -1;
  for (size_t i = 0; i < count; ++i) {
    if (blocks[i] == block) return static_cast<int>(i);
  }
  return -1;
}

/// +1: data flows from the port's owner to the peer's owner; -1: the other way; 0: unknown.
// The direction of a mapping comes from whichever side declares it; an undeclared pair gives no
// ordering constraint.
int flow(const BlockPort& port, const BlockPort& peer) {
  if (port.direction() == BLOCKPORT_OUTPUT) return 1;
  if (port.direction() == BLOCKPORT_INPUT) return -1;
  if (peer.direction() == BLOCKPORT_INPUT) return 1;
  if (peer.direction() == BLOCKPORT_OUTPUT) return -1;
  return 0;
}

/// predecessors[i]: the blocks that must run before block i.
void build_predecessors(Block* const* blocks, size_t count, Mask* predecessors) {
  for (size_t i = 0; i < count; ++i) predecessors[i] = 0;
  for (BlockPort* port = BlockPort::first_attached(); port != nullptr; port = port->next_attached()) {
    const BlockPort* peer = port->peer();
    if (peer == nullptr) continue;
    const int own = index_of(blocks, count, port->parent());
    const int other = index_of(blocks, count, peer->parent());
    if (own < 0 || other < 0 || own == other) continue;
    const int direction = flow(*port, *peer);
    if (direction > 0) predecessors[other] |= Mask{1} << own;
    if (direction < 0) predecessors[own] |= Mask{1} << other;
  }
}

void append(char* text, size_t capacity, size_t& length, const char* piece) {
  while (*piece != '\0' && length + 1 < capacity) text[length++] = *piece++;
  text[length] = '\0';
}

void name_unplaced(Block* const* blocks, size_t count, Mask placed, char* text, size_t capacity) {
  size_t length = 0;
  append(text, capacity, length, "cycle, begin() order kept:");
  const char* separator = " ";
  for (size_t i = 0; i < count; ++i) {
    if ((placed >> i) & 1u) continue;
    append(text, capacity, length, separator);
    append(text, capacity, length, blocks[i]->type_name());
    separator = ", ";
  }
}

}  // namespace

// Kahn's algorithm, always taking the earliest-begun ready block, so blocks with no data dependency
// keep their begin() order (stable: the order a sketch author expects). O(n²) over at most 64 blocks
// with bitmask sets, at start only. On a cycle nothing is reordered.
bool order_by_graph(Block** blocks, size_t count, char* cycle_names, size_t names_capacity) {
  if (names_capacity > 0) cycle_names[0] = '\0';
  if (count > kMaxOrderedBlocks) {
    size_t length = 0;
    if (names_capacity > 0) append(cycle_names, names_capacity, length, "too many blocks to order");
    return false;
  }
  Mask predecessors[kMaxOrderedBlocks];
  build_predecessors(blocks, count, predecessors);
  Block* ordered[kMaxOrderedBlocks];
  Mask placed = 0;
  for (size_t slot = 0; slot < count; ++slot) {
    size_t next = count;
    for (size_t i = 0; i < count && next == count; ++i) {
      const bool free = ((placed >> i) & 1u) == 0 && (predecessors[i] & ~placed) == 0;
      if (free) next = i;  // the earliest-begun ready block keeps independent blocks in order
    }
    if (next == count) {
      if (names_capacity > 0) name_unplaced(blocks, count, placed, cycle_names, names_capacity);
      return false;
    }
    placed |= Mask{1} << next;
    ordered[slot] = blocks[next];
  }
  for (size_t i = 0; i < count; ++i) blocks[i] = ordered[i];
  return true;
}

}  // namespace stepdance
