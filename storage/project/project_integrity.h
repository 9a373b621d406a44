#pragma once
// How a project file is checked before it is trusted: SQLite's own checks
// of its pages (quick_check / integrity_check), and, where a whole-file read
// costs too much on every opening (a project of many visits is gigabytes of
// photographs and 3D images), a check of the rows without the bulk.
#include <atomic>
#include <filesystem>

#include "storage/project/project_records.h"
#include "storage/project/project_sqlite.h"

namespace rockface::storage {

// quick: every page of the file (quick_check: indexes not cross-checked);
// full: integrity_check; rows: every table and index but the tables of
// photographs and 3D-image parts (the file's bulk: their pages are read
// when a photograph or a 3D image is loaded, where SQLite finds a damaged
// page as it reads it), and the file's length against its header (a copy
// cut short). The cost of each is in docs/accuracy-cost.md.
enum class IntegrityDepth { quick, full, rows };

// The check on an open connection; `cancel` (may be null) stops it early,
// giving a report with ok = false and no problems.
IntegrityReport check_project_pages(sqlite::Connection& db, IntegrityDepth depth,
                                    const std::atomic<bool>* cancel = nullptr);

// The same on a read-only connection of its own, so a worker checks a file
// the program has open for writing without holding up its reads and
// writes. Throws InputError naming the file when it cannot be read at all.
IntegrityReport check_project_file(const std::filesystem::path& file, IntegrityDepth depth,
                                   const std::atomic<bool>* cancel = nullptr);

}  // namespace rockface::storage
