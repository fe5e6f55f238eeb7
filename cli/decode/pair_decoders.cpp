// PairDecoders: a wire → pairs table, decoders made at the first edge, edges passed straight on.
#include "decode/pair_decoders.hpp"

namespace stepdance::sim {

PairDecoders::PairDecoders(std::size_t wire_count, std::vector<StepDirPair> pairs, const DecodeOptions& options)
    : pairs_(std::move(pairs)), options_(options), initial_(wire_count, 0), first_feed_(wire_count, kNone) {
  feeds_.reserve(2 * pairs_.size());
  next_feed_.reserve(2 * pairs_.size());
  for (std::size_t pair = 0; pair < pairs_.size(); ++pair) {
    add_feed(pairs_[pair].step, static_cast<uint32_t>(2 * pair));
    add_feed(pairs_[pair].dir, static_cast<uint32_t>(2 * pair + 1));
  }
}

void PairDecoders::add_feed(std::size_t wire, uint32_t feed) {
  feeds_.push_back(feed);
  next_feed_.push_back(first_feed_[wire]);
  first_feed_[wire] = static_cast<uint32_t>(feeds_.size() - 1);
}

void PairDecoders::on_initial_level(std::size_t wire, bool high) { initial_[wire] = high ? 1 : 0; }

void PairDecoders::start() {
  decoders_.reserve(pairs_.size());
  for (const StepDirPair& pair : pairs_) {
    decoders_.emplace_back(options_, InitialLevels{initial_[pair.step] != 0, initial_[pair.dir] != 0});
  }
  std::vector<uint8_t>().swap(initial_);
}

void PairDecoders::on_edge(std::size_t wire, SimTime time_ns, bool high) {
  if (decoders_.size() != pairs_.size()) start();
  for (uint32_t at = first_feed_[wire]; at != kNone; at = next_feed_[at]) {
    const uint32_t feed = feeds_[at];
    StepDirDecoder& decoder = decoders_[feed / 2];
    if (feed % 2 == 0) {
      decoder.step_edge(time_ns, high);
    } else {
      decoder.dir_edge(time_ns, high);
    }
  }
}

DecodeResult PairDecoders::finish(std::size_t pair) {
  if (decoders_.size() != pairs_.size()) start();
  return decoders_[pair].finish();
}

}  // namespace stepdance::sim
