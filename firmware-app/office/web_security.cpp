#include "firmware-app/office/web_security.h"

#include <sys/random.h>

#include <array>
#include <cstdint>
#include <stdexcept>

namespace rockface::app::office_web {

const std::map<std::string, std::string>& security_headers() {
  static const std::map<std::string, std::string> headers = {
      // 'self' only: the pages' modules, three.js and the data come from
      // this server; blob: for the textures three.js makes from fetched
      // photographs; no inline script or style, no plugin, no framing.
      {"Content-Security-Policy",
       "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' blob:; "
       "connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; "
       "frame-ancestors 'none'"},
      {"X-Content-Type-Options", "nosniff"},
      {"X-Frame-Options", "DENY"},
      {"Referrer-Policy", "no-referrer"},
      {"Cross-Origin-Opener-Policy", "same-origin"},
      {"Cross-Origin-Resource-Policy", "same-origin"},
  };
  return headers;
}

std::string random_token() {
  std::array<std::uint8_t, 32> bytes{};
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = getrandom(bytes.data() + got, bytes.size() - got, 0);
    if (n <= 0) throw std::runtime_error("the kernel gave no random bytes for a session token");
    got += static_cast<std::size_t>(n);
  }
  static const char* hex = "0123456789abcdef";
  std::string out;
  out.reserve(64);
  for (std::uint8_t b : bytes) {
    out += hex[b >> 4];
    out += hex[b & 15];
  }
  return out;
}

std::string session_cookie_name(bool tls) {
  return tls ? "__Host-rockface_session" : "rockface_session";
}

std::string session_cookie(bool tls, const std::string& token, int max_age_s) {
  return session_cookie_name(tls) + "=" + token + "; Path=/; Max-Age=" + std::to_string(max_age_s) +
         "; HttpOnly; SameSite=Strict" + (tls ? "; Secure" : "");
}

std::string cleared_session_cookie(bool tls) {
  return session_cookie_name(tls) + "=; Path=/; Max-Age=0; HttpOnly; SameSite=Strict" +
         (tls ? "; Secure" : "");
}

std::string known_browser_cookie_name(bool tls) {
  return tls ? "__Host-rockface_known" : "rockface_known";
}

std::string known_browser_cookie(bool tls, const std::string& token, int max_age_s) {
  return known_browser_cookie_name(tls) + "=" + token +
         "; Path=/; Max-Age=" + std::to_string(max_age_s) + "; HttpOnly; SameSite=Strict" +
         (tls ? "; Secure" : "");
}

std::string cookie_value(std::string_view header, std::string_view name) {
  std::size_t at = 0;
  while (at < header.size()) {
    std::size_t end = header.find(';', at);
    if (end == std::string_view::npos) end = header.size();
    std::string_view pair = header.substr(at, end - at);
    while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
    const std::size_t eq = pair.find('=');
    if (eq != std::string_view::npos && pair.substr(0, eq) == name)
      return std::string(pair.substr(eq + 1));
    at = end + 1;
  }
  return "";
}

bool same_origin_request(bool tls, std::string_view host, std::string_view origin,
                         std::string_view fetch_site) {
  if (!fetch_site.empty() && fetch_site != "same-origin") return false;
  if (origin.empty() || host.empty()) return false;
  const std::string own = std::string(tls ? "https://" : "http://") + std::string(host);
  return origin == own;
}

bool tokens_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

bool plausible_role_name(std::string_view role) {
  if (role.empty() || role.size() > 63) return false;
  if (role.front() >= '0' && role.front() <= '9') return false;
  for (char ch : role)
    if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_')) return false;
  return true;
}

}  // namespace rockface::app::office_web
