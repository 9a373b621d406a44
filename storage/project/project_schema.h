#pragma once
// The layout of a project file and its history. A project file says what it
// is by its SQLite application_id and which layout it has by its user_version;
// every layout change is a numbered forward migration, kept forever, so that a
// file from any earlier version of rockface opens (and is upgraded in one
// transaction) in a later one.
//
// Versions:
//   1  first layout: the two images of a capture stored inline in the capture row.
//   2  images in their own table, shared by identical bytes: replaying the
//      same capture folder into a project a second time (a second visit) adds
//      capture rows, not a second copy of 20 MB of JPEGs.
//   3  measurements keep their photo and pixels, the plane's sigma, the trace
//      length and its censoring; joint sets their alpha95, spacing, trace
//      length and persistence; joints their type and persistence (issue 12).
//   4  models keep the map from their camera frame to their mesh's frame
//      (the views of their photographs), apart from the registration: a
//      further pair of a visit is registered onto the face (issue 15).
//   5  the tunnel (issue 22).
//   6  a UUID on every record, made when it is created, and the record of
//      what was synced to the office server (issue 24).
//   7  the rock-mass classification form entered per visit (issue 23).
//   8  where a trace came from: by hand, a proposal, a corrected one (issue 25).
//   9  a trace's compass reading and how far the trace leaves it (issue 27).
//  10  the tunnel's support classes and each visit's support decision (issue 44).
//  11  a model's mesh in parts of 8 MiB (issue 43): meshes over 1 GB.
//  12  the heading a visit was taken at (issue 46): a tunnel driven from
//      more than one face (storage/tunnel/visit_heading.h); an index of the
//      analyses by visit.
//  13  the geologist who mapped a visit (issue 46), by name
//      (storage/project/visit_geologist.h).
#include <cstdint>

#include "storage/project/project_sqlite.h"

namespace rockface::storage::schema {

// "RocF": PRAGMA application_id of every rockface project file.
constexpr std::int32_t kApplicationId = 0x526F6346;
constexpr int kCurrentVersion = 13;

// Creates the version-1 layout in an empty database, sets application_id and
// user_version = 1, in one transaction. New projects start here and are then
// migrated like any old file, so the migrations run on every new project.
// Never change this function: it is what version 1 of rockface wrote.
void create_version_1(sqlite::Connection& db);

// Upgrades a project of an earlier version to kCurrentVersion in one
// transaction (all steps or none). No-op when already current. Throws
// rockface::Error when the file is newer than this program or a step fails;
// the file then keeps its old version untouched.
void migrate_to_current(sqlite::Connection& db);
// The same up to schema `target` only: what an earlier rockface left, for
// the migration tests of each step.
void migrate_to(sqlite::Connection& db, int target);

// user_version of the open database.
int version_of(sqlite::Connection& db);

}  // namespace rockface::storage::schema
