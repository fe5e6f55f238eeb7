// parse_request: a small recursive-descent JSON reader for one request object.
#include "stepdance/interfaces/rpc/json_request.hpp"

#include <math.h>
#include <string.h>

namespace stepdance::rpc {
namespace {

class Reader {
 public:
  Reader(const char* text, size_t length, char* pool, size_t pool_size)
      : text_(text), length_(length), pool_(pool), pool_size_(pool_size) {}

  JsonError error = JsonError::kNone;

  void skip_space() {
    while (position_ < length_ && (text_[position_] == ' ' || text_[position_] == '\t' || text_[position_] == '\r')) {
      ++position_;
    }
  }
  bool peek(char c) {
    skip_space();
    return position_ < length_ && text_[position_] == c;
  }
  bool take(char c) {
    if (!peek(c)) return fail(JsonError::kSyntax);
    ++position_;
    return true;
  }
  bool at_end() {
    skip_space();
    return position_ == length_;
  }
  bool fail(JsonError why) {
    if (error == JsonError::kNone) error = why;
    return false;
  }

  /// A string into the pool; `out` points at it.
  bool string(const char*& out) {
    if (!take('"')) return false;
    const size_t start = pool_used_;
    while (position_ < length_ && text_[position_] != '"') {
      char c = text_[position_++];
      if (c == '\\') {
        if (!escape(c)) return false;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        return fail(JsonError::kSyntax);
      }
      if (pool_used_ + 1 >= pool_size_) return fail(JsonError::kTooLong);
      pool_[pool_used_++] = c;
    }
    if (!take('"')) return false;
    pool_[pool_used_++] = '\0';
    out = pool_ + start;
    return true;
  }

  /// The character an escape after a backslash stands for.
  bool escape(char& c) {
    if (position_ >= length_) return fail(JsonError::kSyntax);
    const char letter = text_[position_++];
    switch (letter) {
      case '"': case '\\': case '/': c = letter; return true;
      case 'b': c = '\b'; return true;
      case 'f': c = '\f'; return true;
      case 'n': c = '\n'; return true;
      case 'r': c = '\r'; return true;
      case 't': c = '\t'; return true;
      case 'u': return unicode_escape(c);
      default: return fail(JsonError::kSyntax);
    }
  }

  /// \uXXXX: ASCII names and text only (1..0x7F).
  bool unicode_escape(char& c) {
    if (position_ + 4 > length_) return fail(JsonError::kSyntax);
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[position_++];
      const int digit = (h >= '0' && h <= '9') ? h - '0' : (h >= 'a' && h <= 'f') ? h - 'a' + 10
                        : (h >= 'A' && h <= 'F') ? h - 'A' + 10 : -1;
      if (digit < 0) return fail(JsonError::kSyntax);
      code = code * 16 + static_cast<unsigned>(digit);
    }
    if (code == 0 || code > 0x7F) return fail(JsonError::kSyntax);
    c = static_cast<char>(code);
    return true;
  }

  bool number(double& out) {
    skip_space();
    const size_t start = position_;
    if (position_ < length_ && text_[position_] == '-') ++position_;
    size_t digits = 0;
    double value = 0.0;
    while (at_digit()) {
      value = value * 10.0 + (text_[position_++] - '0');
      ++digits;
    }
    if (digits == 0) return fail(JsonError::kSyntax);
    if (!fraction(value) || !exponent(value)) return false;
    out = text_[start] == '-' ? -value : value;
    return true;
  }

  bool at_digit() const { return position_ < length_ && text_[position_] >= '0' && text_[position_] <= '9'; }

  /// An optional ".digits", added to `value`.
  bool fraction(double& value) {
    if (position_ >= length_ || text_[position_] != '.') return true;
    ++position_;
    double scale = 0.1;
    size_t fraction_digits = 0;
    while (at_digit()) {
      value += (text_[position_++] - '0') * scale;
      scale *= 0.1;
      ++fraction_digits;
    }
    return fraction_digits > 0 || fail(JsonError::kSyntax);
  }

  /// An optional "e[+-]digits", applied to `value`.
  bool exponent(double& value) {
    if (position_ >= length_ || (text_[position_] != 'e' && text_[position_] != 'E')) return true;
    ++position_;
    bool negative = false;
    if (position_ < length_ && (text_[position_] == '+' || text_[position_] == '-')) negative = text_[position_++] == '-';
    int power = 0;
    size_t exponent_digits = 0;
    while (at_digit()) {
      if (power < 1000) power = power * 10 + (text_[position_] - '0');
      ++position_;
      ++exponent_digits;
    }
    if (exponent_digits == 0) return fail(JsonError::kSyntax);
    value *= pow(10.0, negative ? -power : power);
    return true;
  }

