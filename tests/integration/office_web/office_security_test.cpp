// The office web server's refusals over plain HTTP requests (issue 46): a
// wrong password, a tablet's role, an office role of another tunnel, an
// expired session, a forged cookie, a request from another site; the
// security headers on every response; a stored script served as data.
#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <string>
#include <thread>

#include "tests/integration/office_web/office_site.h"

namespace rockface::office_web_test {
namespace {

using nlohmann::json;

struct Login {
  int status = 0;
  std::string cookie;  // "name=value" for a Cookie header
  std::string set_cookie, csrf, error;
};

Login log_in(httplib::Client& c, const std::string& origin, const std::string& role,
             const std::string& password) {
  httplib::Headers h = {{"Origin", origin}, {"Sec-Fetch-Site", "same-origin"}};
  const auto r = c.Post("/api/login", h, json{{"role", role}, {"password", password}}.dump(),
                        "application/json");
  Login out;
  if (!r) return out;
  out.status = r->status;
  out.set_cookie = r->get_header_value("Set-Cookie");
  out.cookie = out.set_cookie.substr(0, out.set_cookie.find(';'));
  const json body = json::parse(r->body);
  out.csrf = body.value("csrf", "");
  out.error = body.value("error", "");
  return out;
}

void expect_security_headers(const httplib::Result& r, const std::string& what) {
  ASSERT_TRUE(r) << what;
  const std::string csp = r->get_header_value("Content-Security-Policy");
  EXPECT_NE(csp.find("default-src 'self'"), std::string::npos) << what;
  EXPECT_NE(csp.find("frame-ancestors 'none'"), std::string::npos) << what;
  EXPECT_EQ(csp.find("unsafe-inline"), std::string::npos) << what;
  EXPECT_EQ(csp.find("unsafe-eval"), std::string::npos) << what;
  EXPECT_EQ(r->get_header_value("X-Content-Type-Options"), "nosniff") << what;
  EXPECT_EQ(r->get_header_value("X-Frame-Options"), "DENY") << what;
  EXPECT_EQ(r->get_header_value("Referrer-Policy"), "no-referrer") << what;
}

TEST(OfficeWebSecurity, LogInAsAnOfficeRoleOnlyWithItsPassword) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  const Login wrong = log_in(c, server.origin(), "office_reader", "not the password");
  EXPECT_EQ(wrong.status, 403);
  EXPECT_EQ(wrong.set_cookie, "") << "no session for a wrong password";
  EXPECT_EQ(log_in(c, server.origin(), "nobody_here", kOfficePassword).status, 403);
  // The tablet's own right password: a tablet role never logs in to the web.
  const Login tablet = log_in(c, server.origin(), "tablet_a", kTabletPassword);
  EXPECT_EQ(tablet.status, 403);
  EXPECT_NE(tablet.error.find("tablet"), std::string::npos) << tablet.error;
  EXPECT_EQ(tablet.set_cookie, "");

  const Login ok = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(ok.status, 200) << ok.error;
  EXPECT_EQ(ok.csrf.size(), 64u) << "256 random bits in hex";
  EXPECT_NE(ok.set_cookie.find("HttpOnly"), std::string::npos);
  EXPECT_NE(ok.set_cookie.find("SameSite=Strict"), std::string::npos);
  EXPECT_EQ(ok.cookie.size(), std::string("rockface_session=").size() + 64);
  const auto tunnels = c.Get("/api/tunnels", {{"Cookie", ok.cookie}});
  ASSERT_TRUE(tunnels);
  ASSERT_EQ(tunnels->status, 200) << tunnels->body;
  const json list = json::parse(tunnels->body);
  ASSERT_EQ(list.size(), 2u) << "rockface_office reads every tunnel";
  EXPECT_EQ(list[0]["name"], "Main drive");
  EXPECT_EQ(list[0]["visits"], 4) << "tablet A's visit and its mapped face, tablet B's two";
}

TEST(OfficeWebSecurity, AnOfficeRoleOfOneTunnelSeesOnlyThatTunnel) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  const Login adit = log_in(c, server.origin(), "adit_office", kAditPassword);
  ASSERT_EQ(adit.status, 200) << adit.error;
  const auto tunnels = c.Get("/api/tunnels", {{"Cookie", adit.cookie}});
  ASSERT_TRUE(tunnels);
  const json list = json::parse(tunnels->body);
  ASSERT_EQ(list.size(), 1u) << tunnels->body;
  EXPECT_EQ(list[0]["name"], "North adit");
  // The other tunnel's drive, by name: as if it did not exist.
  const auto drive =
      c.Get("/api/drive?tunnel=Main%20drive", httplib::Headers{{"Cookie", adit.cookie}});
  ASSERT_TRUE(drive);
  EXPECT_EQ(drive->status, 404) << drive->body;
  EXPECT_EQ(drive->body.find("tablet_a"), std::string::npos);
}

