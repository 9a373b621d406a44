#pragma once
// One photograph or mesh up to the office server: stored once by SHA-256
// (a blob already complete there is not sent again), sent in chunks read
// piece by piece from the project file, each chunk its own transaction (a
// cut upload resumes at the first missing chunk), and marked complete only
// when the server has checked its size and hash.
#include <cstdint>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"
#include "storage/office/record_documents.h"

namespace rockface::storage::office {

struct BlobUploadStats {
  int sent = 0, already_there = 0;
  std::int64_t bytes = 0;
};

void upload_blob(Connection& server, sqlite::Connection& db, const BlobSource& blob,
                 std::int64_t chunk_bytes, Progress& progress, double fraction,
                 BlobUploadStats& stats);

}  // namespace rockface::storage::office
