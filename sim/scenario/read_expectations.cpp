// [[expect]]: end-of-run checks. Each table names one check by its key; the kind that owns the key
// (kinds/expectation_kinds.hpp) reads the rest.
#include <set>
#include <string>
#include <utility>

#include "kinds/expectation_kinds.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// "'a', 'b' or 'c'" (quoted) or "a, b or c" for the kinds `pick` keeps.
template <typename Pick>
std::string kind_list(bool quoted, Pick pick) {
  std::vector<std::string> names;
  for (const ExpectationKind* kind : expectation_kinds()) {
    if (pick(*kind)) names.push_back(quoted ? "'" + std::string(kind->name) + "'" : std::string(kind->name));
  }
  std::string text;
  for (size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

/// The kind whose check key the table has, or null (reported) for none or two. A kind whose own
/// keys include another's check key takes the table ('rejected' counts pulses at a 'port').
const ExpectationKind* choose_kind(TableReader& reader) {
  const ExpectationKind* chosen = nullptr;
  for (const ExpectationKind* kind : expectation_kinds()) {
    if (!reader.has(kind->name)) continue;
    if (chosen == nullptr || kind->has_key(chosen->name)) {
      chosen = kind;
    } else if (!chosen->has_key(kind->name)) {
      reader.accept(kind->name);
      reader.error(kind->name, "an [[expect]] checks one thing, but has both '" + std::string(chosen->name) +
                                   "' and '" + std::string(kind->name) + "'");
      return nullptr;
    }
  }
  if (chosen == nullptr) {
    reader.reporter().error(reader.line(), "an [[expect]] needs one check: " +
                                               kind_list(false, [](const ExpectationKind&) { return true; }));
  }
  return chosen;
}

/// Reports every key of another kind that `chosen` does not take ("'steps' only goes with
/// 'motor'"); false if there was one.
bool refuse_other_kinds_keys(TableReader& reader, const ExpectationKind& chosen) {
  bool ok = true;
  std::set<std::string_view> reported;
  for (const ExpectationKind* kind : expectation_kinds()) {
    for (std::string_view key : kind->keys) {
      if (key == chosen.name || chosen.has_key(key) || !reader.has(key) || !reported.insert(key).second) continue;
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' only goes with " +
                            kind_list(true, [key](const ExpectationKind& owner) { return owner.has_key(key); }));
      ok = false;
    }
  }
  return ok;
}

void read_expectation(const toml::table& table, ParseContext& context) {
  TableReader reader(table, "[[expect]]", context.reporter);
  const ExpectationKind* kind = choose_kind(reader);
  if (kind == nullptr) return;
  bool ok = refuse_other_kinds_keys(reader, *kind);
  ExpectationReading reading{reader, context, {}};
  ok = kind->read(reading) && ok;
  reader.finish();
  if (ok) context.scenario.expectations.push_back(Expectation{kind, std::move(reading.settings), reader.line()});
}

}  // namespace

void read_expectations(TableReader& top, ParseContext& context) {
  for_each_table(top, "expect", [&](const toml::table& table) { read_expectation(table, context); });
}

}  // namespace stepdance::sim::scenario
