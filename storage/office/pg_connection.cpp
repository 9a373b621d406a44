#include "storage/office/pg_connection.h"

#include <libpq-fe.h>

#include <cctype>
#include <cstdlib>
#include <vector>

namespace rockface::storage::office {

std::string masked_conninfo(std::string_view conninfo) {
  std::string s(conninfo);
  // URL form: scheme://user:password@host...
  const std::size_t scheme = s.find("://");
  if (scheme != std::string::npos) {
    const std::size_t start = scheme + 3;
    const std::size_t at = s.find('@', start);
    const std::size_t slash = s.find('/', start);
    if (at != std::string::npos && (slash == std::string::npos || at < slash)) {
      const std::size_t colon = s.find(':', start);
      if (colon != std::string::npos && colon < at) s.replace(colon + 1, at - colon - 1, "****");
    }
  }
  // password=VALUE as a keyword (key=value form, quoted or not) or a URL
  // query parameter.
  for (std::size_t at = s.find("password"); at != std::string::npos;
       at = s.find("password", at + 8)) {
    std::size_t p = at + 8;
    while (p < s.size() && s[p] == ' ') ++p;
    if (p >= s.size() || s[p] != '=') continue;
    ++p;
    while (p < s.size() && s[p] == ' ') ++p;
    std::size_t end = p;
    if (end < s.size() && s[end] == '\'') {
      ++end;
      while (end < s.size() && s[end] != '\'') end += (s[end] == '\\' ? 2 : 1);
      end = std::min(end + 1, s.size());
    } else {
      while (end < s.size() && s[end] != ' ' && s[end] != '&') ++end;
    }
    s.replace(p, end - p, "****");
  }
  return s;
}

namespace {

std::string trimmed(const char* message) {
  std::string m = message ? message : "";
  while (!m.empty() && std::isspace(static_cast<unsigned char>(m.back()))) m.pop_back();
  return m;
}

}  // namespace

Result::~Result() {
  if (r_) PQclear(r_);
}

Result& Result::operator=(Result&& o) noexcept {
  if (this != &o) {
    if (r_) PQclear(r_);
    r_ = o.r_;
    o.r_ = nullptr;
  }
  return *this;
}

int Result::rows() const {
  return PQntuples(r_);
}
bool Result::is_null(int row, int column) const {
  return PQgetisnull(r_, row, column) != 0;
}
std::string Result::text(int row, int column) const {
  return std::string(PQgetvalue(r_, row, column),
                     static_cast<std::size_t>(PQgetlength(r_, row, column)));
}
std::int64_t Result::int64(int row, int column) const {
  return std::strtoll(PQgetvalue(r_, row, column), nullptr, 10);
}
std::optional<std::string> Result::optional_text(int row, int column) const {
  if (is_null(row, column)) return std::nullopt;
  return text(row, column);
}
std::span<const std::uint8_t> Result::bytes(int row, int column) const {
  return {reinterpret_cast<const std::uint8_t*>(PQgetvalue(r_, row, column)),
          static_cast<std::size_t>(PQgetlength(r_, row, column))};
}

Connection::Connection(const std::string& conninfo, int connect_timeout_s)
    : Connection(conninfo, {}, {}, connect_timeout_s) {}

Connection::Connection(const std::string& conninfo, const std::string& user,
                       const std::string& password, int connect_timeout_s)
    : label_(masked_conninfo(conninfo)) {
  // Keywords beside the caller's string: libpq takes the last value of a
  // keyword, and expand_dbname lets `conninfo` be a URL or key=value text.
  const std::string timeout = std::to_string(connect_timeout_s);
  std::vector<const char*> keys = {"dbname", "application_name"};
  std::vector<const char*> values = {conninfo.c_str(), "rockface"};
  if (connect_timeout_s > 0) {
    keys.push_back("connect_timeout");
    values.push_back(timeout.c_str());
  }
  if (!user.empty()) {
    keys.push_back("user");
    values.push_back(user.c_str());
    keys.push_back("password");
    values.push_back(password.c_str());
  }
  keys.push_back(nullptr);
  values.push_back(nullptr);
  conn_ = PQconnectdbParams(keys.data(), values.data(), 1);
  if (!conn_) throw ServerError(label_ + ": cannot connect: out of memory", "", true);
  if (PQstatus(conn_) != CONNECTION_OK) {
    const std::string why = trimmed(PQerrorMessage(conn_));
    PQfinish(conn_);
    conn_ = nullptr;
    throw ServerError(label_ + ": cannot connect to the server: " + masked_conninfo(why), "08001",
                      true);
  }
  // The server's notices ("role is already a member ...") are not errors;
  // libpq's default prints them on stderr, which library code never does.
  PQsetNoticeProcessor(
      conn_, [](void*, const char*) {}, nullptr);
}

Connection::~Connection() {
  if (conn_) PQfinish(conn_);
}
Connection::Connection(Connection&& o) noexcept : conn_(o.conn_), label_(std::move(o.label_)) {
  o.conn_ = nullptr;
}
Connection& Connection::operator=(Connection&& o) noexcept {
  if (this != &o) {
    if (conn_) PQfinish(conn_);
    conn_ = o.conn_;
    label_ = std::move(o.label_);
    o.conn_ = nullptr;
  }
  return *this;
}

void Connection::fail(pg_result* r, std::string_view doing) {
  std::string state, message;
  if (r) {
    const char* s = PQresultErrorField(r, PG_DIAG_SQLSTATE);
    state = s ? s : "";
    message = trimmed(PQresultErrorMessage(r));
    PQclear(r);
  }
  if (message.empty()) message = trimmed(PQerrorMessage(conn_));
  // An error the server did not send (no SQLSTATE: libpq's own, such as
  // "server closed the connection unexpectedly", which PQstatus may not
  // reflect yet), a connection exception (08) or a shutdown (57P01-03).
  const bool lost = PQstatus(conn_) != CONNECTION_OK || state.empty() ||
                    state.rfind("08", 0) == 0 || state == "57P01" || state == "57P02" ||
                    state == "57P03";
  throw ServerError(label_ + ": " + std::string(doing) + ": " +
                        (lost ? "the connection to the server was lost: " : "") + message,
                    state, lost);
}

void Connection::exec(std::string_view sql, std::string_view doing) {
  pg_result* r = PQexec(conn_, std::string(sql).c_str());
  const auto status = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) fail(r, doing);
  PQclear(r);
}

