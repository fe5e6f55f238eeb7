// RPC: line reading, dispatch, replies (including the chunked __index__ and __describe__).
#include "stepdance/interfaces/rpc/rpc.hpp"

#include "stepdance/interfaces/rpc/json_text.hpp"

namespace stepdance {

namespace {

constexpr size_t kReplyRoomNeeded = 640;  // a request is taken only when its reply surely fits
constexpr int kRequestsPerLoop = 8;

}  // namespace

// RPC runs only in loop context: requests call sketch methods that are not written to be ISR-safe.
Status RPC::begin_stream(ByteStream& stream) {
  (void)stream;  // the link keeps it: link_stream()
  return register_in(Stage::kLoop);
}

// ---- enrolling ---------------------------------------------------------------------------------------

// The member-function pointer is stored as bytes next to its object; the typed invoker chosen at
// enroll time (rpc_arguments.hpp) copies it back to its type. No heap and no std::function on firmware.
rpc::Entry* RPC::add_method(const char* instance_name, const char* name, void* instance, const void* method,
                            size_t method_bytes) {
  rpc::Entry* entry = registry_.add(instance_name, name, false);
  if (entry == nullptr) return nullptr;
  entry->object = instance;
  memcpy(entry->callable, method, method_bytes);
  return entry;
}

void RPC::enroll_port(const char* instance_name, const char* name, BlockPort& port) {
  char storage[kMaxNameBytes + 1];
  TextWriter full(storage, sizeof(storage));
  full.text(instance_name).character('.').text(name);
  registry_.add_port(full.c_str(), port);
}

// ---- requests -----------------------------------------------------------------------------------------

// Loop context. Back-pressure instead of loss: a request is read only when its reply surely fits the
// reply ring (kReplyRoomNeeded), so a host that stops reading makes the board stop taking requests
// rather than drop answers. At most kRequestsPerLoop requests per call keep dance_loop() responsive,
// and a half-sent __index__ reply goes on before any new request so its lines are not interleaved.
void RPC::loop() {
  ByteStream* stream = link_stream();
  if (stream == nullptr) return;
  flush_replies();
  for (int requests = 0; requests < kRequestsPerLoop; ++requests) {
    if (index_cursor_ >= 0) {
      continue_index();
      if (index_cursor_ >= 0) break;  // the host reads slowly: go on next time
    }
    if (!replies_.reserve(kReplyRoomNeeded) || !lines_.pump(*stream)) break;
    handle_line();
    lines_.take();
  }
  send_events();
  flush_replies();
}

// The order of checks follows docs/rpc.md's codes: 14 line too long, 1–4 parse errors, then the
// built-in names (__index__, __describe__, __subscribe__, __unsubscribe__), then 10 unknown name.
void RPC::handle_line() {
  if (lines_.overflowed()) {
    reply_error(14, "line too long", "");
    return;
  }
  rpc::JsonRequest request;
  const rpc::JsonError error = rpc::parse_request(lines_.text(), lines_.length(), request, pool_, sizeof(pool_));
  if (error != rpc::JsonError::kNone) {
    reply_error(static_cast<int>(error), rpc::to_string(error), request.id);
  } else if (strcmp(request.name, "__index__") == 0 || strcmp(request.name, "__describe__") == 0) {
    reply_index(request, request.name[2] == 'd');
  } else if (!handle_subscription(request)) {
    const int entry = registry_.find(request.name);
    if (entry < 0) {
      reply_error(10, "Unknown Function or Parameter", request.id);
    } else {
      call(registry_.at(entry), request);
    }
  }
}

// The invoker writes ",\"return\":…" after the "ok" prefix; on a problem the partial reply is
// discarded and an error reply is sent instead, so a client never sees both.
void RPC::call(rpc::Entry& entry, const rpc::JsonRequest& request) {
  char storage[256];
  TextWriter reply(storage, sizeof(storage));
  reply.text("{\"result\":\"ok\"");
  const rpc::Problem problem = entry.invoke(entry, request, reply);
  if (!problem.ok()) {
    reply_error(problem.code, problem.message, request.id);
    return;
  }
  if (request.id[0] != '\0') reply.text(",\"id\":").text(request.id);
  reply.character('}');
  replies_.send_line(reply);
}

// ---- replies ------------------------------------------------------------------------------------------

void RPC::reply_ok(const char* id) {
  char storage[96];
  TextWriter reply(storage, sizeof(storage));
  reply.text("{\"result\":\"ok\"");
  if (id[0] != '\0') reply.text(",\"id\":").text(id);
  reply.character('}');
  replies_.send_line(reply);
}

// The id is echoed only when the request had one; a request that failed to parse may have none.
void RPC::reply_error(int code, const char* message, const char* id) {
  ++errors_replied_;
  char storage[192];
  TextWriter reply(storage, sizeof(storage));
  // "error" keeps the original's key, so its clients recognise a failure.
  reply.text("{\"result\":\"error\",\"error\":");
  rpc::write_json_string(reply, message);
  reply.text(",\"code\":").unsigned_number(static_cast<uint32_t>(code));
  if (id != nullptr && id[0] != '\0') reply.text(",\"id\":").text(id);
  reply.character('}');
  replies_.send_line(reply);
}

// The index can be larger than the reply ring, so it is sent as one JSON line in pieces, each
// waiting for room (continue_index); loop() sends nothing else until the line is complete.
void RPC::reply_index(const rpc::JsonRequest& request, bool describe) {
  memcpy(index_id_, request.id, sizeof(index_id_));
  index_describes_ = describe;
  replies_.send("{\"result\":\"ok\",\"return\":{");
  index_cursor_ = 0;
  continue_index();
}

void RPC::continue_index() {
  while (index_cursor_ >= 0) {
    flush_replies();
    char storage[kMaxNameBytes + 96];
    TextWriter piece(storage, sizeof(storage));
    const bool last = static_cast<size_t>(index_cursor_) >= registry_.count();
    if (last) {
      piece.character('}');
      if (index_id_[0] != '\0') piece.text(",\"id\":").text(index_id_);
      piece.text("}\r\n");
    } else {
      const rpc::Entry& entry = registry_.at(index_cursor_);
      if (index_cursor_ > 0) piece.character(',');
      rpc::write_json_string(piece, entry.name);
      if (index_describes_) {
        write_description(piece, entry);
      } else {
        piece.text(entry.parameter ? ":\"parameter\"" : ":\"function\"");
      }
    }
    if (!replies_.reserve(piece.size())) return;  // wait for the host to read
    replies_.send(piece.c_str());
    index_cursor_ = last ? -1 : index_cursor_ + 1;
  }
}

// A signature "args:return" (one letter per type, see rpc_arguments.hpp) becomes
// "function <args> <return>", with '-' for no arguments and 'v' (void) when there is no return part.
void RPC::write_description(TextWriter& out, const rpc::Entry& entry) {
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

void RPC::flush_replies() { replies_.flush(*link_stream()); }

}  // namespace stepdance