  bool literal(const char* word) {
    skip_space();
    const size_t n = strlen(word);
    if (position_ + n > length_ || strncmp(text_ + position_, word, n) != 0) return fail(JsonError::kSyntax);
    position_ += n;
    return true;
  }

  bool value(JsonValue& out) {
    skip_space();
    if (position_ >= length_) return fail(JsonError::kSyntax);
    const char c = text_[position_];
    if (c == '"') {
      out.type = JsonValue::Type::kString;
      return string(out.text);
    }
    if (c == 't' || c == 'f') {
      out.type = JsonValue::Type::kBool;
      out.boolean = c == 't';
      return literal(c == 't' ? "true" : "false");
    }
    if (c == 'n') {
      out.type = JsonValue::Type::kNull;
      return literal("null");
    }
    if (c == '[' || c == '{') return fail(JsonError::kTooManyArgs);
    out.type = JsonValue::Type::kNumber;
    return number(out.number);
  }

  /// The id's JSON text, copied as sent (a number or a string with its quotes).
  bool id(char* out, size_t capacity) {
    skip_space();
    const size_t start = position_;
    JsonValue ignored;
    const size_t pool_mark = pool_used_;
    if (!value(ignored)) return false;
    pool_used_ = pool_mark;
    const size_t n = position_ - start;
    if (n >= capacity) return fail(JsonError::kTooLong);
    memcpy(out, text_ + start, n);
    out[n] = '\0';
    return true;
  }

  /// Skips any value (an unknown key's).
  bool skip_value() {
    skip_space();
    if (peek('[') || peek('{')) {
      const char open = text_[position_];
      const char close = open == '[' ? ']' : '}';
      ++position_;
      if (peek(close)) return take(close);
      for (;;) {
        if (open == '{') {
          const char* key;
          const size_t mark = pool_used_;
          if (!string(key) || !take(':')) return false;
          pool_used_ = mark;
        }
        if (!skip_value()) return false;
        if (peek(',')) {
          ++position_;
          continue;
        }
        return take(close);
      }
    }
    JsonValue ignored;
    const size_t mark = pool_used_;
    const bool ok = value(ignored);
    pool_used_ = mark;
    return ok;
  }

 private:
  const char* text_;
  size_t length_;
  size_t position_ = 0;
  char* pool_;
  size_t pool_size_;
  size_t pool_used_ = 0;
};

bool read_args(Reader& reader, JsonRequest& out) {
  if (!reader.take('[')) return false;
  out.has_args = true;
  if (reader.peek(']')) return reader.take(']');
  for (;;) {
    if (out.arg_count == JsonRequest::kMaxArgs) return reader.fail(JsonError::kTooManyArgs);
    if (!reader.value(out.args[out.arg_count])) return false;
    ++out.arg_count;
    if (reader.peek(',')) {
      reader.take(',');
      continue;
    }
    return reader.take(']');
  }
}

/// One "key": value member of the request object.
bool read_member(Reader& reader, JsonRequest& out, bool& have_name) {
  const char* key;
  if (!reader.string(key) || !reader.take(':')) return false;
  if (strcmp(key, "name") == 0) {
    const char* name;
    if (!reader.peek('"')) return reader.fail(JsonError::kMissingName);
    if (!reader.string(name)) return false;
    if (strlen(name) > JsonRequest::kMaxNameBytes) return reader.fail(JsonError::kTooLong);
    strcpy(out.name, name);
    have_name = true;
    return true;
  }
  if (strcmp(key, "args") == 0) return reader.peek('n') ? reader.literal("null") : read_args(reader, out);
  if (strcmp(key, "id") == 0) return reader.id(out.id, sizeof(out.id));
  return reader.skip_value();
}

}  // namespace

JsonError parse_request(const char* line, size_t length, JsonRequest& out, char* pool, size_t pool_size) {
  out = JsonRequest{};
  Reader reader(line, length, pool, pool_size);
  bool have_name = false;
  if (!reader.take('{')) return reader.error;
  if (!reader.peek('}')) {
    for (;;) {
      if (!read_member(reader, out, have_name)) return reader.error;
      if (!reader.peek(',')) break;
      reader.take(',');
    }
  }
  if (!reader.take('}') || !reader.at_end()) return reader.fail(JsonError::kSyntax), reader.error;
  if (!have_name) return JsonError::kMissingName;
  return JsonError::kNone;
}

const char* to_string(JsonError error) {
  switch (error) {
    case JsonError::kNone: return "ok";
    case JsonError::kSyntax: return "malformed JSON request";
    case JsonError::kMissingName: return "request has no \"name\" string";
    case JsonError::kTooManyArgs: return "too many arguments, or an argument that is not a number, string, boolean or null";
    case JsonError::kTooLong: return "a name, id or string is too long";
  }
  return "unknown error";
}

}  // namespace stepdance::rpc
