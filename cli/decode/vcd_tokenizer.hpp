// VCD text as whitespace-separated tokens, read in fixed chunks so no line or token of a file,
// however long (a capture of /dev/zero is one endless token), is ever held whole beyond a bound.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace stepdance::sim {

/// One token of a VCD file.
struct VcdToken {
  std::string text;
  std::size_t line = 0;  ///< 1-based
  /// The last token of a file that ends without a newline: maybe a fragment ("#12" of "#1234").
  bool cut = false;
};

/// Splits a stream into whitespace-separated tokens (space, tab, CR, LF, VT, FF), remembering
/// each token's line. Reads kChunkBytes at a time; memory stays within a chunk and one token.
/// Context: host, one thread.
class VcdTokenizer {
 public:
  static constexpr std::size_t kChunkBytes = 64 * 1024;
  /// The longest token: a vector value of a 1,000,000-bit wire ("b" and its bits) fits.
  static constexpr std::size_t kMaxTokenBytes = 1024 * 1024;

  explicit VcdTokenizer(std::istream& in) : in_(in), chunk_(kChunkBytes) {}

  /// The next token; false at the end of the file, or when a token exceeds kMaxTokenBytes
  /// (then too_long() is true and line() is where it started).
  bool next(VcdToken& token);
  /// Skips the rest of the current line.
  void skip_line();

  /// Whether the file ended in the middle of a line (its last byte is not a newline).
  bool cut() const { return cut_; }
  /// The line the file was cut in (valid when cut()).
  std::size_t cut_line() const { return lines_started(); }
  /// Whether next() stopped at a token longer than kMaxTokenBytes.
  bool too_long() const { return too_long_; }
  /// The line an end-of-file error points at: the last line that has any byte (at least 1);
  /// after too_long(), the line the long token started on.
  std::size_t line() const;

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
  /// Makes sure a byte is at pos_; false at the end of the stream.
  bool fill();
  std::size_t lines_started() const { return newlines_ + (bytes_since_newline_ ? 1 : 0); }
  void advance();  ///< moves past the byte at pos_, counting lines

  std::istream& in_;
  std::vector<char> chunk_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  std::size_t newlines_ = 0;
  bool bytes_since_newline_ = false;
  bool cut_ = false;
  bool too_long_ = false;
  std::size_t too_long_line_ = 0;
};

}  // namespace stepdance::sim
