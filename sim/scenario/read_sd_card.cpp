// [board.sd_card]: the simulated card's speed, stalls and failure point (a slow or failing card).
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {
namespace {

/// One key of the card: a number in [0, max] stored into `out`.
struct CardKey {
  const char* key;
  double max;
  double SdCardConfig::*out;
};

constexpr CardKey kCardKeys[] = {
    {"write_kb_per_s", 1e6, &SdCardConfig::write_kb_per_s}, {"read_kb_per_s", 1e6, &SdCardConfig::read_kb_per_s},
    {"stall_every_kb", 1e9, &SdCardConfig::stall_every_kb}, {"stall_ms", 10000, &SdCardConfig::stall_ms},
    {"fail_after_kb", 1e9, &SdCardConfig::fail_after_kb},
};

}  // namespace

void read_sd_card(TableReader& board_reader, BoardConfig& board, ParseContext& context) {
  const toml::table* table = board_reader.table("sd_card");
  if (table == nullptr) return;
  TableReader reader(*table, "sd_card", context.reporter);
  for (const CardKey& key : kCardKeys) {
    const std::optional<double> value = reader.number(key.key);
    if (!value) continue;
    if (*value < 0 || *value > key.max) {
      reader.error(key.key, "'" + std::string(key.key) + "' must be in 0.." +
                                std::to_string(static_cast<int64_t>(key.max)) + ", got " + std::to_string(*value));
      continue;
    }
    board.sd_card.*(key.out) = *value;
  }
  reader.finish();
}

}  // namespace stepdance::sim::scenario
