// EBB replies: the two reply syntaxes (legacy and CU,10,1 "future") and the EBB's error texts.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/interfaces/ebb/ebb_parameters.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"

namespace stepdance::ebb {

/// The replies of one EBB link, in the syntax in force, for the command being answered. Holds
/// the reply ring the loop flushes to the link; a command is taken only while its largest reply
/// fits (reserve_largest()), so no reply is dropped. Context: loop.
class EbbReplies {
 public:
  /// Reply ring size, bytes; and the most one command can reply (the unknown-command echo).
  static constexpr size_t kBufferBytes = 512;
  static constexpr size_t kLargestReplyBytes = 160;

  /// The command being answered (one or two characters, already upper-cased; "" for a line
  /// that has none): the future syntax names it in every reply.
  void set_command(const char* name);
  const char* command() const { return command_; }

  /// "OK\r\n" (legacy; "\r\n" with acks off by CU,1,0) or "<CMD>\n" (future).
  void ok();
  /// Legacy: `data` + `legacy_ending` (+ the OK line when `ok_after`); future: "<CMD>,<data>\n".
  void data(const char* data, bool ok_after, const char* legacy_ending = "\r\n");
  /// The EBB's "!n Err: …" line for `error` (`offending`: the axis digit of !0, the character of
  /// !5), counted in errors().
  void error(EbbError error, char offending = ' ');
  /// Replies the parameters' first error, if they have one; true when it replied.
  bool parameter_error(const EbbParameters& parameters);
  /// Queues raw text (the few replies whose layout is their own: QU, QM, PI).
  void send(const char* text) { ring_.send(text); }

  /// CU,10,`future`: switches the syntax, replying half before and half after as the EBB does.
  /// True when it switched (the reply is sent); false when the syntax stays (reply ok()).
  bool switch_syntax(bool future);
  /// CU,1: OK lines on or off (legacy syntax only).
  void set_acks(bool on) { acks_ = on; }
  /// R: back to the legacy syntax with acks on.
  void reset();
  bool future_syntax() const { return future_; }
  bool acks() const { return acks_; }

  /// True when the largest reply of one command fits now.
  bool reserve_largest() const { return ring_.reserve(kLargestReplyBytes); }
  /// Hands queued replies to the link; returns the bytes written.
  size_t flush(ByteStream& stream) { return ring_.flush(stream); }
  /// Error replies since the start, and replies that found no room (stays 0).
  uint32_t errors() const { return errors_; }
  uint32_t dropped() const { return ring_.dropped(); }

 private:
  void error_text(EbbError error, char offending, TextWriter& line) const;

  link::ReplyRing<kBufferBytes> ring_;
  char command_[3] = {};
  bool future_ = false;
  bool acks_ = true;
  uint32_t errors_ = 0;
};

}  // namespace stepdance::ebb
