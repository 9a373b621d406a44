#pragma once
// `rockface office serve`: the office's view of the database in a browser
// (issue 46). A cpp-httplib server (Debian's libcpp-httplib) serving the
// pages compiled into the binary (web_assets.h), three.js from Debian's
// libjs-three, and the pages' data as JSON from the same reads as `rockface
// drive postgresql://...` and `pull`, each request on a pooled connection
// acting as the session's role (office_sessions.h). Plain HTTP only on a loopback address;
// anything else needs --tls.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

namespace rockface::app {

struct OfficeServeOptions {
  // libpq connection string of the web server's service role (`rockface
  // server add-web`; its password in a passfile), which the pool connects
  // as; the log-ins' own user and password replace its user to check them.
  std::string server;
  std::string listen_host;                         // e.g. "127.0.0.1"
  int listen_port = 8046;                          // 0: any free port (reported by on_listening)
  std::filesystem::path tls_certificate, tls_key;  // both or neither
  std::chrono::milliseconds session_idle{30 * 60 * 1000};
  // The database connections the sessions' requests share (storage/office/
  // connection_pool.h: acting as each person's role); a request waits this
  // long for one, then is answered 503 "busy, try again".
  std::size_t pool_size = 8;
  std::chrono::milliseconds pool_wait{10000};
  // Where the sessions' pulled copies live (removed with each session);
  // empty: a folder under the system's temporary folder.
  std::filesystem::path work_folder;
  // Where three.js is (Debian's libjs-three).
  std::filesystem::path three_folder = "/usr/share/javascript/three";
  // Told what failed on the server's side (the database's message, the
  // request's path; never a password or a token): the verb prints it on
  // stderr, which systemd keeps in the journal.
  std::function<void(const std::string&)> log_failure = [](const std::string&) {};
};

// Whether a listen address is a loopback one (127.0.0.0/8, ::1 with or
// without brackets, ::ffff:127.0.0.0/104, "localhost"): the only ones
// served without TLS. Any other name is not, whatever it resolves to.
bool is_loopback_address(const std::string& host);

// Serves until stop_office_server() (or SIGTERM / SIGINT through the verb).
// Throws InputError for options that cannot work (a non-loopback address
// without TLS, a certificate without a key, a port in use).
// `on_listening` is told the port once the socket is bound.
void serve_office(const OfficeServeOptions& options,
                  const std::function<void(int port)>& on_listening);
void stop_office_server();

}  // namespace rockface::app
