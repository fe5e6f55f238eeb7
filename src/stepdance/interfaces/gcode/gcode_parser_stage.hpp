// The parser's stage of a G-code line's path: text in, a parsed block handed on.
#pragma once

#include <stddef.h>

#include "stepdance/interfaces/gcode/gcode_interpreter_stage.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"
#include "stepdance/interfaces/gcode/line_answer.hpp"

namespace stepdance::gcode {

/// First stage of a G-code line after the receiver: parses the line's text and hands the block
/// forward to the interpreter's stage. A syntax error refuses the line through its answer; a line
/// with nothing to do (a lone `%`, housekeeping alone) is answered as taken at once. Context: loop.
class ParserStage {
 public:
  /// `next` must outlive the stage.
  explicit ParserStage(InterpreterStage& next) : next_(next) {}

  /// Takes one line as the receiver hands it on (upper-cased, comments gone, not `$`), and
  /// `answer`, where its outcome goes. Context: loop.
  void take(const char* text, size_t length, LineAnswer& answer);
  /// The dialect accepted (printer codes). Context: loop.
  const ParserOptions& options() const { return options_; }

 private:
  InterpreterStage& next_;
  ParserOptions options_;
};

}  // namespace stepdance::gcode
