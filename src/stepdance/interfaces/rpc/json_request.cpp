// parse_request: a small recursive-descent JSON reader for one request object.
#include "stepdance/interfaces/rpc/json_request.hpp"

#include <math.h>
#include <string.h>

namespace stepdance::rpc {
namespace {

// A reader over one request line with no heap: strings are copied into a caller's pool, and the first
// error is kept (later ones would only describe the damage it caused). Only what docs/rpc.md promises
// is accepted: an object with "name", "args" (flat: numbers, strings, booleans, null) and "id".
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
  // JSON forbids raw control characters in strings (RFC 8259 §7), so they are a syntax error. The pool
  // keeps a byte for the terminating NUL, hence `+ 1 >=`.
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
      case '"':
      case '\\':
      case '/': c = letter; return true;
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
  // Names and arguments are ASCII, so \uXXXX beyond 0x7F (and \u0000, which would cut the C string)
  // is refused rather than half-decoded; surrogate pairs are therefore never needed.
  bool unicode_escape(char& c) {
    if (position_ + 4 > length_) return fail(JsonError::kSyntax);
    unsigned code = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[position_++];
      const int digit = (h >= '0' && h <= '9')   ? h - '0'
                        : (h >= 'a' && h <= 'f') ? h - 'a' + 10
                        : (h >= 'A' && h <= 'F') ? h - 'A' + 10
                                                 : -1;
      if (digit < 0) return fail(JsonError::kSyntax);
      code = code * 16 + static_cast<unsigned>(digit);
    }
    if (code == 0 || code > 0x7F) return fail(JsonError::kSyntax);
    c = static_cast<char>(code);
    return true;
  }

  // JSON's number grammar (RFC 8259 §6): no leading '+', no bare '.', at least one digit on each side
  // of the point. Built digit by digit instead of strtod, which is locale-dependent and not on every
  // firmware libc; the last bit may differ from a correctly rounded parse, well below the 9
  // significant digits the replies carry.
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
  // The exponent is capped at 1000 while reading so a long digit string cannot overflow an int; pow()
  // then gives 0 or infinity, and the argument check rejects a non-finite value (code 13).
  bool exponent(double& value) {
    if (position_ >= length_ || (text_[position_] != 'e' && text_[position_] != 'E')) return true;
    ++position_;
    bool negative = false;
    if (position_ < length_ && (text_[position_] == '+' || text_[position_] == '-'))
      negative = text_[position_++] == '-';
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

  // Arrays and objects are not arguments of any enrolled function, so they are reported as code 3
  // ("too many or nested arguments") instead of a generic syntax error.
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
  // JSON-RPC style: the id is echoed back exactly as sent, so it is kept as text, not parsed. The pool
  // space used while checking it is given back.
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
  // Unknown keys are skipped, nested values included, so a client may add fields (a newer client, a
  // bridge's own tags) without the board refusing its requests.
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

// At most JsonRequest::kMaxArgs (8) arguments; a ninth is code 3, never silently dropped.
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
// Keys may come in any order (JSON objects are unordered); "args": null means no arguments.
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

// Loop context. Anything after the closing brace is a syntax error (one request per line), and a
// request without "name" is code 2 even if otherwise well formed. `out` is reset first so a failed
// parse never leaves a previous request's arguments behind.
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
    case JsonError::kTooManyArgs:
      return "too many arguments, or an argument that is not a number, string, boolean or null";
    case JsonError::kTooLong: return "a name, id or string is too long";
  }
  return "unknown error";
}

}  // namespace stepdance::rpc
