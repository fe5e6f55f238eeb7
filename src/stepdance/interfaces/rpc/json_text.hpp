// JSON text for RPC replies and events: numbers and strings written into a TextWriter.
#pragma once

#include "stepdance/core/text_writer.hpp"

namespace stepdance::rpc {

/// A JSON number with nine significant digits (whole numbers below 10^15 in full, an exponent
/// below 0.001 and from 10^15); NaN and ±infinity, which JSON lacks, as null. Context: any.
void write_json_number(TextWriter& out, double value);
/// A JSON string: quotes and backslashes escaped, control and non-ASCII bytes as \u00XX.
/// Context: any.
void write_json_string(TextWriter& out, const char* text);

}  // namespace stepdance::rpc