Result Connection::query(std::string_view sql, const std::vector<Param>& params,
                         std::string_view doing, bool binary_result) {
  std::vector<const char*> values(params.size());
  std::vector<int> lengths(params.size()), formats(params.size());
  for (std::size_t i = 0; i < params.size(); ++i) {
    const Param& p = params[i];
    if (p.kind == Param::Kind::text) {
      values[i] = p.text.c_str();
    } else if (p.kind == Param::Kind::binary) {
      values[i] = reinterpret_cast<const char*>(p.bytes.data());
      lengths[i] = static_cast<int>(p.bytes.size());
      formats[i] = 1;
    }
  }
  pg_result* r =
      PQexecParams(conn_, std::string(sql).c_str(), static_cast<int>(params.size()), nullptr,
                   values.data(), lengths.data(), formats.data(), binary_result ? 1 : 0);
  const auto status = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) fail(r, doing);
  return Result(r);
}

std::string Connection::current_user() {
  return query("SELECT current_user", {}, "asking who we are").text(0, 0);
}

bool Connection::ssl_in_use() const {
  return PQsslInUse(conn_) != 0;
}

Transaction::Transaction(Connection& c, std::string_view doing) : c_(c), doing_(doing) {
  c_.exec("BEGIN", doing_);
  open_ = true;
}

Transaction::~Transaction() {
  if (open_ && c_.handle() && PQstatus(c_.handle()) == CONNECTION_OK) {
    pg_result* r = PQexec(c_.handle(), "ROLLBACK");
    if (r) PQclear(r);
  }
}

void Transaction::commit() {
  c_.exec("COMMIT", doing_);
  open_ = false;
}

}  // namespace rockface::storage::office
