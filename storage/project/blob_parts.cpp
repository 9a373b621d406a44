#include "storage/project/blob_parts.h"

#include <sqlite3.h>

#include <algorithm>
#include <cstring>

#include "core/common/error.h"

namespace rockface::storage::parts {

const PartsTable* parts_table_of(const std::string& table, const std::string& column) {
  static constexpr PartsTable kModelMesh{"model_mesh_part", "model_id"};
  if (table == "model" && column == "mesh") return &kModelMesh;
  return nullptr;
}

PartWriter::PartWriter(sqlite::Connection& db, const PartsTable& parts, std::int64_t owner)
    : db_(db),
      insert_(db,
              std::string("INSERT INTO ") + parts.table + " (" + parts.owner_column +
                  ", idx, bytes) VALUES (?, ?, ?)",
              std::string("storing ") + parts.table),
      owner_(owner) {
  part_.reserve(kPartBytes);
}

void PartWriter::append(const void* bytes, std::size_t n) {
  const auto* p = static_cast<const std::uint8_t*>(bytes);
  while (n > 0) {
    const std::size_t take = std::min(n, kPartBytes - part_.size());
    part_.insert(part_.end(), p, p + take);
    p += take;
    n -= take;
    written_ += take;
    if (part_.size() == kPartBytes) flush();
  }
}

void PartWriter::flush() {
  insert_.reset();
  insert_.bind(1, owner_).bind(2, next_idx_++).bind_blob(3, part_);
  insert_.run();
  part_.clear();
}

void PartWriter::finish() {
  if (!part_.empty()) flush();
}

PartsReader::PartsReader(sqlite::Connection& db, const PartsTable& parts, std::int64_t owner,
                         std::string where)
    : db_(db), table_(parts.table), where_(std::move(where)) {
  // length() of a blob column is read from the record's header: the parts'
  // bytes are not loaded to list them.
  sqlite::Statement st(db,
                       std::string("SELECT rowid, idx, length(bytes) FROM ") + parts.table +
                           " WHERE " + parts.owner_column + " = ? ORDER BY idx",
                       "listing " + where_);
  st.bind(1, owner);
  while (st.step()) {
    if (st.column_int(1) != static_cast<std::int64_t>(rowids_.size()))
      throw Error(where_ + ": stored data is damaged (part " + std::to_string(rowids_.size()) +
                  " is missing)");
    rowids_.push_back(st.column_int(0));
    starts_.push_back(size_);
    size_ += static_cast<std::uint64_t>(st.column_int(2));
  }
}

void PartsReader::read(std::uint64_t offset, std::span<std::uint8_t> out) const {
  if (offset > size_ || out.size() > size_ - offset)
    throw Error(where_ + ": stored data is damaged (truncated at byte " + std::to_string(size_) +
                ")");
  auto part = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), offset) -
                                       starts_.begin() - 1);
  std::size_t done = 0;
  while (done < out.size()) {
    sqlite3_blob* blob = nullptr;
    int rc =
        sqlite3_blob_open(db_.handle(), "main", table_.c_str(), "bytes", rowids_[part], 0, &blob);
    if (rc != SQLITE_OK) sqlite::fail(db_.handle(), rc, db_.file(), "reading " + where_);
    const std::uint64_t in_part = offset + done - starts_[part];
    const auto part_size = static_cast<std::uint64_t>(sqlite3_blob_bytes(blob));
    const std::size_t n =
        static_cast<std::size_t>(std::min<std::uint64_t>(out.size() - done, part_size - in_part));
    rc = sqlite3_blob_read(blob, out.data() + done, static_cast<int>(n), static_cast<int>(in_part));
    sqlite3_blob_close(blob);
    if (rc != SQLITE_OK) sqlite::fail(db_.handle(), rc, db_.file(), "reading " + where_);
    done += n;
    ++part;
  }
}

}  // namespace rockface::storage::parts
