// replay_page_html: index.html with its <link> and <script> replaced by the files themselves.
#include "replay_page.hpp"

#include <stdexcept>
#include <string_view>

#include "web_assets.hpp"

namespace stepdance::cli {
namespace {

/// A built-in file of the page; `inline_text`: one to put inside <script> or <style>, where
/// nothing may close the element early.
std::string asset(const char* path, bool inline_text = true) {
  const serve::WebAsset* found = serve::find_view_asset(path);
  if (found == nullptr) throw std::runtime_error(std::string("the replay page: no built-in ") + path);
  const std::string text(found->body);
  if (inline_text && (text.find("</script") != std::string::npos || text.find("</style") != std::string::npos)) {
    throw std::runtime_error(std::string("the replay page: the built-in ") + path + " cannot be inlined");
  }
  return text;
}

/// Replaces the one `from` in `text` with `to`; throws if `from` is not there.
void replace_once(std::string& text, std::string_view from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("the replay page: index.html has no " + std::string(from));
  text.replace(at, from.size(), to);
}

/// JSON text safe inside <script>: every '<' (only ever inside strings) as \u003c.
std::string script_safe_json(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string replay_page_html(const nlohmann::json& recording) {
  std::string page = asset("/index.html", false);
  replace_once(page, "<link rel=\"stylesheet\" href=\"style.css\">", "<style>\n" + asset("/style.css") + "</style>");
  replace_once(page, "<script src=\"app.js\" defer></script>\n", "");
  // Nothing may be fetched: the page opens the same with no network (and cannot leak the run).
  replace_once(page, "<title>Stepdance live view</title>",
               "<title>Stepdance replay</title>\n<meta http-equiv=\"Content-Security-Policy\" content=\"default-src "
               "'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:\">");
  // At the end of the body, in order: the recording, the replay transport, the page itself.
  replace_once(page, "</body>",
               "<script type=\"application/json\" id=\"stepdance-replay\">" + script_safe_json(recording) +
                   "</script>\n<script>\n" + asset("/replay.js") + "</script>\n<script>\n" + asset("/app.js") +
                   "</script>\n</body>");
  return page;
}

}  // namespace stepdance::cli
