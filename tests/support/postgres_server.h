#pragma once
// A real PostgreSQL server for a test binary (Debian's postgresql package,
// /usr/lib/postgresql/<version>/bin): initdb in a fresh temporary folder,
// started with pg_ctl on a Unix socket in that folder (and, with TLS, on
// 127.0.0.1 with a certificate signed by a CA made here with openssl),
// stopped and removed when destroyed. PostgreSQL refuses to run as root:
// when the test runs as root (CI), the server runs as user nobody
// (setpriv), owning the folder. One server per test binary: start it in a
// GoogleTest environment or a static fixture.
#include <filesystem>
#include <string>

namespace rockface::test {

class PostgresServer {
 public:
  struct Options {
    bool tls = false;  // also listen on 127.0.0.1 with TLS (hostssl, scram-sha-256)
  };
  explicit PostgresServer(Options options);
  PostgresServer() : PostgresServer(Options{}) {}
  ~PostgresServer();
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;

  // Over the Unix socket (trust authentication), as `user`, to database `db`.
  std::string socket_conninfo(const std::string& user, const std::string& db = "rockface") const;
  // Over TCP to localhost with sslmode=verify-full against the test's CA
  // (the password comes from a pgpass file: see write_pgpass).
  std::string tls_conninfo(const std::string& user, const std::string& db = "rockface") const;
  // The superuser of the cluster.
  static constexpr const char* kSuperuser = "postgres";
  // Runs SQL as the superuser with psql; returns its output, throws on failure.
  std::string psql(const std::string& sql, const std::string& db = "rockface") const;
  // A pgpass file (mode 0600) with one line; libpq reads it via PGPASSFILE.
  std::filesystem::path write_pgpass(const std::string& user, const std::string& password) const;

  void stop();  // immediate: as if the server's machine lost power
  void start();
  bool running() const { return running_; }
  const std::filesystem::path& folder() const { return dir_; }
  const std::filesystem::path& ca_certificate() const { return ca_cert_; }
  int port() const { return port_; }

 private:
  std::string as_server_user(const std::string& command) const;
  void make_certificates();

  Options options_;
  std::filesystem::path dir_, data_, ca_cert_;
  std::filesystem::path bin_;
  int port_ = 0;
  bool running_ = false;
  bool as_nobody_ = false;
};

}  // namespace rockface::test
