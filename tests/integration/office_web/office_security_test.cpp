// The office web server's refusals over plain HTTP requests (issue 46): a
// wrong password, a tablet's role, an office role of another tunnel, an
// expired session, a forged cookie, a request from another site; the
// security headers on every response; a stored script served as data.
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "firmware-app/office/web_server.h"
#include "tests/integration/office_web/office_client.h"
#include "tests/integration/office_web/office_site.h"
#include "tests/support/test_paths.h"

namespace rockface::office_web_test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

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

  // No password a person typed is kept or logged by the server: not in its
  // log (stdout and stderr, what systemd's journal gets) nor in any file
  // it wrote in its work folder (the site's folder holds both; the web
  // service's own passfile is the one file meant to hold a password).
  const Site& s = site();
  for (const auto& e : fs::recursive_directory_iterator(s.folder)) {
    if (!e.is_regular_file() || e.path().extension() == ".pgpass") continue;
    std::ifstream in(e.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* typed : {kOfficePassword, kTabletPassword, "not the password"})
      EXPECT_EQ(bytes.find(typed), std::string::npos)
          << e.path() << " holds the password \"" << typed << "\"";
  }
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

// The drive pages and pulled copies are shared by sessions whose roles read
// the same tunnels (firmware-app/office/office_shared_cache.h): each role
// here reads a different set, and each request is made right after another
// role's filled the cache with what it may not read.
TEST(OfficeWebSecurity, RolesOfDifferentTunnelsNeverSeeEachOthersVisitsThroughTheCache) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  const Login all = log_in(c, server.origin(), "office_reader", kOfficePassword);
  const Login adit = log_in(c, server.origin(), "adit_office", kAditPassword);
  const Login main = log_in(c, server.origin(), "main_office", kMainOfficePassword);
  ASSERT_EQ(all.status, 200) << all.error;
  ASSERT_EQ(adit.status, 200) << adit.error;
  ASSERT_EQ(main.status, 200) << main.error;
  auto get = [&](const Login& who, const std::string& path) {
    const auto r = c.Get(path.c_str(), httplib::Headers{{"Cookie", who.cookie}});
    EXPECT_TRUE(r) << path;
    return r ? std::make_pair(r->status, r->body) : std::make_pair(0, std::string());
  };
  auto visit_ids = [](const std::string& body) {
    std::set<std::string> ids;
    const json page = json::parse(body);
    for (const auto& v : page["visits"]) ids.insert(v["id"].get<std::string>());
    return ids;
  };
  auto tablets = [](const std::string& body) {
    std::set<std::string> t;
    const json page = json::parse(body);
    for (const auto& v : page["visits"]) t.insert(v["tablet"].get<std::string>());
    return t;
  };
  const std::string main_drive = "/api/drive?tunnel=Main%20drive";
  const std::string adit_drive = "/api/drive?tunnel=North%20adit";

  // rockface_office fills the cache with both tunnels.
  const auto all_main = get(all, main_drive);
  const auto all_adit = get(all, adit_drive);
  ASSERT_EQ(all_main.first, 200) << all_main.second;
  ASSERT_EQ(all_adit.first, 200) << all_adit.second;
  const std::set<std::string> main_ids = visit_ids(all_main.second);
  const std::set<std::string> adit_ids = visit_ids(all_adit.second);
  ASSERT_EQ(main_ids.size(), 4u) << "tablet A's two, tablet B's two";
  ASSERT_FALSE(adit_ids.empty());
  EXPECT_EQ(tablets(all_adit.second), std::set<std::string>{"tablet_c"});

  // Each one-tunnel role: the other tunnel as if it did not exist, its own
  // tunnel with exactly its own visits.
  const auto adit_main = get(adit, main_drive);
  EXPECT_EQ(adit_main.first, 404) << adit_main.second;
  EXPECT_EQ(adit_main.second.find("tablet_a"), std::string::npos);
  const auto adit_adit = get(adit, adit_drive);
  ASSERT_EQ(adit_adit.first, 200) << adit_adit.second;
  EXPECT_EQ(visit_ids(adit_adit.second), adit_ids);
  const auto main_adit = get(main, adit_drive);
  EXPECT_EQ(main_adit.first, 404) << main_adit.second;
  EXPECT_EQ(main_adit.second.find("tablet_c"), std::string::npos);
  const auto main_main = get(main, main_drive);
  ASSERT_EQ(main_main.first, 200) << main_main.second;
  EXPECT_EQ(visit_ids(main_main.second), main_ids);
  EXPECT_EQ(tablets(main_main.second), (std::set<std::string>{"tablet_a", "tablet_b"}));
  // The stamp the pages poll: refused the same way.
  EXPECT_EQ(get(adit, "/api/stamp?tunnel=Main%20drive").first, 404);

  // A visit of the other tunnel, once its tunnel has been pulled for a
  // role that may read it: named under the role's own tunnel or the other.
  const std::string main_visit = *main_ids.begin();
  ASSERT_EQ(get(all, "/api/visit?tunnel=Main%20drive&visit=" + main_visit).first, 200);
  const auto by_own = get(adit, "/api/visit?tunnel=North%20adit&visit=" + main_visit);
  EXPECT_EQ(by_own.first, 404) << by_own.second;
  const auto by_other = get(adit, "/api/visit?tunnel=Main%20drive&visit=" + main_visit);
  EXPECT_EQ(by_other.first, 404) << by_other.second;
  EXPECT_EQ(get(main, "/api/visit?tunnel=Main%20drive&visit=" + main_visit).first, 200);
}

