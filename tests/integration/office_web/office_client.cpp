#include "tests/integration/office_web/office_client.h"

#include <nlohmann/json.hpp>

namespace rockface::office_web_test {

using nlohmann::json;

Login log_in(httplib::Client& c, const std::string& origin, const std::string& role,
             const std::string& password, const std::string& cookie) {
  httplib::Headers h = {{"Origin", origin}, {"Sec-Fetch-Site", "same-origin"}};
  if (!cookie.empty()) h.emplace("Cookie", cookie);
  const auto r = c.Post("/api/login", h, json{{"role", role}, {"password", password}}.dump(),
                        "application/json");
  Login out;
  if (!r) return out;
  out.status = r->status;
  out.set_cookie = r->get_header_value("Set-Cookie");
  out.cookie = out.set_cookie.substr(0, out.set_cookie.find(';'));
  const auto [from, to] = r->headers.equal_range("Set-Cookie");
  for (auto it = from; it != to; ++it)
    if (it->second.find("rockface_known=") != std::string::npos)
      out.known = it->second.substr(0, it->second.find(';'));
  const json body = json::parse(r->body);
  out.csrf = body.value("csrf", "");
  out.error = body.value("error", "");
  return out;
}

}  // namespace rockface::office_web_test
