// Arduino's String on the host: a growable text with the member functions sketches use.
#pragma once

#include <stddef.h>

#include <string>

class __FlashStringHelper;

/// Text owned by value. Numbers convert as Print prints them (decimal by default, floats with two
/// digits). Positions are 0-based; "not found" is −1. Out-of-range positions are tolerated: they
/// read as '\0' or select nothing, never crash. Context: loop (it allocates).
class String {
 public:
  String() = default;
  String(const char* text);                         // NOLINT: implicit, as in Arduino
  String(const __FlashStringHelper* text);          // NOLINT
  String(const std::string& text) : text_(text) {}  // NOLINT
  explicit String(char c);
  explicit String(unsigned char value, unsigned char base = 10);
  explicit String(int value, unsigned char base = 10);
  explicit String(unsigned int value, unsigned char base = 10);
  explicit String(long value, unsigned char base = 10);
  explicit String(unsigned long value, unsigned char base = 10);
  explicit String(long long value, unsigned char base = 10);
  explicit String(unsigned long long value, unsigned char base = 10);
  explicit String(float value, unsigned char decimal_places = 2);
  explicit String(double value, unsigned char decimal_places = 2);

  /// Characters, without the terminating NUL.
  unsigned int length() const { return static_cast<unsigned int>(text_.size()); }
  bool isEmpty() const { return text_.empty(); }
  /// The text, NUL-terminated; valid until the String changes.
  const char* c_str() const { return text_.c_str(); }
  /// Reserves room for `size` characters; always true on the host.
  bool reserve(unsigned int size);

  /// Appends; each returns true (the host never runs out of memory).
  bool concat(const String& other);
  bool concat(const char* text);
  bool concat(char c);
  bool concat(unsigned char value);
  bool concat(int value);
  bool concat(unsigned int value);
  bool concat(long value);
  bool concat(unsigned long value);
  bool concat(long long value);
  bool concat(unsigned long long value);
  bool concat(float value);
  bool concat(double value);
  bool concat(const __FlashStringHelper* text);

  template <typename T>
  String& operator+=(const T& value) {
    concat(value);
    return *this;
  }
  template <typename T>
  friend String operator+(String left, const T& right) {
    left.concat(right);
    return left;
  }
  friend String operator+(const char* left, const String& right);

  /// −1, 0 or +1 as the text sorts before, equal to or after `other` (byte order).
  int compareTo(const String& other) const;
  bool equals(const String& other) const { return text_ == other.text_; }
  bool equals(const char* text) const { return text != nullptr && text_ == text; }
  bool equalsIgnoreCase(const String& other) const;
  bool startsWith(const String& prefix) const;
  bool startsWith(const String& prefix, unsigned int offset) const;
  bool endsWith(const String& suffix) const;

  friend bool operator==(const String& a, const String& b) { return a.equals(b); }
  friend bool operator==(const String& a, const char* b) { return a.equals(b); }
  friend bool operator==(const char* a, const String& b) { return b.equals(a); }
  friend bool operator!=(const String& a, const String& b) { return !a.equals(b); }
  friend bool operator!=(const String& a, const char* b) { return !a.equals(b); }
  friend bool operator!=(const char* a, const String& b) { return !b.equals(a); }
  friend bool operator<(const String& a, const String& b) { return a.compareTo(b) < 0; }
  friend bool operator>(const String& a, const String& b) { return a.compareTo(b) > 0; }
  friend bool operator<=(const String& a, const String& b) { return a.compareTo(b) <= 0; }
  friend bool operator>=(const String& a, const String& b) { return a.compareTo(b) >= 0; }

  /// The character at `index`, or '\0' past the end.
  char charAt(unsigned int index) const;
  char operator[](unsigned int index) const { return charAt(index); }
  /// A writable character; past the end it refers to a scratch byte whose writes are lost.
  char& operator[](unsigned int index);
  /// Replaces the character at `index`; nothing past the end.
  void setCharAt(unsigned int index, char c);
  /// Copies up to size − 1 characters starting at `index` into buffer, NUL-terminated.
  void toCharArray(char* buffer, unsigned int size, unsigned int index = 0) const;
  void getBytes(unsigned char* buffer, unsigned int size, unsigned int index = 0) const;

  /// First / last position of a character or text at or after (before) `from`, or −1.
  int indexOf(char c, unsigned int from = 0) const;
  int indexOf(const String& text, unsigned int from = 0) const;
  int lastIndexOf(char c) const;
  int lastIndexOf(char c, unsigned int from) const;
  int lastIndexOf(const String& text) const;
  int lastIndexOf(const String& text, unsigned int from) const;
  /// Characters from `begin` to the end, or from begin up to (not including) `end`; the two
  /// bounds are swapped when end < begin, as in the Arduino core.
  String substring(unsigned int begin) const;
  String substring(unsigned int begin, unsigned int end) const;

  /// In-place edits.
  void replace(char find, char replacement);
  void replace(const String& find, const String& replacement);
  void remove(unsigned int index);
  void remove(unsigned int index, unsigned int count);
  void toLowerCase();
  void toUpperCase();
  /// Removes leading and trailing white space.
  void trim();

  /// The leading number (after white space, with an optional sign), or 0 if none.
  long toInt() const;
  float toFloat() const;
  double toDouble() const;

  /// The text as a std::string (host-only convenience).
  const std::string& str() const { return text_; }

 private:
  std::string text_;
  char scratch_ = '\0';
};
