// VCD writer: header from the declared wires, then time-ordered value changes flushed by watermark.
#include "output/vcd_writer.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <ostream>
#include <stdexcept>

namespace stepdance::sim {
namespace {

constexpr size_t kChunkBytes = 1 << 16;
constexpr char kFirstIdChar = '!';
constexpr uint32_t kIdChars = '~' - '!' + 1;

bool valid_name(const std::string& name, bool allow_empty) {
  if (name.empty()) return allow_empty;
  return std::all_of(name.begin(), name.end(), [](char c) { return c > ' ' && c <= '~'; });
}

std::string timescale_text(SimTime ns) {
  switch (ns) {
    case 1: return "1 ns";
    case 10: return "10 ns";
    case 100: return "100 ns";
    case 1000: return "1 us";
    default: throw std::invalid_argument("VCD timescale must be 1, 10, 100 or 1000 ns");
  }
}

void append_number(std::string& out, SimTime value) {
  char digits[24];
  const auto result = std::to_chars(digits, digits + sizeof digits, value);
  out.append(digits, result.ptr);
}

}  // namespace

VcdWriter::VcdWriter(const std::string& path, VcdWriterOptions options)
    : file_(std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc)),
      out_(file_.get()),
      name_(path),
      options_(std::move(options)) {
  timescale_text(options_.timescale_ns);
  if (!*file_) throw std::runtime_error(path + ": cannot open for writing");
}

VcdWriter::VcdWriter(std::ostream& out, std::string name, VcdWriterOptions options)
    : out_(&out), name_(std::move(name)), options_(std::move(options)) {
  timescale_text(options_.timescale_ns);
}

VcdWriter::~VcdWriter() {
  if (closed_) return;
  try {
    close(last_time_units_ * options_.timescale_ns);
  } catch (const std::exception&) {
    // A destructor must not throw; close() reports the error to callers that want it.
  }
}

std::string VcdWriter::identifier(WireId index) {
  std::string id;
  uint32_t rest = index;
  do {
    id.push_back(static_cast<char>(kFirstIdChar + rest % kIdChars));
    rest /= kIdChars;
  } while (rest != 0);
  return id;
}

VcdWriter::WireId VcdWriter::add_wire(const std::string& scope, const std::string& name, bool initial) {
  if (header_written_) throw std::logic_error(name_ + ": VCD wire '" + name + "' added after the header was written");
  if (!valid_name(name, false)) throw std::invalid_argument("invalid VCD wire name '" + name + "'");
  if (!valid_name(scope, true)) throw std::invalid_argument("invalid VCD scope name '" + scope + "'");
  if (wires_.size() >= std::numeric_limits<WireId>::max()) throw std::invalid_argument("too many VCD wires");
  wires_.push_back(Wire{scope, name, std::string(), initial});
  return static_cast<WireId>(wires_.size() - 1);
}

SimTime VcdWriter::to_units(SimTime time_ns) const {
  const SimTime unit = options_.timescale_ns;
  return time_ns / unit + (time_ns % unit * 2 >= unit ? 1 : 0);
}

void VcdWriter::record(WireId wire, SimTime time, bool level) {
  if (wire >= wires_.size()) throw std::logic_error(name_ + ": VCD record on an undeclared wire");
  if (closed_) throw std::logic_error(name_ + ": VCD record after close");
  if (time < watermark_ns_ || time < 0) {
    throw std::logic_error(name_ + ": VCD edge at " + std::to_string(time) + " ns is older than the watermark " +
                           std::to_string(watermark_ns_) + " ns");
  }
  buffer_.push_back(Pending{to_units(time), wire, level});
}

void VcdWriter::record_all(WireId wire, const EdgeList& edges) {
  for (const Edge& edge : edges) record(wire, edge.time, edge.level);
}

void VcdWriter::flush_before(SimTime watermark) {
  if (closed_ || watermark <= watermark_ns_) return;
  watermark_ns_ = watermark;
  // Every later record rounds to the watermark's unit or a later one, so earlier units are complete.
  write_pending(to_units(watermark));
  check_stream();
}

void VcdWriter::close(SimTime end_time) {
  if (closed_) return;
  write_pending(std::numeric_limits<SimTime>::max());
  if (!header_written_) write_header();
  const SimTime end_units = to_units(std::max<SimTime>(end_time, 0));
  if (end_units > last_time_units_) write_time(end_units);
  closed_ = true;
  out_->write(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
  chunk_.clear();
  out_->flush();
  if (file_) file_->close();
  check_stream();
}

void VcdWriter::check_stream() {
  if (chunk_.size() >= kChunkBytes) {
    out_->write(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
    chunk_.clear();
  }
  if (!*out_) throw std::runtime_error(name_ + ": write failed");
}

void VcdWriter::write_pending(SimTime before_units) {
  // Stable: equal (time, wire) keys keep their call order. Usually already in order.
  const auto earlier = [](const Pending& a, const Pending& b) {
    return a.time != b.time ? a.time < b.time : a.wire < b.wire;
  };
  if (!std::is_sorted(buffer_.begin(), buffer_.end(), earlier))
    std::stable_sort(buffer_.begin(), buffer_.end(), earlier);
  size_t done = 0;
  for (; done < buffer_.size() && buffer_[done].time < before_units; ++done) {
    const Pending& change = buffer_[done];
    Wire& wire = wires_[change.wire];
    if (change.level == wire.level) continue;
    if (change.time <= 0 && !header_written_) {
      wire.level = change.level;  // folds into the $dumpvars values
      continue;
    }
    if (!header_written_) write_header();
    if (change.time > last_time_units_) write_time(change.time);
    wire.level = change.level;
    chunk_ += change.level ? '1' : '0';
    chunk_ += wire.id;
    chunk_ += '\n';
    if (chunk_.size() >= kChunkBytes) check_stream();
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(done));
}

void VcdWriter::write_time(SimTime units) {
  chunk_ += '#';
  append_number(chunk_, units);
  chunk_ += '\n';
  last_time_units_ = units;
}

void VcdWriter::write_header() {
  header_written_ = true;
  if (!options_.version.empty()) chunk_ += "$version " + options_.version + " $end\n";
  chunk_ += "$timescale " + timescale_text(options_.timescale_ns) + " $end\n";
  // Scopes in order of first declaration, the top level (empty scope) last.
  std::vector<std::string> scopes;
  for (const Wire& wire : wires_) {
    if (std::find(scopes.begin(), scopes.end(), wire.scope) == scopes.end()) scopes.push_back(wire.scope);
  }
  std::stable_partition(scopes.begin(), scopes.end(), [](const std::string& s) { return !s.empty(); });
  WireId next_id = 0;
  for (const std::string& scope : scopes) {
    if (!scope.empty()) chunk_ += "$scope module " + scope + " $end\n";
    for (Wire& wire : wires_) {
      if (wire.scope != scope) continue;
      wire.id = identifier(next_id++);
      chunk_ += "$var wire 1 " + wire.id + ' ' + wire.name + " $end\n";
    }
    if (!scope.empty()) chunk_ += "$upscope $end\n";
  }
  chunk_ += "$enddefinitions $end\n#0\n$dumpvars\n";
  for (const Wire& wire : wires_) {
    chunk_ += wire.level ? '1' : '0';
    chunk_ += wire.id;
    chunk_ += '\n';
  }
  chunk_ += "$end\n";
  last_time_units_ = 0;
}

}  // namespace stepdance::sim