TEST(OfficeWebSecurity, FiveFailedLogInsAMinuteThenTheAddressWaits) {
  OfficeServer server;  // a server of its own: its count starts at zero
  httplib::Client c("127.0.0.1", server.port());
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(log_in(c, server.origin(), "office_reader", "guess " + std::to_string(i)).status, 403)
        << i;
  // The right password now waits too: PostgreSQL is not even asked.
  httplib::Headers h = {{"Origin", server.origin()}};
  const auto held =
      c.Post("/api/login", h, json{{"role", "office_reader"}, {"password", kOfficePassword}}.dump(),
             "application/json");
  ASSERT_TRUE(held);
  EXPECT_EQ(held->status, 429) << held->body;
  EXPECT_EQ(held->get_header_value("Set-Cookie"), "");
  const int wait = std::stoi("0" + held->get_header_value("Retry-After"));
  // Five failures within the last few seconds: the first leaves the
  // one-minute window in at most 60 s and at least 1 s.
  EXPECT_GE(wait, 1);
  EXPECT_LE(wait, 60);
  EXPECT_NE(json::parse(held->body).value("error", "").find("try again"), std::string::npos);
  // Another role from the same address waits as well.
  EXPECT_EQ(log_in(c, server.origin(), "adit_office", kAditPassword).status, 429);
}

// The count per role let anyone keep a person out of their own role for a
// minute (five wrong guesses at it). The person's own browser, known from
// an earlier log-in as that role, still logs in; a stranger, and the same
// browser as another role, are still held; the known browser's own
// failures hold it.
TEST(OfficeWebSecurity, GuessesAtARoleDoNotKeepItsOwnBrowserOut) {
  OfficeServer server;  // a server of its own: its count starts at zero
  httplib::Client c("127.0.0.1", server.port());
  const Login first = log_in(c, server.origin(), "main_office", kMainOfficePassword);
  ASSERT_EQ(first.status, 200) << first.error;
  ASSERT_FALSE(first.known.empty()) << "no known-browser cookie: " << first.set_cookie;
  // A stranger guesses at main_office five times (another browser: no cookie).
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(log_in(c, server.origin(), "main_office", "guess " + std::to_string(i)).status, 403)
        << i;
  EXPECT_EQ(log_in(c, server.origin(), "main_office", kMainOfficePassword).status, 429)
      << "a browser never seen is held by the role's count";
  // The person's browser: let in with the right password.
  const Login again = log_in(c, server.origin(), "main_office", kMainOfficePassword, first.known);
  EXPECT_EQ(again.status, 200) << again.error;
  EXPECT_TRUE(again.known.empty()) << "an already known browser gets no second token";
  // Its token is for main_office only: as another role it is a stranger
  // from an address that has failed five times.
  EXPECT_EQ(log_in(c, server.origin(), "adit_office", kAditPassword, first.known).status, 429);
  // A forged token vouches for nothing.
  EXPECT_EQ(log_in(c, server.origin(), "main_office", kMainOfficePassword,
                   "rockface_known=" + std::string(64, 'a'))
                .status,
            429);
  // The known browser's own wrong guesses are counted against it: five,
  // then it waits too.
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(
        log_in(c, server.origin(), "main_office", "wrong " + std::to_string(i), first.known).status,
        403)
        << i;
  EXPECT_EQ(log_in(c, server.origin(), "main_office", kMainOfficePassword, first.known).status,
            429);
}

