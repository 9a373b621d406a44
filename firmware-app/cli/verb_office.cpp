// `rockface office serve postgresql://HOST/DB --listen ADDR:PORT [--tls
// CERT,KEY]`: the office's view of the database in a browser (issue 46;
// firmware-app/office/web_server.h). Runs until SIGTERM or SIGINT.
#include <pthread.h>
#include <signal.h>

#include <cstdint>
#include <iostream>
#include <memory>
#include <thread>

#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/office/web_server.h"

namespace rockface::app {
namespace {

struct OfficeOptions {
  std::string server, listen = "127.0.0.1:8046", tls, work;
  double session_minutes = 30;
  int pool = 8;
  double pool_wait_seconds = 10;
};

VerbRun setup_office(CLI::App& sub) {
  auto o = std::make_shared<OfficeOptions>();
  sub.require_subcommand(1);
  CLI::App* serve = sub.add_subcommand(
      "serve", "serve the office's pages: tunnels, drives, visits, 3D faces, reports");
  serve
      ->add_option("SERVER", o->server,
                   "the office database as the web server's own role (`rockface server add-web`; "
                   "postgresql://ROLE@HOST/DB or service=NAME, its password in a passfile): each "
                   "person logs in with their own role, which the server's connections act as")
      ->required();
  serve->add_option("--listen", o->listen, "ADDR:PORT to listen on (default 127.0.0.1:8046)");
  serve->add_option("--tls", o->tls, "CERT,KEY: serve HTTPS with this certificate (PEM files)");
  serve
      ->add_option("--session-minutes", o->session_minutes,
                   "a session ends after this many minutes without a request (default 30; "
                   "a fraction for tests)")
      ->check(CLI::Range(0.001, 24.0 * 60));
  serve
      ->add_option("--pool", o->pool,
                   "database connections shared by every logged-in person (default 8)")
      ->check(CLI::Range(1, 200));
  serve
      ->add_option("--pool-wait-seconds", o->pool_wait_seconds,
                   "a request waits this long for a free connection, then is answered \"busy, "
                   "try again\" (default 10)")
      ->check(CLI::Range(0.001, 600.0));
  serve->add_option("--work", o->work, "folder for the sessions' pulled copies (default: /tmp)");
  return [o] {
    OfficeServeOptions options;
    options.server = o->server;
    const std::size_t colon = o->listen.rfind(':');
    if (colon == std::string::npos || colon + 1 == o->listen.size())
      throw InputError("--listen", "give ADDR:PORT, e.g. 127.0.0.1:8046");
    options.listen_host = o->listen.substr(0, colon);
    // An IPv6 address is written in brackets before its port ([::1]:8046).
    if (options.listen_host.size() > 2 && options.listen_host.front() == '[' &&
        options.listen_host.back() == ']')
      options.listen_host = options.listen_host.substr(1, options.listen_host.size() - 2);
    try {
      options.listen_port = std::stoi(o->listen.substr(colon + 1));
    } catch (const std::exception&) {
      throw InputError("--listen", "the port is not a number");
    }
    if (!o->tls.empty()) {
      const std::size_t comma = o->tls.find(',');
      if (comma == std::string::npos) throw InputError("--tls", "give CERT,KEY");
      options.tls_certificate = o->tls.substr(0, comma);
      options.tls_key = o->tls.substr(comma + 1);
    }
    options.session_idle =
        std::chrono::milliseconds(static_cast<std::int64_t>(o->session_minutes * 60000));
    options.work_folder = o->work;
    options.pool_size = static_cast<std::size_t>(o->pool);
    options.pool_wait =
        std::chrono::milliseconds(static_cast<std::int64_t>(o->pool_wait_seconds * 1000));
    options.log_failure = [](const std::string& what) {
      std::cerr << "office: " << what << std::endl;
    };

    // SIGTERM (systemd) and SIGINT stop the server: waited for on a thread
    // of their own, since stopping is not safe from a signal handler.
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGTERM);
    sigaddset(&stop_signals, SIGINT);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
    std::thread([stop_signals] {
      int signal = 0;
      sigwait(&stop_signals, &signal);
      stop_office_server();
    }).detach();

    serve_office(options, [&](int port) {
      std::cout << "office: serving " << (options.tls_certificate.empty() ? "http" : "https")
                << "://" << options.listen_host << ":" << port << "/ (sessions end after "
                << o->session_minutes << " min idle; " << o->pool << " database connections)"
                << std::endl;
    });
    std::cout << "office: stopped\n";
    return 0;
  };
}

const VerbRegistrar office_verb{
    "office",
    "the office in a browser: `office serve postgresql://...` serves the tunnels, drives, "
    "visits with their 3D faces and reports to office roles of the database",
    setup_office};

}  // namespace
}  // namespace rockface::app
