// JSON text for RPC replies and events.
#include "stepdance/interfaces/rpc/json_text.hpp"

#include <math.h>

namespace stepdance::rpc {

void write_json_number(TextWriter& out, double value) {
  if (!isfinite(value)) {
    out.text("null");  // JSON has no NaN or infinity
    return;
  }
  out.significant(value, 9);
}

void write_json_string(TextWriter& out, const char* text) {
  out.character('"');
  for (const char* c = text; *c != '\0'; ++c) {
    const unsigned char byte = static_cast<unsigned char>(*c);
    if (byte == '"' || byte == '\\') {
      out.character('\\').character(static_cast<char>(byte));
    } else if (byte < 0x20 || byte > 0x7E) {
      static const char kHex[] = "0123456789abcdef";
      out.text("\\u00").character(kHex[(byte >> 4) & 0xF]).character(kHex[byte & 0xF]);
    } else {
      out.character(static_cast<char>(byte));
    }
  }
  out.character('"');
}

}  // namespace stepdance::rpc
