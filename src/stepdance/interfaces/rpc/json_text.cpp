// JSON text for RPC replies and events.
#include "stepdance/interfaces/rpc/json_text.hpp"

#include <math.h>

namespace stepdance::rpc {

// Nine significant digits: enough to read a float parameter back exactly, and the format docs/rpc.md
// describes (exponent form only for very large or small values).
void write_json_number(TextWriter& out, double value) {
  if (!isfinite(value)) {
    out.text("null");  // JSON has no NaN or infinity
    return;
  }
  out.significant(value, 9);
}

// Escapes what RFC 8259 requires (quote, backslash, control characters) and every non-ASCII byte as
// \u00XX, so a reply is plain ASCII whatever a fault detail or name contains.
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
