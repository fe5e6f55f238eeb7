// Arduino's String on the host, over std::string.
#include "WString.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include <type_traits>

#include "number_format.hpp"

namespace {

using stepdance::arduino::format_float;
using stepdance::arduino::format_signed_decimal;
using stepdance::arduino::format_unsigned;
using stepdance::arduino::kFloatTextSize;
using stepdance::arduino::kIntegerTextSize;

// Integers as Print writes them: signed decimal, or the two's complement digits in other bases.
template <typename Signed>
std::string signed_text(Signed value, int base) {
  char text[kIntegerTextSize];
  if (stepdance::arduino::effective_base(base) == 10) {
    format_signed_decimal(value, text);
  } else {
    format_unsigned(static_cast<std::make_unsigned_t<Signed>>(value), base, text);
  }
  return text;
}

std::string unsigned_text(unsigned long long value, int base) {
  char text[kIntegerTextSize];
  format_unsigned(value, base, text);
  return text;
}

std::string float_text(double value, int digits) {
  char text[kFloatTextSize];
  format_float(value, digits, text);
  return text;
}

}  // namespace

String::String(const char* text) : text_(text != nullptr ? text : "") {}
String::String(const __FlashStringHelper* text) : String(reinterpret_cast<const char*>(text)) {}
String::String(char c) : text_(1, c) {}
String::String(unsigned char value, unsigned char base) : text_(unsigned_text(value, base)) {}
String::String(int value, unsigned char base) : text_(signed_text(value, base)) {}
String::String(unsigned int value, unsigned char base) : text_(unsigned_text(value, base)) {}
String::String(long value, unsigned char base) : text_(signed_text(value, base)) {}
String::String(unsigned long value, unsigned char base) : text_(unsigned_text(value, base)) {}
String::String(long long value, unsigned char base) : text_(signed_text(value, base)) {}
String::String(unsigned long long value, unsigned char base) : text_(unsigned_text(value, base)) {}
String::String(float value, unsigned char decimal_places) : text_(float_text(value, decimal_places)) {}
String::String(double value, unsigned char decimal_places) : text_(float_text(value, decimal_places)) {}

bool String::reserve(unsigned int size) {
  text_.reserve(size);
  return true;
}

bool String::concat(const String& other) {
  text_ += other.text_;
  return true;
}
bool String::concat(const char* text) {
  if (text != nullptr) text_ += text;
  return true;
}
bool String::concat(char c) {
  text_ += c;
  return true;
}
bool String::concat(unsigned char value) { return concat(String(value)); }
bool String::concat(int value) { return concat(String(value)); }
bool String::concat(unsigned int value) { return concat(String(value)); }
bool String::concat(long value) { return concat(String(value)); }
bool String::concat(unsigned long value) { return concat(String(value)); }
bool String::concat(long long value) { return concat(String(value)); }
bool String::concat(unsigned long long value) { return concat(String(value)); }
bool String::concat(float value) { return concat(String(value)); }
bool String::concat(double value) { return concat(String(value)); }
bool String::concat(const __FlashStringHelper* text) { return concat(String(text)); }

String operator+(const char* left, const String& right) {
  String result(left);
  result.concat(right);
  return result;
}

int String::compareTo(const String& other) const {
  const int order = text_.compare(other.text_);
  return order < 0 ? -1 : (order > 0 ? 1 : 0);
}

bool String::equalsIgnoreCase(const String& other) const {
  if (text_.size() != other.text_.size()) return false;
  for (size_t i = 0; i < text_.size(); ++i) {
    if (tolower(static_cast<unsigned char>(text_[i])) != tolower(static_cast<unsigned char>(other.text_[i]))) {
      return false;
    }
  }
  return true;
}

bool String::startsWith(const String& prefix) const { return startsWith(prefix, 0); }

