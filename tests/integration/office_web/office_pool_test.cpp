// The office server's database connections (issue 46): a bounded pool
// shared by every logged-in person, each request acting as its person's
// role, where each person held a connection of their own (fifty people,
// fifty of PostgreSQL's slots).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "storage/office/connection_pool.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_schema.h"
#include "tests/integration/office_web/office_site.h"
#include "tests/storage/office/office_environment.h"

// Last: <resolv.h>, which httplib.h includes, defines the macro _res that
// Eigen uses as a parameter name.
#include "tests/integration/office_web/office_client.h"

namespace rockface::office_web_test {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;
namespace office = storage::office;
namespace fs = std::filesystem;

std::string current_user(office::Connection& c) {
  return c.query("SELECT current_user", {}, "asking who").text(0, 0);
}

TEST(OfficePool, ALeaseActsAsItsRoleAndTheSlotsAreBounded) {
  const Site& s = site();
  office::ConnectionPool pool(s.server, 1, std::chrono::milliseconds(300));
  {
    auto adit = pool.acquire("adit_office");
    EXPECT_EQ(current_user(adit.db()), "adit_office");
    // Row-level security as that person: one tunnel.
    const office::Result r =
        adit.db().query("SELECT name FROM rockface.tunnel", {}, "reading the tunnels");
    ASSERT_EQ(r.rows(), 1);
    EXPECT_EQ(r.text(0, 0), "North adit");
    // The one slot is lent: the next waits its 300 ms, then is told so.
    const auto t0 = Clock::now();
    EXPECT_THROW(pool.acquire("office_reader"), office::PoolBusy);
    EXPECT_GE(Clock::now() - t0, std::chrono::milliseconds(300));
    // A request that failed inside a transaction gives its connection back usable.
    adit.db().exec("BEGIN", "a request");
    EXPECT_THROW(adit.db().exec("SELECT no_such_column FROM rockface.tunnel", "a bad request"),
                 office::ServerError);
  }
  // The same connection, reset: the next person is who they are.
  auto reader = pool.acquire("office_reader");
  EXPECT_EQ(current_user(reader.db()), "office_reader");
  EXPECT_EQ(pool.open(), 1u);
  // Read-only whoever it acts as.
  EXPECT_THROW(reader.db().exec("CREATE TEMP TABLE t (x int)", "writing"), office::ServerError);
}

TEST(OfficePool, TheServiceRoleActsAsNoTabletAndNoOtherRole) {
  const Site& s = site();
  office::ConnectionPool pool(s.server, 1, std::chrono::seconds(5));
  for (const char* role : {"tablet_a", "postgres", "rockface_admin"}) {
    try {
      pool.acquire(role);
      ADD_FAILURE() << "the pool acted as " << role;
    } catch (const office::ServerError& e) {
      EXPECT_EQ(e.sqlstate(), "42501") << role << ": " << e.what();
    }
  }
}

// Six people on a server of two connections, all asking at once: every
// request served, each person seeing their own tunnels, never more than two
// connections of the server at the database, and no person's own.
TEST(OfficePool, MoreUsersThanConnectionsAreAllServed) {
  const Site& s = site();
  const std::map<std::string, std::string> passwords = {
      {"office_reader", kOfficePassword}, {"main_office", kMainOfficePassword},
      {"adit_office", kAditPassword},     {"pool_reader_1", "pool pass 1"},
      {"pool_reader_2", "pool pass 2"},   {"pool_reader_3", "pool pass 3"}};
  {
    office::Connection c(office_test::as_superuser(s.database));
    for (int i = 1; i <= 3; ++i) office::add_office_user(c, "pool_reader_" + std::to_string(i));
  }
  for (int i = 1; i <= 3; ++i)
    office_test::server().psql("ALTER ROLE pool_reader_" + std::to_string(i) +
                                   " PASSWORD 'pool pass " + std::to_string(i) + "'",
                               s.database);
  OfficeServer server(s, 30, {"--pool", "2", "--pool-wait-seconds", "120"});
  std::map<std::string, std::string> cookies;
  for (const auto& [role, password] : passwords) {
    httplib::Client c("127.0.0.1", server.port());
    const Login l = log_in(c, server.origin(), role, password);
    ASSERT_EQ(l.status, 200) << role << ": " << l.error;
    cookies[role] = l.cookie;
  }
  office::Connection super(office_test::as_superuser(s.database));
  auto backends = [&](const std::string& who) {
    return static_cast<int>(super
                                .query("SELECT count(*) FROM pg_stat_activity WHERE usename = "
                                       "ANY(string_to_array($1, ','))",
                                       {office::Param::of(who)}, "counting connections")
                                .int64(0, 0));
  };
  std::string people;
  for (const auto& [role, password] : passwords) people += (people.empty() ? "" : ",") + role;
  EXPECT_EQ(backends(people), 0) << "a logged-in person holds a connection of their own";

  std::atomic<bool> done{false};
  std::atomic<int> most{0};
  std::thread watch([&] {
    office::Connection w(office_test::as_superuser(s.database));
    while (!done) {
      const int n = static_cast<int>(
          w.query("SELECT count(*) FROM pg_stat_activity WHERE usename = 'office_web'", {},
                  "counting the pool's connections")
              .int64(0, 0));
      most = std::max(most.load(), n);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  std::map<std::string, std::vector<std::string>> seen;
  std::map<std::string, int> failed;
  std::mutex lock;
  std::vector<std::thread> people_asking;
  for (const auto& [role, cookie] : cookies)
    people_asking.emplace_back([&, role = role, cookie = cookie] {
      httplib::Client c("127.0.0.1", server.port());
      c.set_read_timeout(std::chrono::seconds(180));
      for (int i = 0; i < 3; ++i) {
        const auto t = c.Get("/api/tunnels", {{"Cookie", cookie}});
        const auto tunnels = t && t->status == 200 ? json::parse(t->body) : json();
        std::vector<std::string> names;
        for (const auto& tunnel : tunnels) names.push_back(tunnel["name"]);
        const std::string mine = names.empty() ? "Main drive" : names.front();
        const auto d =
            c.Get(("/api/drive?tunnel=" + (mine == "North adit" ? std::string("North%20adit")
                                                                : std::string("Main%20drive")))
                      .c_str(),
                  {{"Cookie", cookie}});
        std::lock_guard guard(lock);
        if (!t || t->status != 200) ++failed[role];
        if (!d || d->status != 200) ++failed[role];
        seen[role] = names;
      }
    });
  for (auto& t : people_asking) t.join();
  done = true;
  watch.join();
  for (const auto& [role, n] : failed) ADD_FAILURE() << role << ": " << n << " requests failed";
  EXPECT_EQ(seen["adit_office"], std::vector<std::string>{"North adit"});
  EXPECT_EQ(seen["main_office"], std::vector<std::string>{"Main drive"});
  EXPECT_EQ(seen["office_reader"].size(), 2u);
  EXPECT_EQ(seen["pool_reader_1"].size(), 2u);
  EXPECT_GT(most.load(), 0);
  EXPECT_LE(most.load(), 2) << "the server held more connections than its pool";
  EXPECT_EQ(backends(people), 0) << "a person's own connection stayed open";
}

// More people than the pool's one connection over HTTP: while a request
// holds it (stalled at the database: the test holds a lock on the
// tunnels), a second person is told "busy, try again" with 503 and
// Retry-After once the pool's wait is over — not a hang, not a 500 — and
// the held request is served when the database answers; so is the second
// person's next request.
TEST(OfficePool, ARequestWaitingPastThePoolsWaitIsToldToTryAgain) {
  const Site& s = site();
  OfficeServer server(s, 30, {"--pool", "1", "--pool-wait-seconds", "1"});
  httplib::Client first("127.0.0.1", server.port()), second("127.0.0.1", server.port());
  first.set_read_timeout(std::chrono::seconds(120));
  second.set_read_timeout(std::chrono::seconds(120));
  const Login a = log_in(first, server.origin(), "office_reader", kOfficePassword);
  const Login b = log_in(second, server.origin(), "main_office", kMainOfficePassword);
  ASSERT_EQ(a.status, 200) << a.error;
  ASSERT_EQ(b.status, 200) << b.error;

  office::Connection locker(office_test::as_superuser(s.database));
  locker.exec("BEGIN; LOCK TABLE rockface.tunnel IN ACCESS EXCLUSIVE MODE", "holding the tunnels");
  std::optional<httplib::Result> held;
  std::thread holding([&] { held.emplace(first.Get("/api/tunnels", {{"Cookie", a.cookie}})); });
  // The first request has the pool's only connection once it waits on the
  // lock at the database.
  office::Connection watch(office_test::as_superuser(s.database));
  const auto until = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < until &&
         watch.query("SELECT count(*) FROM pg_stat_activity WHERE usename = 'office_web' AND "
                     "wait_event_type = 'Lock'",
                     {}, "watching the pool")
                 .int64(0, 0) == 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));

  const auto t0 = Clock::now();
  const auto busy = second.Get("/api/tunnels", {{"Cookie", b.cookie}});
  const auto waited = Clock::now() - t0;
  ASSERT_TRUE(busy);
  EXPECT_EQ(busy->status, 503) << busy->body;
  EXPECT_FALSE(busy->get_header_value("Retry-After").empty());
  EXPECT_NE(json::parse(busy->body).value("error", "").find("busy"), std::string::npos)
      << busy->body;
  // It waited the pool's second (and not the held request's time). The
  // upper bound is the machine's slack under load, not the server's.
  EXPECT_GE(waited, std::chrono::milliseconds(1000));
  EXPECT_LT(waited, std::chrono::seconds(30));

  locker.exec("COMMIT", "letting the tunnels go");
  holding.join();
  ASSERT_TRUE(held.has_value() && *held);
  EXPECT_EQ((*held)->status, 200) << (*held)->body;
  const auto again = second.Get("/api/tunnels", {{"Cookie", b.cookie}});
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 200) << again->body;
}

// A visit opening gives its connection back once it has read the server
// (issue 46's load run: fifty people, a visit opening holding the pool's
// connection through its whole pull, ~10 s, and the others told "busy"
// after the pool's wait). A server of one connection, a visit opening held
// by the server's test gate (firmware-app/office/test_gate.h) first while
// its copy is built, then while its page is put together: each time a
// second person's requests, which need the pool's one connection, are
// answered while the opening is still held; then the opening is answered.
TEST(OfficePool, AVisitOpeningHoldsNoConnectionWhileItsCopyIsBuiltOrItsPageAssembled) {
  const Site& s = site();
  const fs::path gate =
      fs::temp_directory_path() / ("rockface-office-gate-" + std::to_string(::getpid()) + "-" +
                                   std::to_string(Clock::now().time_since_epoch().count()));
  fs::create_directories(gate);
  // The gate is the server's only: this process's other servers have none.
  ::setenv("ROCKFACE_OFFICE_TEST_GATE", gate.c_str(), 1);
  std::optional<OfficeServer> server;
  try {
    server.emplace(s, 30, std::vector<std::string>{"--pool", "1", "--pool-wait-seconds", "2"});
  } catch (...) {
    ::unsetenv("ROCKFACE_OFFICE_TEST_GATE");
    throw;
  }
  ::unsetenv("ROCKFACE_OFFICE_TEST_GATE");
  httplib::Client opener("127.0.0.1", server->port()), other("127.0.0.1", server->port());
  opener.set_read_timeout(std::chrono::seconds(180));
  other.set_read_timeout(std::chrono::seconds(60));
  const Login a = log_in(opener, server->origin(), "office_reader", kOfficePassword);
  const Login b = log_in(other, server->origin(), "main_office", kMainOfficePassword);
  ASSERT_EQ(a.status, 200) << a.error;
  ASSERT_EQ(b.status, 200) << b.error;
  const auto drive = other.Get("/api/drive?tunnel=Main%20drive", {{"Cookie", b.cookie}});
  ASSERT_TRUE(drive && drive->status == 200);
  const std::string visit = json::parse(drive->body).at("visits").at(0).at("id");

  std::atomic<bool> answered{false};
  std::optional<httplib::Result> opened;
  std::thread opening([&] {
    opened.emplace(opener.Get(("/api/visit?tunnel=Main%20drive&visit=" + visit).c_str(),
                              {{"Cookie", a.cookie}}));
    answered = true;
  });
  auto reached = [&](const std::string& point) {
    const auto until = Clock::now() + std::chrono::seconds(120);
    while (!fs::exists(gate / (point + ".reached")) && !answered && Clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return fs::exists(gate / (point + ".reached"));
  };
  // What the other person asks while the opening is held: the tunnels (a
  // query of its own) and the drive (its readable tunnels and stamp).
  auto others_answered = [&](const std::string& point) {
    const auto t = other.Get("/api/tunnels", {{"Cookie", b.cookie}});
    const auto d = other.Get("/api/drive?tunnel=Main%20drive", {{"Cookie", b.cookie}});
    EXPECT_TRUE(t && t->status == 200) << point << ": " << (t ? t->body : "no answer");
    EXPECT_TRUE(d && d->status == 200) << point << ": " << (d ? d->body : "no answer");
    EXPECT_FALSE(answered) << point << ": the opening was not held";
  };
  const bool copy_held = reached("copy-build");
  EXPECT_TRUE(copy_held) << "the visit opening never reached its copy's build";
  if (copy_held) others_answered("while the visit's copy is built");
  std::ofstream(gate / "copy-build.go") << "go\n";
  const bool page_held = reached("visit-assembly");
  EXPECT_TRUE(page_held) << "the visit opening never reached its page";
  if (page_held) others_answered("while the visit's page is put together");
  std::ofstream(gate / "visit-assembly.go") << "go\n";
  opening.join();
  ASSERT_TRUE(opened.has_value() && *opened);
  EXPECT_EQ((*opened)->status, 200) << (*opened)->body;
  EXPECT_EQ(json::parse((*opened)->body).value("id", ""), visit);
  server.reset();
  fs::remove_all(gate);
}

}  // namespace
}  // namespace rockface::office_web_test
