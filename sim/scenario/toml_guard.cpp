// find_unsafe_toml: a control-character pass, then one pass of a small TOML lexer that follows
// strings, comments, table headers, open brackets and whether a key or a value comes next.
#include "scenario/toml_guard.hpp"

#include <algorithm>
#include <cstddef>
#include <string>

namespace stepdance::sim::scenario {
namespace {

constexpr const char* kNonAscii = "a non-ASCII character outside a string or comment is not allowed in a scenario file";
constexpr const char* kNonAsciiAfterBackslash =
    "a non-ASCII character after a backslash in a string is not allowed in a scenario file";
constexpr const char* kNamelessHeader =
    "a table header must start with a name (letters, digits, '_', '-' or a quoted key)";
constexpr const char* kBraceAfterOpening = "'}' cannot follow '[' or ','";
const std::string kTooManyKeyParts =
    "a key of more than " + std::to_string(kMaxKeyParts) + " dotted parts is not allowed in a scenario file";
const std::string kKeyTooLong =
    "a key longer than " + std::to_string(kMaxKeyChars) + " characters is not allowed in a scenario file";

bool is_ascii(char c) { return static_cast<unsigned char>(c) < 0x80; }
/// TOML's whitespace (a lone CR is not: it belongs to a line break).
bool is_space_or_tab(char c) { return c == ' ' || c == '\t'; }
bool is_blank(char c) { return is_space_or_tab(c) || c == '\r'; }
bool is_space_or_tab_or_break(char c) { return is_blank(c) || c == '\n'; }

bool is_decimal(char c) { return c >= '0' && c <= '9'; }
bool is_hex(char c) { return is_decimal(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
bool is_octal(char c) { return c >= '0' && c <= '7'; }
bool is_binary(char c) { return c == '0' || c == '1'; }

/// Digits from `at` (one or more; an underscore only between two digits); `at` moves past them.
bool digits(std::string_view text, std::size_t& at, bool (*is_digit)(char)) {
  if (at >= text.size() || !is_digit(text[at])) return false;
  for (++at; at < text.size(); ++at) {
    if (text[at] == '_' && at + 1 < text.size() && is_digit(text[at + 1]))
      ++at;
    else if (!is_digit(text[at]))
      break;
  }
  return true;
}

/// A TOML integer or float, as TOML 1.0 writes them (no dates: no scenario value is one).
bool is_number(std::string_view text) {
  std::size_t at = 2;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'o' || text[1] == 'b')) {
    const auto kind = text[1] == 'x' ? is_hex : text[1] == 'o' ? is_octal : is_binary;
    return digits(text, at, kind) && at == text.size();
  }
  at = text[0] == '+' || text[0] == '-' ? 1 : 0;
  if (text.substr(at) == "inf" || text.substr(at) == "nan") return true;
  if (at < text.size() && text[at] == '0') {
    ++at;  // no leading zeros
  } else if (!digits(text, at, is_decimal)) {
    return false;
  }
  if (at < text.size() && text[at] == '.' && !digits(text, ++at, is_decimal)) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    if (!digits(text, at, is_decimal)) return false;
  }
  return at == text.size();
}

/// Where an unquoted value ends.
bool ends_a_bare_value(char c) { return is_space_or_tab_or_break(c) || c == ',' || c == ']' || c == '}' || c == '#'; }

bool starts_a_key(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '"' || c == '\'';
}

/// The first control character other than tab, LF and CR, or CR without LF, anywhere (strings
/// and comments too): TOML allows none of them.
UnsafeToml find_control_character(std::string_view text) {
  int line = 1;
  for (std::size_t at = 0; at < text.size(); ++at) {
    const auto byte = static_cast<unsigned char>(text[at]);
    if (byte == '\n') ++line;
    if (byte == '\r' && (at + 1 >= text.size() || text[at + 1] != '\n')) {
      return {line, "a carriage return without a line feed (U+000D) is not allowed in a scenario file"};
    }
    if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') || byte == 0x7F) {
      static const char kHex[] = "0123456789ABCDEF";
      return {line, std::string("control character U+00") + kHex[byte >> 4] + kHex[byte & 15] +
                        " is not allowed in a scenario file"};
    }
  }
  return {};
}

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  UnsafeToml run() {
    UnsafeToml found;
    while (at_ < text_.size() && found.line == 0) {
      const char c = text_[at_];
      if (c == '\n') {
        new_line();
      } else if (is_blank(c)) {
        ++at_;
      } else if (!is_ascii(c)) {
        found = unsafe(kNonAscii);
      } else if (c == '#') {
        at_ = std::min(text_.find('\n', at_), text_.size());
      } else if (c == '[' && line_start_ && open_.empty() && !in_value_) {
        found = table_header();
      } else if ((c == '"' || c == '\'') && string_may_start()) {
        const std::size_t start = at_;
        found = string();
        if (found.line == 0 && !in_value_) found = count_key(at_ - start, false);
      } else if (c != '[' && c != '{' && c != ']' && c != '}' && c != ',' && value_may_start()) {
        found = bare_value();
      } else if (c == '}' && (previous_ == '[' || previous_ == ',')) {
        found = unsafe(kBraceAfterOpening);
      } else {
        if (!in_value_ && is_key_character(c)) found = count_key(1, c == '.');
        follow_structure(c);
        significant(c);
        ++at_;
      }
    }
    return found;
  }

 private:
  UnsafeToml unsafe(const char* message) const { return {line_, message}; }

  /// Outside values, what is not structure belongs to a key: its bare parts and dots.
  static bool is_key_character(char c) { return c != '=' && c != '{' && c != '}' && c != '[' && c != ']' && c != ','; }

  /// Adds `chars` characters (and a part when `dot`) to the key being read; unsafe beyond the
  /// limits. A key starts anew at a line's start, after '{' or ',' and at '='.
  UnsafeToml count_key(std::size_t chars, bool dot) {
    key_chars_ += chars;
    if (dot) ++key_parts_;
    if (key_parts_ > kMaxKeyParts) return {line_, kTooManyKeyParts};
    if (key_chars_ > kMaxKeyChars) return {line_, kKeyTooLong};
    return {};
  }

  void start_key() {
    key_parts_ = 1;
    key_chars_ = 0;
  }

  void new_line() {
    start_key();
    ++line_;
    ++at_;
    line_start_ = true;
    if (open_.empty()) in_value_ = false;  // a value ends with its line unless a bracket is open
  }

  void significant(char c) {
    previous_ = c;
    line_start_ = false;
  }

  /// Where a value may start: after '=', or after '[' or ',' in an array.
  bool value_may_start() const { return in_value_ && (previous_ == '=' || previous_ == '[' || previous_ == ','); }

  /// An unquoted value at at_: true, false or a number. toml++ 3.3 scans such a value ahead to
  /// tell its type and asserts on some text it cannot type (`9904------ 0`, found by the fuzz
  /// target), so anything else is refused here with a message of our own.
  UnsafeToml bare_value() {
    std::size_t end = at_;
    while (end < text_.size() && !ends_a_bare_value(text_[end]) && is_ascii(text_[end])) ++end;
    const std::string_view value = text_.substr(at_, end - at_);
    if (end < text_.size() && !is_ascii(text_[end])) return unsafe(kNonAscii);
    if (value != "true" && value != "false" && !is_number(value)) {
      const std::string shown = value.size() <= 40 ? std::string(value) : std::string(value.substr(0, 40)) + "...";
      return {line_, "'" + shown + "' is not a number, true or false (a text value needs quotes)"};
    }
    significant(text_[end - 1]);
    at_ = end;
    return {};
  }

  /// Where TOML lets a string start: a value after '=', '[' or ','; a key at a line's start,
  /// after '{', ',' or '.', or first in a table header.
  bool string_may_start() const {
    if (in_value_) return previous_ == '=' || previous_ == '[' || previous_ == ',';
    return line_start_ || previous_ == '[' || previous_ == '{' || previous_ == ',' || previous_ == '.';
  }

  void follow_structure(char c) {
    if (c == '=' || c == '{' || c == ',') start_key();
    switch (c) {
      case '=': in_value_ = true; break;
      case '[':
        if (in_value_) open_.push_back('[');  // an array
        break;
      case '{':
        open_.push_back('{');  // an inline table: a key comes next
        in_value_ = false;
        break;
      case ',':
        if (!open_.empty()) in_value_ = open_.back() == '[';
        break;
      case ']':
      case '}':
        if (!open_.empty()) open_.pop_back();
        in_value_ = true;  // after a value; ',' or the line's end says what comes next
        break;
      default: break;
    }
  }

  /// A '[' or "[[" opening a line outside any value: its name must start like a key.
  UnsafeToml table_header() {
    std::size_t name = at_ + 1;
    if (name < text_.size() && text_[name] == '[') ++name;
    while (name < text_.size() && is_space_or_tab(text_[name])) ++name;
    if (name >= text_.size() || (!starts_a_key(text_[name]) && text_[name] != ']')) return unsafe(kNamelessHeader);
    significant('[');
    at_ = name;
    return {};
  }

  /// The string whose quote is at at_, up to its closing quotes (or the line's end, if a
  /// single-line string is not closed: toml++ reports that). Basic strings take escapes, and
  /// what follows a backslash (after blanks, and in a multi-line string line breaks) must be
  /// ASCII.
  UnsafeToml string() {
    const char quote = text_[at_];
    const bool basic = quote == '"';
    const std::string_view triple = basic ? "\"\"\"" : "'''";
    const bool multi_line = text_.compare(at_, 3, triple) == 0;
    const std::string_view close = multi_line ? triple : triple.substr(0, 1);
    significant(quote);
    at_ += close.size();
    while (at_ < text_.size() && text_.compare(at_, close.size(), close) != 0) {
      char c = text_[at_];
      if (basic && c == '\\') {
        // toml++ tests what follows for whitespace: after a line-ending backslash, across lines.
        std::size_t next = at_ + 1;
        while (next < text_.size() && (is_blank(text_[next]) || (multi_line && text_[next] == '\n'))) ++next;
        if (next < text_.size() && !is_ascii(text_[next])) return unsafe(kNonAsciiAfterBackslash);
        if (++at_ >= text_.size()) break;
        c = text_[at_];  // the escaped character is never a closing quote
      }
      if (c == '\n') {
        if (!multi_line) return {};  // the main loop counts this line break
        ++line_;
      }
      ++at_;
    }
    at_ = std::min(at_ + close.size(), text_.size());
    return {};
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int line_ = 1;
  bool line_start_ = true;
  bool in_value_ = false;      // a value comes next or is being read, not a key
  char previous_ = '\n';       // the last character outside blanks, line breaks, comments and strings
  std::string open_;           // the values' open '[' and '{', innermost last
  std::size_t key_parts_ = 1;  // dotted parts of the key being read
  std::size_t key_chars_ = 0;  // its characters so far
};

}  // namespace

UnsafeToml find_unsafe_toml(std::string_view text) {
  if (UnsafeToml control = find_control_character(text); control.line != 0) return control;
  return Scanner(text).run();
}

}  // namespace stepdance::sim::scenario
