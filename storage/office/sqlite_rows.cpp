#include "storage/office/sqlite_rows.h"

#include "core/common/error.h"

namespace rockface::storage::office {

RawStatement::RawStatement(sqlite::Connection& db, const std::string& sql, const std::string& doing)
    : db_(db), doing_(doing) {
  const int rc = sqlite3_prepare_v2(db.handle(), sql.c_str(), -1, &st_, nullptr);
  if (rc != SQLITE_OK) sqlite::fail(db.handle(), rc, db.file(), doing_);
}

RawStatement::~RawStatement() {
  sqlite3_finalize(st_);
}

bool RawStatement::step() {
  const int rc = sqlite3_step(st_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  sqlite::fail(db_.handle(), rc, db_.file(), doing_);
}

void RawStatement::reset() {
  sqlite3_reset(st_);
  sqlite3_clear_bindings(st_);
}

void RawStatement::reset(const std::string& doing) {
  reset();
  doing_ = doing;
}

std::string RawStatement::text(int c) const {
  const auto* p = sqlite3_column_text(st_, c);
  return p ? std::string(reinterpret_cast<const char*>(p),
                         static_cast<std::size_t>(sqlite3_column_bytes(st_, c)))
           : std::string();
}

void RawStatement::bind_text(int i, const std::string& v) {
  sqlite3_bind_text(st_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
}
void RawStatement::bind_int64(int i, std::int64_t v) {
  sqlite3_bind_int64(st_, i, v);
}
void RawStatement::bind_null(int i) {
  sqlite3_bind_null(st_, i);
}

std::vector<ForeignKey> foreign_keys(sqlite::Connection& db, const std::string& table) {
  RawStatement st(db, "SELECT \"from\", \"table\", \"to\" FROM pragma_foreign_key_list(?)",
                  "reading the keys of table " + table);
  st.bind_text(1, table);
  std::vector<ForeignKey> out;
  while (st.step()) out.push_back({st.text(0), st.text(1), st.text(2)});
  return out;
}

std::vector<std::string> column_names(sqlite::Connection& db, const std::string& table) {
  RawStatement st(db, "SELECT name FROM pragma_table_info(?) ORDER BY cid",
                  "reading the columns of table " + table);
  st.bind_text(1, table);
  std::vector<std::string> out;
  while (st.step()) out.push_back(st.text(0));
  return out;
}

BlobReader::BlobReader(sqlite::Connection& db, const std::string& table, const std::string& column,
                       std::int64_t rowid)
    : db_(db), where_("reading " + table + "." + column + " of row " + std::to_string(rowid)) {
  const int rc =
      sqlite3_blob_open(db.handle(), "main", table.c_str(), column.c_str(), rowid, 0, &blob_);
  if (rc != SQLITE_OK) sqlite::fail(db.handle(), rc, db.file(), where_);
  size_ = sqlite3_blob_bytes(blob_);
  if (const auto* table_of_parts = parts::parts_table_of(table, column); table_of_parts && !size_) {
    parts_.emplace(db, *table_of_parts, rowid, where_);
    size_ = static_cast<std::int64_t>(parts_->size());
  }
}

BlobReader::~BlobReader() {
  if (blob_) sqlite3_blob_close(blob_);
}

void BlobReader::read(std::int64_t offset, std::vector<std::uint8_t>& out) {
  if (parts_) return parts_->read(static_cast<std::uint64_t>(offset), out);
  const int rc =
      sqlite3_blob_read(blob_, out.data(), static_cast<int>(out.size()), static_cast<int>(offset));
  if (rc != SQLITE_OK) sqlite::fail(db_.handle(), rc, db_.file(), where_);
}

BlobWriter::BlobWriter(sqlite::Connection& db, const std::string& table, const std::string& column,
                       std::int64_t rowid)
    : db_(db), where_("writing " + table + "." + column + " of row " + std::to_string(rowid)) {
  const int rc =
      sqlite3_blob_open(db.handle(), "main", table.c_str(), column.c_str(), rowid, 1, &blob_);
  if (rc != SQLITE_OK) sqlite::fail(db.handle(), rc, db.file(), where_);
}

BlobWriter::~BlobWriter() {
  if (blob_) sqlite3_blob_close(blob_);
}

void BlobWriter::write(std::int64_t offset, const std::uint8_t* bytes, std::size_t n) {
  const int rc = sqlite3_blob_write(blob_, bytes, static_cast<int>(n), static_cast<int>(offset));
  if (rc != SQLITE_OK) sqlite::fail(db_.handle(), rc, db_.file(), where_);
}

std::string hex_of(const std::uint8_t* bytes, std::size_t n) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    out += kHex[bytes[i] >> 4];
    out += kHex[bytes[i] & 15];
  }
  return out;
}

std::vector<std::uint8_t> bytes_of_hex(const std::string& hex, const std::string& where) {
  auto nibble = [&](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    throw InputError(where, "not hexadecimal bytes");
  };
  if (hex.size() % 2) throw InputError(where, "odd number of hexadecimal digits");
  std::vector<std::uint8_t> out(hex.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<std::uint8_t>(nibble(hex[2 * i]) * 16 + nibble(hex[2 * i + 1]));
  return out;
}

}  // namespace rockface::storage::office