TEST(OfficeWebSecurity, ForgedAndExpiredSessionsAreRefused) {
  // 0.02 min = 1.2 s idle: the session ends while the test waits 2 s.
  OfficeServer server(0.02);
  httplib::Client c("127.0.0.1", server.port());
  const std::string forged = "rockface_session=" + std::string(64, 'a');
  const auto r1 = c.Get("/api/tunnels", {{"Cookie", forged}});
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1->status, 401);
  const auto r2 = c.Get("/api/tunnels", {{"Cookie", "rockface_session=../../etc/passwd"}});
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2->status, 401);
  const auto r3 = c.Get("/api/tunnels");
  ASSERT_TRUE(r3);
  EXPECT_EQ(r3->status, 401);

  const Login ok = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(ok.status, 200) << ok.error;
  const auto fresh = c.Get("/api/tunnels", {{"Cookie", ok.cookie}});
  ASSERT_TRUE(fresh);
  EXPECT_EQ(fresh->status, 200);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  const auto stale = c.Get("/api/tunnels", {{"Cookie", ok.cookie}});
  ASSERT_TRUE(stale);
  EXPECT_EQ(stale->status, 401) << "the session outlived its idle time";
  EXPECT_NE(stale->get_header_value("Set-Cookie").find("Max-Age=0"), std::string::npos)
      << "the browser is told to drop the cookie";
}

TEST(OfficeWebSecurity, RequestsFromAnotherSiteAreRefused) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  // A log-in form posted from another site (login CSRF).
  EXPECT_EQ(log_in(c, "https://evil.example", "office_reader", kOfficePassword).status, 403);
  const auto no_origin =
      c.Post("/api/login", json{{"role", "office_reader"}, {"password", kOfficePassword}}.dump(),
             "application/json");
  ASSERT_TRUE(no_origin);
  EXPECT_EQ(no_origin->status, 403) << "a POST without Origin";

  const Login ok = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(ok.status, 200);
  // Log-out from another site, and from this one without the session's token.
  const auto cross = c.Post("/api/logout",
                            {{"Cookie", ok.cookie},
                             {"Origin", server.origin()},
                             {"Sec-Fetch-Site", "cross-site"},
                             {"X-Rockface-CSRF", ok.csrf}},
                            "{}", "application/json");
  ASSERT_TRUE(cross);
  EXPECT_EQ(cross->status, 403);
  const auto no_token = c.Post("/api/logout", {{"Cookie", ok.cookie}, {"Origin", server.origin()}},
                               "{}", "application/json");
  ASSERT_TRUE(no_token);
  EXPECT_EQ(no_token->status, 403);
  const auto still = c.Get("/api/tunnels", {{"Cookie", ok.cookie}});
  ASSERT_TRUE(still);
  EXPECT_EQ(still->status, 200) << "the refused requests ended nothing";
  const auto out =
      c.Post("/api/logout",
             {{"Cookie", ok.cookie}, {"Origin", server.origin()}, {"X-Rockface-CSRF", ok.csrf}},
             "{}", "application/json");
  ASSERT_TRUE(out);
  EXPECT_EQ(out->status, 200);
  const auto after = c.Get("/api/tunnels", {{"Cookie", ok.cookie}});
  ASSERT_TRUE(after);
  EXPECT_EQ(after->status, 401);
}

TEST(OfficeWebSecurity, EveryResponseCarriesTheHeadersAndDataIsServedAsData) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  const Login ok = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(ok.status, 200);
  const httplib::Headers auth = {{"Cookie", ok.cookie}};
  for (const std::string path :
       {"/", "/assets/app.js", "/assets/style.css", "/assets/nothing.js", "/no/such/page",
        "/three/build/three.module.js", "/api/session", "/api/tunnels",
        "/api/drive?tunnel=Main%20drive", "/api/drive?tunnel=none"}) {
    const auto r = c.Get(path.c_str(), auth);
    expect_security_headers(r, path);
  }
  expect_security_headers(c.Get("/api/tunnels"), "401");
  // The page has no inline script: every script is a module file.
  const auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_NE(page->body.find("<script type=\"module\" src=\"/assets/app.js\"></script>"),
            std::string::npos);
  EXPECT_EQ(page->body.find("<script>"), std::string::npos);
  // The stored note comes back as a JSON string, never as markup.
  const auto drive = c.Get("/api/drive?tunnel=Main%20drive", auth);
  ASSERT_TRUE(drive);
  ASSERT_EQ(drive->status, 200);
  EXPECT_EQ(drive->get_header_value("Content-Type"), "application/json; charset=utf-8");
  const json d = json::parse(drive->body);
  bool found = false;
  for (const auto& v : d["visits"]) found |= v["note"] == kScriptNote;
  EXPECT_TRUE(found) << "the note reaches the page unchanged, to be shown as text";
}

}  // namespace
}  // namespace rockface::office_web_test