// A self-signed certificate for `address` (an IP), made with openssl
// (Debian: openssl); false when none was made.
bool make_certificate(const std::filesystem::path& cert, const std::filesystem::path& key,
                      const std::string& address) {
  const std::string make =
      "openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days 1 "
      "-subj /CN=" +
      address + " -addext subjectAltName=IP:" + address + " -keyout '" + key.string() + "' -out '" +
      cert.string() + "' 2>/dev/null";
  return std::system(make.c_str()) == 0;
}

// The office reader's log-in over HTTPS, the server verified by `cert`.
httplib::Result tls_log_in(httplib::SSLClient& c, const std::filesystem::path& cert,
                           const std::string& origin) {
  c.set_ca_cert_path(cert.c_str());
  c.enable_server_certificate_verification(true);
  return c.Post("/api/login", {{"Origin", origin}},
                json{{"role", "office_reader"}, {"password", kOfficePassword}}.dump(),
                "application/json");
}

// `office serve --tls`: a self-signed certificate for 127.0.0.1 made here
// with openssl, a client that verifies it, the session's cookie Secure and
// __Host- prefixed, HSTS on every answer, and no plain HTTP on that port.
TEST(OfficeWebSecurity, OverTlsTheCookieIsSecureAndHostOnly) {
  namespace fs = std::filesystem;
  const fs::path dir = site().folder / "tls";
  fs::create_directories(dir);
  const fs::path cert = dir / "cert.pem", key = dir / "key.pem";
  ASSERT_TRUE(make_certificate(cert, key, "127.0.0.1"))
      << "openssl (Debian: openssl) made no certificate";
  OfficeServer server(site(), 30, {"--tls", cert.string() + "," + key.string()});
  const std::string origin = "https://127.0.0.1:" + std::to_string(server.port());

  httplib::SSLClient c("127.0.0.1", server.port());
  const auto r = tls_log_in(c, cert, origin);
  ASSERT_TRUE(r) << "the HTTPS request failed: " << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200) << r->body;
  const std::string set = r->get_header_value("Set-Cookie");
  EXPECT_EQ(set.rfind("__Host-rockface_session=", 0), 0u) << set;
  EXPECT_NE(set.find("; Secure"), std::string::npos) << set;
  EXPECT_NE(set.find("HttpOnly"), std::string::npos) << set;
  EXPECT_NE(set.find("Path=/"), std::string::npos) << "__Host- cookies need Path=/: " << set;
  EXPECT_EQ(set.find("Domain"), std::string::npos) << "__Host- cookies have no Domain: " << set;
  EXPECT_NE(r->get_header_value("Strict-Transport-Security").find("max-age="), std::string::npos);
  const std::string cookie = set.substr(0, set.find(';'));
  const auto tunnels = c.Get("/api/tunnels", {{"Cookie", cookie}});
  ASSERT_TRUE(tunnels);
  EXPECT_EQ(tunnels->status, 200) << tunnels->body;
  expect_security_headers(tunnels, "/api/tunnels over TLS");
  // The plain-HTTP cookie's name is not this server's session.
  const auto plain_name = c.Get(
      "/api/tunnels", {{"Cookie", "rockface_session=" + cookie.substr(cookie.find('=') + 1)}});
  ASSERT_TRUE(plain_name);
  EXPECT_EQ(plain_name->status, 401);

  // Plain HTTP to the TLS port gets no page.
  httplib::Client plain("127.0.0.1", server.port());
  plain.set_read_timeout(std::chrono::seconds(5));
  const auto p = plain.Get("/api/session");
  EXPECT_TRUE(!p || p->status >= 400) << "plain HTTP was answered " << (p ? p->status : 0);
}

// A non-loopback IPv4 address of this machine (an interface that is up),
// or "" when it has none.
std::string machine_address() {
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return "";
  std::string found;
  for (ifaddrs* i = list; i && found.empty(); i = i->ifa_next) {
    if (!i->ifa_addr || i->ifa_addr->sa_family != AF_INET || !(i->ifa_flags & IFF_UP) ||
        (i->ifa_flags & IFF_LOOPBACK))
      continue;
    char text[INET_ADDRSTRLEN] = {};
    const auto* in = reinterpret_cast<const sockaddr_in*>(i->ifa_addr);
    if (::inet_ntop(AF_INET, &in->sin_addr, text, sizeof text)) found = text;
  }
  ::freeifaddrs(list);
  return found;
}

