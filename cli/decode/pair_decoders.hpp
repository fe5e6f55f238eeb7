// Every chosen STEP/DIR pair of a capture decoded while VcdStreamReader reads it (`stepdance decode`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "decode/capture_decoder.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"

namespace stepdance::sim {

/// Feeds each pair's StepDirDecoder from the reader's edges, so nothing but the decoders' own
/// state is kept: memory grows with the number of wires and pairs, never with the capture's
/// length. Context: host, one thread.
class PairDecoders final : public VcdValueListener {
 public:
  /// `wire_count`: the capture's declared wires; each pair's indices must be below it.
  PairDecoders(std::size_t wire_count, std::vector<StepDirPair> pairs, const DecodeOptions& options);

  void on_initial_level(std::size_t wire, bool high) override;
  void on_edge(std::size_t wire, SimTime time_ns, bool high) override;

  /// The result of pair `pair` (an index into pairs()). Call once per pair, after the reader is
  /// done; results are made one at a time so that no second copy of them all is held.
  DecodeResult finish(std::size_t pair);
  const std::vector<StepDirPair>& pairs() const { return pairs_; }

 private:
  /// Makes the decoders once the initial levels are all known (the first edge, or the end).
  void start();

  std::vector<StepDirPair> pairs_;
  DecodeOptions options_;
  static constexpr uint32_t kNone = UINT32_MAX;
  /// Adds the feed 2 × pair (the pair's STEP) or 2 × pair + 1 (its DIR) to `wire`'s list.
  void add_feed(std::size_t wire, uint32_t feed);

  std::vector<uint8_t> initial_;  ///< per wire, until start()
  /// The feeds of each wire as linked lists (most wires feed nothing or one pair): the first
  /// feed of a wire, and after each feed the next one of the same wire.
  std::vector<uint32_t> first_feed_;
  std::vector<uint32_t> feeds_;
  std::vector<uint32_t> next_feed_;
  std::vector<StepDirDecoder> decoders_;
};

}  // namespace stepdance::sim
