#include "tests/support/postgres_server.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rockface::test {

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void run(const std::string& command, const fs::path& log) {
  const std::string full = command + " >>" + log.string() + " 2>&1";
  if (std::system(full.c_str()) != 0)
    throw std::runtime_error("test server: failed: " + command + "\n" + slurp(log));
}

// A TCP port nobody listens on now (the kernel's choice for port 0).
int free_port() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = 0;
  socklen_t n = sizeof(a);
  if (::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof(a)) != 0 ||
      ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &n) != 0) {
    ::close(s);
    throw std::runtime_error("test server: no free port");
  }
  const int port = ntohs(a.sin_port);
  ::close(s);
  return port;
}

fs::path postgres_bin() {
  for (const char* v : {"17", "16", "15", "14", "13"}) {
    const fs::path bin = fs::path("/usr/lib/postgresql") / v / "bin";
    if (fs::exists(bin / "initdb")) return bin;
  }
  throw std::runtime_error(
      "test server: no PostgreSQL server binaries under /usr/lib/postgresql (tools/setup.sh "
      "installs the postgresql package)");
}

}  // namespace

PostgresServer::PostgresServer(Options options) : options_(options) {
  bin_ = postgres_bin();
  as_nobody_ = ::geteuid() == 0;
  char pattern[] = "/tmp/rockface-pg-XXXXXX";
  if (!::mkdtemp(pattern)) throw std::runtime_error("test server: cannot make a folder");
  dir_ = pattern;
  data_ = dir_ / "data";
  port_ = free_port();
  if (as_nobody_) run("chown nobody:nogroup " + dir_.string(), dir_ / "setup.log");
  if (options_.tls) make_certificates();
  run(as_server_user(bin_.string() + "/initdb -D " + data_.string() + " -U " + kSuperuser +
                     " --auth-local=trust --auth-host=scram-sha-256 -E UTF8 --locale=C --no-sync"),
      dir_ / "setup.log");
  std::ofstream conf(data_ / "postgresql.conf", std::ios::app);
  conf << "\n# rockface test server\nunix_socket_directories = '" << dir_.string() << "'\n"
       << "port = " << port_ << "\n"
       << "listen_addresses = '" << (options_.tls ? "127.0.0.1" : "") << "'\n"
       << "fsync = off\nsynchronous_commit = off\nfull_page_writes = off\n"
       << "max_connections = 40\nshared_buffers = 32MB\n";
  if (options_.tls)
    conf << "ssl = on\nssl_cert_file = '" << (dir_ / "server.crt").string() << "'\n"
         << "ssl_key_file = '" << (dir_ / "server.key").string() << "'\n";
  conf.close();
  if (options_.tls) {
    std::ofstream hba(data_ / "pg_hba.conf", std::ios::trunc);
    hba << "local all all trust\nhostssl all all 127.0.0.1/32 scram-sha-256\n";
  }
  start();
  psql("CREATE DATABASE rockface", "postgres");
}

PostgresServer::~PostgresServer() {
  try {
    if (running_) stop();
  } catch (...) {
  }
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string PostgresServer::as_server_user(const std::string& command) const {
  if (!as_nobody_) return command;
  return "setpriv --reuid=nobody --regid=nogroup --clear-groups " + command;
}

void PostgresServer::make_certificates() {
  const fs::path log = dir_ / "setup.log";
  const std::string d = dir_.string();
  run("openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=rockface-test-CA -keyout " + d +
          "/ca.key -out " + d + "/ca.crt",
      log);
  run("openssl req -newkey rsa:2048 -nodes -subj /CN=localhost -keyout " + d + "/server.key -out " +
          d + "/server.csr",
      log);
  std::ofstream(dir_ / "san.ext") << "subjectAltName=DNS:localhost,IP:127.0.0.1\n";
  run("openssl x509 -req -in " + d + "/server.csr -CA " + d + "/ca.crt -CAkey " + d +
          "/ca.key -CAcreateserial -days 2 -extfile " + d + "/san.ext -out " + d + "/server.crt",
      log);
  fs::permissions(dir_ / "server.key", fs::perms::owner_read | fs::perms::owner_write);
  if (as_nobody_) run("chown nobody:nogroup " + d + "/server.key " + d + "/server.crt", log);
  ca_cert_ = dir_ / "ca.crt";
}

void PostgresServer::start() {
  run(as_server_user(bin_.string() + "/pg_ctl -D " + data_.string() + " -l " +
                     (dir_ / "server.log").string() + " -w -t 60 start"),
      dir_ / "ctl.log");
  running_ = true;
}

void PostgresServer::stop() {
  running_ = false;
  run(as_server_user(bin_.string() + "/pg_ctl -D " + data_.string() + " -m immediate -w stop"),
      dir_ / "ctl.log");
}

std::string PostgresServer::socket_conninfo(const std::string& user, const std::string& db) const {
  return "host=" + dir_.string() + " port=" + std::to_string(port_) + " user=" + user +
         " dbname=" + db;
}

std::string PostgresServer::tls_conninfo(const std::string& user, const std::string& db) const {
  return "postgresql://" + user + "@localhost:" + std::to_string(port_) + "/" + db +
         "?sslmode=verify-full&sslrootcert=" + ca_cert_.string();
}

std::string PostgresServer::psql(const std::string& sql, const std::string& db) const {
  const fs::path file = dir_ / "query.sql", out = dir_ / "query.out";
  std::ofstream(file) << sql << "\n";
  const std::string cmd = bin_.string() + "/psql -X -q -A -t -v ON_ERROR_STOP=1 \"" +
                          socket_conninfo(kSuperuser, db) + "\" -f " + file.string() + " >" +
                          out.string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  const std::string text = slurp(out);
  if (rc != 0) throw std::runtime_error("psql failed: " + sql + "\n" + text);
  return text;
}

fs::path PostgresServer::write_pgpass(const std::string& user, const std::string& password) const {
  const fs::path file = dir_ / ("pgpass-" + user);
  std::ofstream(file) << "localhost:" << port_ << ":*:" << user << ":" << password << "\n";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  return file;
}

}  // namespace rockface::test
