#pragma once
// A small RAII layer over libpq's C API (Debian's libpq 15) for the office
// server: one connection, queries with text parameters or binary ones,
// transactions, and errors turned into rockface::Error messages that never
// carry a password.
//
// Connection strings are libpq's own: a URL (postgresql://user@host/db?
// sslmode=verify-full), key=value pairs, or service=NAME looked up in
// ~/.pg_service.conf or PGSYSCONFDIR/pg_service.conf; a password comes from
// ~/.pgpass (PGPASSFILE) or the PG* environment as libpq users expect.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

struct pg_conn;
struct pg_result;

namespace rockface::storage::office {

// The connection string with any password replaced by "****", for messages
// and for what a project remembers of its server.
std::string masked_conninfo(std::string_view conninfo);

// A failed server call. sqlstate is PostgreSQL's five-character code
// ("42501" insufficient privilege, "08006" connection failure, ...), empty
// when the connection itself is gone.
class ServerError : public std::runtime_error {
 public:
  ServerError(std::string message, std::string sqlstate, bool connection_lost)
      : std::runtime_error(std::move(message)),
        sqlstate_(std::move(sqlstate)),
        connection_lost_(connection_lost) {}
  const std::string& sqlstate() const { return sqlstate_; }
  // The server could not be reached or went away (no network, stopped).
  bool connection_lost() const { return connection_lost_; }

 private:
  std::string sqlstate_;
  bool connection_lost_;
};

class Result {
 public:
  explicit Result(pg_result* r) : r_(r) {}
  ~Result();
  Result(Result&& o) noexcept : r_(o.r_) { o.r_ = nullptr; }
  Result& operator=(Result&& o) noexcept;
  Result(const Result&) = delete;
  Result& operator=(const Result&) = delete;

  int rows() const;
  bool is_null(int row, int column) const;
  std::string text(int row, int column) const;
  std::int64_t int64(int row, int column) const;
  std::optional<std::string> optional_text(int row, int column) const;
  // The raw bytes of a column fetched in binary format (a bytea).
  std::span<const std::uint8_t> bytes(int row, int column) const;

 private:
  pg_result* r_ = nullptr;
};

// One parameter: text, NULL, or binary bytes (a bytea, sent as they are).
struct Param {
  enum class Kind { text, null, binary };
  Kind kind = Kind::null;
  std::string text;
  std::span<const std::uint8_t> bytes;

  static Param null() { return {}; }
  static Param of(std::string value) { return {Kind::text, std::move(value), {}}; }
  static Param of(std::int64_t value) { return of(std::to_string(value)); }
  static Param of(std::optional<std::string> value) {
    return value ? of(std::move(*value)) : null();
  }
  static Param binary(std::span<const std::uint8_t> value) { return {Kind::binary, {}, value}; }
};

class Connection {
 public:
  // Connects or throws ServerError (connection_lost = true) naming the
  // server by its masked connection string. connect_timeout_s bounds the
  // wait for an unreachable server (0 = libpq's default).
  explicit Connection(const std::string& conninfo, int connect_timeout_s = 10);
  // The same as a given role with its password (the office's web log-in):
  // both go to libpq as keywords after `conninfo`, so they override any
  // user or password it names; the password is checked by the server and
  // kept nowhere here. A failed log-in throws ServerError with the
  // server's SQLSTATE-less message masked.
  Connection(const std::string& conninfo, const std::string& user, const std::string& password,
             int connect_timeout_s = 10);
  ~Connection();
  Connection(Connection&&) noexcept;
  Connection& operator=(Connection&&) noexcept;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // Runs statements without parameters (several separated by ';').
  void exec(std::string_view sql, std::string_view doing);
  // One statement with parameters $1, $2, ...; binary_result fetches every
  // column in binary form (for bytea).
  Result query(std::string_view sql, const std::vector<Param>& params, std::string_view doing,
               bool binary_result = false);

  // The masked connection string, for messages and the project's record.
  const std::string& label() const { return label_; }
  std::string current_user();
  bool ssl_in_use() const;
  pg_conn* handle() const { return conn_; }

 private:
  [[noreturn]] void fail(pg_result* r, std::string_view doing);
  pg_conn* conn_ = nullptr;
  std::string label_;
};

// BEGIN ... COMMIT; rolls back when destroyed uncommitted (and the
// connection is still there).
class Transaction {
 public:
  Transaction(Connection& c, std::string_view doing);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Connection& c_;
  std::string doing_;
  bool open_ = false;
};

}  // namespace rockface::storage::office
