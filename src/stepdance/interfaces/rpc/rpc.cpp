// RPC: line reading, dispatch, replies (including the chunked __index__), registry, numbers.
#include "stepdance/interfaces/rpc/rpc.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/file_storage.hpp"

namespace stepdance {

int RPC::pending_code_ = 0;
const char* RPC::pending_message_ = "";

namespace {

constexpr size_t kReplyRoomNeeded = 640;  // a request is taken only when its reply surely fits

}  // namespace

Status RPC::begin() { return begin_stream(hal::console()); }

Status RPC::begin_stream(ByteStream& stream) {
  stream_ = &stream;
  return register_in(Stage::kLoop);
}

// ---- registry ---------------------------------------------------------------------------------------

RPC::Entry* RPC::add(const char* prefix, const char* suffix, bool parameter) {
  const size_t prefix_length = strlen(prefix);
  const size_t suffix_length = strlen(suffix);
  const size_t length = prefix_length + (suffix_length > 0 ? 1 + suffix_length : 0);
  if (entry_count_ == kMaxEntries || length > kMaxNameBytes || prefix_length == 0) {
    ++enroll_failures_;
    report_fault(FaultLevel::kWarning, FaultReason::kRegistryFull, "rpc", "enroll refused: registry full or name too long");
    return nullptr;
  }
  Entry* entry = nullptr;
  char name[kMaxNameBytes + 1];
  memcpy(name, prefix, prefix_length);
  if (suffix_length > 0) {
    name[prefix_length] = '.';
    memcpy(name + prefix_length + 1, suffix, suffix_length);
  }
  name[length] = '\0';
  for (size_t i = 0; i < entry_count_; ++i) {
    if (strcmp(entries_[i].name, name) == 0) entry = &entries_[i];  // enrolled again: replaced
  }
  if (entry == nullptr) entry = &entries_[entry_count_++];
  *entry = Entry{};
  memcpy(entry->name, name, length + 1);
  entry->parameter = parameter;
  entry->watchable = parameter;
  return entry;
}

void RPC::enroll_port(const char* name, BlockPort& port) {
  static const char* const kOperations[] = {"read", "read_deep", "reset_deep"};
  for (uint8_t operation = 0; operation < 3; ++operation) {
    Entry* entry = add(name, kOperations[operation], false);
    if (entry == nullptr) return;
    entry->object = &port;
    entry->callable[0] = operation;
    entry->invoke = &invoke_port;
    entry->signature = operation == 2 ? "n:v" : ":n";
    entry->watchable = operation != 2;
  }
}

void RPC::enroll_port(const char* instance_name, const char* name, BlockPort& port) {
  char storage[kMaxNameBytes + 1];
  TextWriter full(storage, sizeof(storage));
  full.text(instance_name).character('.').text(name);
  enroll_port(full.c_str(), port);
}

bool RPC::invoke_port(Entry& entry, const rpc::JsonRequest& request, TextWriter& reply) {
  BlockPort& port = *static_cast<BlockPort*>(entry.object);
  const uint8_t operation = entry.callable[0];
  if (operation == 2) {
    if (request.arg_count != 1) return reply_problem(reply, 11, "wrong number of arguments");
    const ArgError error = check<double>(request.args[0]);
    if (error != ArgError::kNone) return reply_problem(reply, error == ArgError::kType ? 12 : 13, "bad position");
    port.reset_deep(as<double>(request.args[0]));
    return true;
  }
  if (request.arg_count != 0) return reply_problem(reply, 11, "wrong number of arguments");
  write_return<double>(reply, operation == 0 ? port.read_absolute() : port.read_deep());
  return true;
}

// ---- requests -----------------------------------------------------------------------------------------

void RPC::loop() {
  if (stream_ == nullptr) return;
  flush_replies();
  for (int requests = 0; requests < 8; ++requests) {
    if (index_cursor_ >= 0) {
      continue_index();
      if (index_cursor_ >= 0) break;  // the host reads slowly: go on next time
    }
    if (kReplyBufferBytes - reply_count_ < kReplyRoomNeeded) break;
    bool complete = false;
    while (!complete) {
      const int value = stream_->read_byte();
      if (value < 0) break;
      if (value == '\n') {
        complete = true;
      } else if (line_length_ < kMaxLineBytes) {
        line_[line_length_++] = static_cast<char>(value);
      } else {
        line_overrun_ = true;
      }
    }
    if (!complete) break;
    handle_line();
    line_length_ = 0;
    line_overrun_ = false;
  }
  send_events();
  flush_replies();
}

void RPC::handle_line() {
  if (line_length_ > 0 && line_[line_length_ - 1] == '\r') --line_length_;
  if (line_overrun_) {
    reply_error(14, "line too long", "");
    return;
  }
  if (line_length_ == 0) return;  // blank lines are ignored
  rpc::JsonRequest request;
  const rpc::JsonError error = rpc::parse_request(line_, line_length_, request, pool_, sizeof(pool_));
  if (error != rpc::JsonError::kNone) {
    reply_error(static_cast<int>(error), rpc::to_string(error), request.id);
    return;
  }
  if (strcmp(request.name, "__index__") == 0 || strcmp(request.name, "__describe__") == 0) {
    reply_index(request, request.name[2] == 'd');
    return;
  }
  if (handle_subscription(request)) return;
  for (size_t i = 0; i < entry_count_; ++i) {
    Entry& entry = entries_[i];
    if (strcmp(entry.name, request.name) != 0) continue;
    char storage[256];
    TextWriter reply(storage, sizeof(storage));
    reply.text("{\"result\":\"ok\"");
    pending_code_ = 0;
    if (!entry.invoke(entry, request, reply)) {
      reply_error(pending_code_, pending_message_, request.id);
      return;
    }
    if (request.id[0] != '\0') reply.text(",\"id\":").text(request.id);
    reply.character('}');
    send_line(reply);
    return;
  }
  reply_error(10, "Unknown Function or Parameter", request.id);
}

bool RPC::reply_problem(TextWriter& reply, int code, const char* message) {
  (void)reply;
  pending_code_ = code;
  pending_message_ = message;
  return false;
}

void RPC::reply_error(int code, const char* message, const char* id) {
  ++errors_replied_;
  char storage[192];
  TextWriter reply(storage, sizeof(storage));
  // "error" keeps the original's key, so its clients recognise a failure.
  reply.text("{\"result\":\"error\",\"error\":");
  write_string(reply, message);
  reply.text(",\"code\":").unsigned_number(static_cast<uint32_t>(code));
  if (id != nullptr && id[0] != '\0') reply.text(",\"id\":").text(id);
  reply.character('}');
  send_line(reply);
}

void RPC::reply_index(const rpc::JsonRequest& request, bool describe) {
  memcpy(index_id_, request.id, sizeof(index_id_));
  index_describes_ = describe;
  char storage[32];
  TextWriter start(storage, sizeof(storage));
  start.text("{\"result\":\"ok\",\"return\":{");
  for (const char* c = start.c_str(); *c != '\0'; ++c) {
    replies_[(reply_head_ + reply_count_++) % kReplyBufferBytes] = *c;
  }
  index_cursor_ = 0;
  continue_index();
}

void RPC::continue_index() {
  while (index_cursor_ >= 0) {
    flush_replies();
    char storage[kMaxNameBytes + 96];
    TextWriter piece(storage, sizeof(storage));
    const bool last = static_cast<size_t>(index_cursor_) >= entry_count_;
    if (last) {
      piece.character('}');
      if (index_id_[0] != '\0') piece.text(",\"id\":").text(index_id_);
      piece.text("}\r\n");
    } else {
      const Entry& entry = entries_[index_cursor_];
      if (index_cursor_ > 0) piece.character(',');
      write_string(piece, entry.name);
      if (index_describes_) {
        write_description(piece, entry);
      } else {
        piece.text(entry.parameter ? ":\"parameter\"" : ":\"function\"");
      }
    }
    if (piece.size() > kReplyBufferBytes - reply_count_) return;  // wait for the host to read
    for (const char* c = piece.c_str(); *c != '\0'; ++c) {
      replies_[(reply_head_ + reply_count_++) % kReplyBufferBytes] = *c;
    }
    index_cursor_ = last ? -1 : index_cursor_ + 1;
  }
}

void RPC::write_description(TextWriter& out, const Entry& entry) {
  if (entry.parameter) {
    out.text(":\"parameter ").text(entry.signature).character('"');
    return;
  }
  const char* colon = strchr(entry.signature, ':');
  out.text(":\"function ");
  if (colon == nullptr || colon == entry.signature) {
    out.character('-');
  } else {
    for (const char* c = entry.signature; c != colon; ++c) out.character(*c);
  }
  out.character(' ').text(colon != nullptr ? colon + 1 : "v").character('"');
}

void RPC::send_line(const TextWriter& line) {
  const size_t length = line.size();
  if (length + 2 > kReplyBufferBytes - reply_count_) return;  // callers check room first
  for (size_t i = 0; i < length; ++i) replies_[(reply_head_ + reply_count_++) % kReplyBufferBytes] = line.c_str()[i];
  replies_[(reply_head_ + reply_count_++) % kReplyBufferBytes] = '\r';
  replies_[(reply_head_ + reply_count_++) % kReplyBufferBytes] = '\n';
}

void RPC::flush_replies() {
  while (reply_count_ > 0) {
    const size_t contiguous = kReplyBufferBytes - reply_head_;
    const size_t chunk = reply_count_ < contiguous ? reply_count_ : contiguous;
    const size_t written = stream_->write_bytes(reinterpret_cast<const uint8_t*>(replies_ + reply_head_), chunk);
    reply_head_ = (reply_head_ + written) % kReplyBufferBytes;
    reply_count_ -= written;
    if (written < chunk) return;
  }
}

// ---- JSON output --------------------------------------------------------------------------------------

void RPC::write_number(TextWriter& out, double value) {
  if (!isfinite(value)) {
    out.text("null");  // JSON has no NaN or infinity
    return;
  }
  out.significant(value, 9);
}

void RPC::write_string(TextWriter& out, const char* text) {
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

}  // namespace stepdance
