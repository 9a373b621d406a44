#pragma once
// A bounded pool of libpq connections shared by the office web server's
// sessions (issue 46: one connection per logged-in person held a server
// slot each, so fifty people took fifty of PostgreSQL's hundred). The
// pool's connections log in as the office server's own service role (a
// member of rockface_web: server_schema.h's add_web_service), which may
// act as any office user and as no other role; each lease acts AS the
// person's role (SET ROLE) for one request and is reset when it returns,
// so row-level security still decides what each person reads. The
// connections are read-only.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

// Every connection was lent for longer than the pool's wait: the page
// says "busy, try again".
class PoolBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ConnectionPool {
 public:
  // Eight connections serve a site office's people: a request holds one
  // for its own time only (tens of milliseconds; a first pull of a tunnel
  // seconds).
  static constexpr std::size_t kDefaultSize = 8;
  static constexpr std::chrono::seconds kDefaultWait{10};

  // `conninfo` names the service role (user=..., its password from a
  // passfile or the service file, never on a command line).
  ConnectionPool(std::string conninfo, std::size_t size = kDefaultSize,
                 std::chrono::milliseconds wait = kDefaultWait);
  ~ConnectionPool();
  ConnectionPool(const ConnectionPool&) = delete;
  ConnectionPool& operator=(const ConnectionPool&) = delete;

  class Lease {
   public:
    Lease(Lease&& o) noexcept : pool_(o.pool_), c_(std::move(o.c_)) { o.pool_ = nullptr; }
    Lease& operator=(Lease&&) = delete;
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease();
    Connection& db() { return *c_; }

   private:
    friend class ConnectionPool;
    Lease(ConnectionPool* pool, std::unique_ptr<Connection> c) : pool_(pool), c_(std::move(c)) {}
    ConnectionPool* pool_;
    std::unique_ptr<Connection> c_;
  };

  // A connection acting as `role`, waiting up to the pool's wait for a free
  // one (then PoolBusy). Throws ServerError when the server cannot be
  // reached or the service role may not act as `role` (SQLSTATE 42501).
  Lease acquire(const std::string& role);

  std::size_t size() const { return size_; }
  // Connections open now (lent or idle): never more than size().
  std::size_t open();

 private:
  void give_back(std::unique_ptr<Connection> c);

  std::string conninfo_;
  std::size_t size_;
  std::chrono::milliseconds wait_;
  std::mutex lock_;
  std::condition_variable freed_;
  std::vector<std::unique_ptr<Connection>> idle_;
  std::size_t open_ = 0;
};

}  // namespace rockface::storage::office
