// Deterministic fixed-point formatting with snprintf and integer time arithmetic.
#include "output/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace stepdance::sim {

std::string format_fixed(double value, int decimals) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[400];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

std::string format_trimmed(double value, int max_decimals) {
  std::string text = format_fixed(value, max_decimals);
  if (text.find('.') == std::string::npos) return text;
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

std::string format_time(SimTime time_ns, SimTime unit_ns, int decimals) {
  // Decimal digits the ns resolution provides in this unit (unit 1000 ns → 3), capped at decimals.
  int shown = 0;
  unsigned long long pow10_shown = 1;
  for (SimTime u = unit_ns; u > 1 && shown < decimals; u /= 10) {
    ++shown;
    pow10_shown *= 10;
  }
  const unsigned long long step = static_cast<unsigned long long>(unit_ns) / pow10_shown;
  const bool negative = time_ns < 0;
  const unsigned long long magnitude =
      negative ? 0ull - static_cast<unsigned long long>(time_ns) : static_cast<unsigned long long>(time_ns);
  const unsigned long long rounded = magnitude / step + (magnitude % step * 2 >= step ? 1 : 0);
  std::string text = (negative && rounded != 0 ? "-" : "") + std::to_string(rounded / pow10_shown);
  if (decimals <= 0) return text;
  const std::string fraction = std::to_string(rounded % pow10_shown);
  text += '.';
  if (shown > 0) {
    text.append(static_cast<size_t>(shown) - fraction.size(), '0');
    text += fraction;
  }
  text.append(static_cast<size_t>(decimals - shown), '0');
  return text;
}

}  // namespace stepdance::sim
