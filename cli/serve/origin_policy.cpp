// OriginPolicy: Host and Origin header checks.
#include "origin_policy.hpp"

#include <algorithm>
#include <cctype>

namespace stepdance::cli::serve {
namespace {

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

OriginPolicy::OriginPolicy(std::string listen_address, uint16_t port, std::vector<std::string> allowed_origins)
    : listen_address_(std::move(listen_address)), port_(port), allowed_origins_(std::move(allowed_origins)) {}

bool OriginPolicy::host_allowed(std::string_view host) const {
  const std::string name = lowercase(host);
  const std::string suffix = ":" + std::to_string(port_);
  if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const std::string bare = name.substr(0, name.size() - suffix.size());
  const bool ipv6_listen = listen_address_.find(':') != std::string::npos;
  const std::string listen = ipv6_listen ? "[" + lowercase(listen_address_) + "]" : lowercase(listen_address_);
  if (bare == "127.0.0.1" || bare == "localhost" || bare == "[::1]" || (bare == listen && listen != "0.0.0.0"))
    return true;
  const std::string as_origin = "http://" + name;  // a name the user allowed with --allow-origin
  return std::any_of(allowed_origins_.begin(), allowed_origins_.end(),
                     [&](const std::string& allowed) { return lowercase(allowed) == as_origin; });
}

bool OriginPolicy::origin_allowed(std::string_view origin, std::string_view host) const {
  if (!host_allowed(host)) return false;
  if (origin.empty()) return false;
  if (std::find(allowed_origins_.begin(), allowed_origins_.end(), origin) != allowed_origins_.end()) return true;
  return lowercase(origin) == "http://" + lowercase(host);
}

}  // namespace stepdance::cli::serve