// `office serve --listen ADDR:PORT` serves plain HTTP on a loopback address
// only (a reverse proxy speaking TLS in front of it); anywhere else it
// wants --tls (firmware-app/office/web_server.h): it refuses to start,
// naming both options, before it listens.
TEST(OfficeWebSecurity, PlainHttpIsServedOnALoopbackAddressOnly) {
  // What counts as loopback: addresses as written, never a name that might
  // resolve elsewhere.
  for (const char* loopback : {"127.0.0.1", "127.0.0.2", "127.255.255.254", "::1", "[::1]",
                               "::ffff:127.0.0.1", "localhost"})
    EXPECT_TRUE(app::is_loopback_address(loopback)) << loopback;
  for (const char* other :
       {"0.0.0.0", "::", "[::]", "192.0.2.2", "10.0.0.1", "128.0.0.1", "::ffff:192.0.2.2",
        "127.example.org", "127.0.0.1.example.org", "localhost.example.org", "", "[::1"})
    EXPECT_FALSE(app::is_loopback_address(other)) << other;

  // The verb refuses those without --tls. A server that started anyway is
  // stopped by `timeout` (exit 124).
  const fs::path dir = site().folder / ("plain-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const std::string& listen :
       std::vector<std::string>{"0.0.0.0:0", "[::]:0", "192.0.2.77:8046", "127.example.org:0",
                                machine_address() + ":0"}) {
    if (listen == ":0") continue;  // no address of this machine but loopback
    const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
    const std::string command = "timeout 30 " + std::string(ROCKFACE_BINARY_DIR) +
                                "/rockface office serve '" + site().server + "' --listen '" +
                                listen + "' --work '" + dir.string() + "' >" + out + " 2>" + err;
    const int status = std::system(command.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err);
    const std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(code, 124) << listen << ": it served plain HTTP off loopback";
    EXPECT_NE(code, 0) << listen;
    EXPECT_NE(said.find("--listen"), std::string::npos) << listen << ": " << said;
    EXPECT_NE(said.find("--tls CERT,KEY"), std::string::npos) << listen << ": " << said;
    EXPECT_NE(said.find("loopback"), std::string::npos) << listen << ": " << said;
  }

  // Another loopback address is served plain, as 127.0.0.1 is (every other
  // test): a log-in there answers, its cookie not marked Secure (a browser
  // would not send it back over plain HTTP).
  {
    OfficeServer server(site(), 30, {}, "127.0.0.2:0");
    httplib::Client c("127.0.0.2", server.port());
    const Login office = log_in(c, "http://127.0.0.2:" + std::to_string(server.port()),
                                "office_reader", kOfficePassword);
    ASSERT_EQ(office.status, 200) << office.error;
    EXPECT_EQ(office.set_cookie.find("Secure"), std::string::npos) << office.set_cookie;
  }

  // With --tls it serves off loopback: on this machine's own address, its
  // session cookie Secure.
  const std::string address = machine_address();
  if (address.empty()) GTEST_SKIP() << "this machine has no address but loopback";
  const fs::path cert = dir / "cert.pem", key = dir / "key.pem";
  ASSERT_TRUE(make_certificate(cert, key, address))
      << "openssl (Debian: openssl) made no certificate";
  OfficeServer server(site(), 30, {"--tls", cert.string() + "," + key.string()}, address + ":0");
  httplib::SSLClient c(address, server.port());
  const auto r = tls_log_in(c, cert, "https://" + address + ":" + std::to_string(server.port()));
  ASSERT_TRUE(r) << "the HTTPS request failed: " << httplib::to_string(r.error());
  ASSERT_EQ(r->status, 200) << r->body;
  const std::string set = r->get_header_value("Set-Cookie");
  EXPECT_EQ(set.rfind("__Host-rockface_session=", 0), 0u) << set;
  EXPECT_NE(set.find("; Secure"), std::string::npos) << set;
  EXPECT_NE(set.find("HttpOnly"), std::string::npos) << set;
  std::error_code ec;
  if (!::testing::Test::HasFailure()) fs::remove_all(dir, ec);
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
