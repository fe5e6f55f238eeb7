// A G-code line's text parsed and handed forward, or refused with Grbl's syntax error.
#include "stepdance/interfaces/gcode/gcode_parser_stage.hpp"

namespace stepdance::gcode {

// A block without commands or words changes nothing, so it goes no further: Grbl answers such a line
// `ok` without touching the parser state.
void ParserStage::take(const char* text, size_t length, LineAnswer& answer) {
  GcodeBlock block;
  const GrblError syntax = parse_line(text, length, block, options_);
  if (syntax != GrblError::kOk) {
    answer.refuse(syntax);
    return;
  }
  const bool empty = block.words_present == 0 && block.g_groups_present == 0 && block.m_groups_present == 0;
  if (empty) {
    answer.taken();
    return;
  }
  next_.take(block, answer);
}

}  // namespace stepdance::gcode
