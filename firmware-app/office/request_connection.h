#pragma once
// A request's database connection in the office server (issue 46): leased
// from the pool when the request first reads, acting as the session's
// role, and given back as soon as the request has read what it needs —
// before the work that needs no database (a pulled copy's build, a field
// report, a mesh's decimation, the JSON) and before it waits for another
// request's build of the same page or copy. Under load a visit opening
// held its connection through its whole pull (~10 s), and the other
// people's requests waited the pool's 10 s for one and were told "busy".
// Leased again, as the same role, if the request reads once more.
#include <optional>
#include <string>

#include "storage/office/connection_pool.h"
#include "storage/office/pg_connection.h"

namespace rockface::app::office_web {

class RequestConnection {
 public:
  RequestConnection(storage::office::ConnectionPool& pool, std::string role)
      : pool_(&pool), role_(std::move(role)) {}

  // The leased connection (leased now if it is not held): throws the
  // pool's PoolBusy past its wait, ServerError when the role is refused.
  storage::office::Connection& db() {
    if (!lease_) lease_.emplace(pool_->acquire(role_));
    return lease_->db();
  }
  // Back to the pool: its transaction rolled back, its role reset.
  void release() { lease_.reset(); }
  bool held() const { return lease_.has_value(); }
  const std::string& role() const { return role_; }

 private:
  storage::office::ConnectionPool* pool_;
  std::string role_;
  std::optional<storage::office::ConnectionPool::Lease> lease_;
};

}  // namespace rockface::app::office_web
