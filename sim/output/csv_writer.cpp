// CSV writer: RFC 4180 header quoting, integer-exact time column, fixed-decimal values.
#include "output/csv_writer.hpp"

#include <ostream>
#include <stdexcept>

#include "output/number_format.hpp"

namespace stepdance::sim {
namespace {

constexpr int kTimeDecimals = 6;
constexpr int kMaxDecimals = 17;

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

CsvWriter::CsvWriter(const std::string& path, std::vector<CsvColumn> columns)
    : file_(std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc)),
      out_(file_.get()),
      name_(path),
      columns_(std::move(columns)) {
  if (!*file_) throw std::runtime_error(path + ": cannot open for writing");
  write_header();
}

CsvWriter::CsvWriter(std::ostream& out, std::string name, std::vector<CsvColumn> columns)
    : out_(&out), name_(std::move(name)), columns_(std::move(columns)) {
  write_header();
}

void CsvWriter::write_header() {
  line_ = "time_s";
  for (const CsvColumn& column : columns_) {
    if (column.decimals < 0 || column.decimals > kMaxDecimals) {
      throw std::invalid_argument("CSV column '" + column.name + "' must have 0..17 decimals");
    }
    line_ += ',' + csv_field(column.name);
  }
  line_ += '\n';
  out_->write(line_.data(), static_cast<std::streamsize>(line_.size()));
  if (!*out_) throw std::runtime_error(name_ + ": write failed");
}

void CsvWriter::write_row(SimTime time, const std::vector<double>& values) {
  if (closed_) throw std::logic_error(name_ + ": CSV row after close");
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(name_ + ": CSV row has " + std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  }
  line_ = format_time(time, kSecond, kTimeDecimals);
  for (size_t i = 0; i < values.size(); ++i) line_ += ',' + format_fixed(values[i], columns_[i].decimals);
  line_ += '\n';
  out_->write(line_.data(), static_cast<std::streamsize>(line_.size()));
  if (!*out_) throw std::runtime_error(name_ + ": write failed");
}

void CsvWriter::close() {
  if (closed_) return;
  closed_ = true;
  out_->flush();
  if (file_) file_->close();
  if (!*out_) throw std::runtime_error(name_ + ": write failed");
}

}  // namespace stepdance::sim
