#pragma once
// What every response and request of the office's web server is checked
// against (issue 46): the headers that keep a page from being framed,
// sniffed or made to run another site's script, the session cookie's
// attributes, the cross-site check of a POST, and the random tokens.
#include <map>
#include <string>
#include <string_view>

namespace rockface::app::office_web {

// The headers set on every response, pages and data alike: a strict
// Content-Security-Policy (scripts and styles only from the server, no
// inline script, no framing), nosniff, DENY, no referrer.
const std::map<std::string, std::string>& security_headers();

// 256 random bits from the kernel (/dev/urandom, getrandom) as 64
// lowercase hex digits; throws when the kernel gives none.
std::string random_token();

// The session cookie's name: "__Host-" prefixed under TLS (the browser then
// insists on Secure, Path=/ and no Domain).
std::string session_cookie_name(bool tls);
// Set-Cookie for a new session: HttpOnly, SameSite=Strict, Path=/, Secure
// under TLS; Max-Age bounds it in the browser too.
std::string session_cookie(bool tls, const std::string& token, int max_age_s);
// Set-Cookie that removes the cookie (log-out, expired session).
std::string cleared_session_cookie(bool tls);
// The known browser's cookie (known_browsers.h): "__Host-" prefixed under
// TLS as the session's, HttpOnly, SameSite=Strict, kept `max_age_s`.
std::string known_browser_cookie_name(bool tls);
std::string known_browser_cookie(bool tls, const std::string& token, int max_age_s);
// The value of cookie `name` in a Cookie header, "" when absent.
std::string cookie_value(std::string_view header, std::string_view name);

// Whether a state-changing request comes from the server's own page: its
// Origin must be present and name this server (scheme://Host), and a
// Sec-Fetch-Site, when the browser sends one, must say same-origin.
bool same_origin_request(bool tls, std::string_view host, std::string_view origin,
                         std::string_view fetch_site);

// Tokens compared in time independent of where they differ.
bool tokens_equal(std::string_view a, std::string_view b);

// A role name as PostgreSQL lets it be written unquoted (lower-case
// letters, digits, underscore; at most 63): anything else is refused
// before it reaches the server.
bool plausible_role_name(std::string_view role);

}  // namespace rockface::app::office_web