bool String::startsWith(const String& prefix, unsigned int offset) const {
  if (offset > text_.size() || text_.size() - offset < prefix.text_.size()) return false;
  return text_.compare(offset, prefix.text_.size(), prefix.text_) == 0;
}

bool String::endsWith(const String& suffix) const {
  if (text_.size() < suffix.text_.size()) return false;
  return text_.compare(text_.size() - suffix.text_.size(), suffix.text_.size(), suffix.text_) == 0;
}

char String::charAt(unsigned int index) const { return index < text_.size() ? text_[index] : '\0'; }

char& String::operator[](unsigned int index) {
  if (index < text_.size()) return text_[index];
  scratch_ = '\0';
  return scratch_;
}

void String::setCharAt(unsigned int index, char c) {
  if (index < text_.size()) text_[index] = c;
}

void String::toCharArray(char* buffer, unsigned int size, unsigned int index) const {
  getBytes(reinterpret_cast<unsigned char*>(buffer), size, index);
}

void String::getBytes(unsigned char* buffer, unsigned int size, unsigned int index) const {
  if (buffer == nullptr || size == 0) return;
  size_t count = 0;
  if (index < text_.size()) {
    count = text_.size() - index;
    if (count > size - 1) count = size - 1;
    memcpy(buffer, text_.data() + index, count);
  }
  buffer[count] = '\0';
}

namespace {
int position_or_none(size_t position) { return position == std::string::npos ? -1 : static_cast<int>(position); }
}  // namespace

int String::indexOf(char c, unsigned int from) const { return position_or_none(text_.find(c, from)); }

int String::indexOf(const String& text, unsigned int from) const {
  if (from > text_.size()) return -1;
  return position_or_none(text_.find(text.text_, from));
}

int String::lastIndexOf(char c) const { return position_or_none(text_.rfind(c)); }

int String::lastIndexOf(char c, unsigned int from) const { return position_or_none(text_.rfind(c, from)); }

int String::lastIndexOf(const String& text) const { return position_or_none(text_.rfind(text.text_)); }

int String::lastIndexOf(const String& text, unsigned int from) const {
  return position_or_none(text_.rfind(text.text_, from));
}

String String::substring(unsigned int begin) const { return substring(begin, length()); }

String String::substring(unsigned int begin, unsigned int end) const {
  if (end < begin) {
    const unsigned int swap = begin;
    begin = end;
    end = swap;
  }
  if (begin >= text_.size()) return String();
  if (end > text_.size()) end = length();
  return String(text_.substr(begin, end - begin));
}

void String::replace(char find, char replacement) {
  for (char& c : text_) {
    if (c == find) c = replacement;
  }
}

void String::replace(const String& find, const String& replacement) {
  if (find.text_.empty()) return;
  size_t at = 0;
  while ((at = text_.find(find.text_, at)) != std::string::npos) {
    text_.replace(at, find.text_.size(), replacement.text_);
    at += replacement.text_.size();
  }
}

void String::remove(unsigned int index) {
  if (index < text_.size()) text_.erase(index);
}

void String::remove(unsigned int index, unsigned int count) {
  if (index < text_.size()) text_.erase(index, count);
}

void String::toLowerCase() {
  for (char& c : text_) c = static_cast<char>(tolower(static_cast<unsigned char>(c)));
}

void String::toUpperCase() {
  for (char& c : text_) c = static_cast<char>(toupper(static_cast<unsigned char>(c)));
}

void String::trim() {
  const char* space = " \t\n\v\f\r";
  const size_t first = text_.find_first_not_of(space);
  if (first == std::string::npos) {
    text_.clear();
    return;
  }
  const size_t last = text_.find_last_not_of(space);
  text_ = text_.substr(first, last - first + 1);
}

long String::toInt() const { return strtol(text_.c_str(), nullptr, 10); }
float String::toFloat() const { return static_cast<float>(toDouble()); }
double String::toDouble() const { return strtod(text_.c_str(), nullptr); }
