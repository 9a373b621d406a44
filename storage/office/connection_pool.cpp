#include "storage/office/connection_pool.h"

#include <libpq-fe.h>

namespace rockface::storage::office {

ConnectionPool::ConnectionPool(std::string conninfo, std::size_t size,
                               std::chrono::milliseconds wait)
    : conninfo_(std::move(conninfo)), size_(size < 1 ? 1 : size), wait_(wait) {}

ConnectionPool::~ConnectionPool() = default;

ConnectionPool::Lease::~Lease() {
  if (pool_ && c_) pool_->give_back(std::move(c_));
}

ConnectionPool::Lease ConnectionPool::acquire(const std::string& role) {
  std::unique_ptr<Connection> c;
  {
    std::unique_lock guard(lock_);
    if (!freed_.wait_for(guard, wait_, [&] { return !idle_.empty() || open_ < size_; }))
      throw PoolBusy("the office server is busy: every one of its " + std::to_string(size_) +
                     " database connections is in use; try again in a moment");
    if (!idle_.empty()) {
      c = std::move(idle_.back());
      idle_.pop_back();
    } else {
      ++open_;  // a slot taken before connecting, outside the lock
    }
  }
  if (!c) {
    try {
      c = std::make_unique<Connection>(conninfo_, 10);
      // The web reads: every transaction of the pool's connections is
      // read-only, whoever it acts as.
      c->exec("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY",
              "making the office's connection read-only");
    } catch (...) {
      std::lock_guard guard(lock_);
      --open_;
      freed_.notify_one();
      throw;
    }
  }
  Lease lease(this, std::move(c));
  // set_config takes the role as a value: no quoting of a name here. A
  // refusal (42501) returns the connection, reset, with the lease.
  lease.db().query("SELECT set_config('role', $1, false)", {Param::of(role)},
                   "acting as role " + role);
  return lease;
}

void ConnectionPool::give_back(std::unique_ptr<Connection> c) {
  // Back to the service role, outside any transaction; a connection that
  // cannot be reset (lost, or a failed statement left it unusable) is
  // closed and its slot freed.
  try {
    if (PQstatus(c->handle()) != CONNECTION_OK) throw std::runtime_error("lost");
    if (PQtransactionStatus(c->handle()) != PQTRANS_IDLE) c->exec("ROLLBACK", "ending a request");
    c->exec("RESET ROLE", "ending a request");
  } catch (...) {
    c.reset();
  }
  std::lock_guard guard(lock_);
  if (c)
    idle_.push_back(std::move(c));
  else
    --open_;
  freed_.notify_one();
}

std::size_t ConnectionPool::open() {
  std::lock_guard guard(lock_);
  return open_;
}

}  // namespace rockface::storage::office
