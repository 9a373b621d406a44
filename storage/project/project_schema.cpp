#include "storage/project/project_schema.h"

#include <string>
#include <string_view>

#include "core/common/error.h"

namespace rockface::storage::schema {

namespace {

// The columns of a capture row but its images, in version 1 and in the table
// version 2 rebuilds. They stand once here and take the place of
// kCaptureColumnsMark in both texts (with_capture_columns): SQLite keeps the
// text of each CREATE TABLE in the file, so the splice must give back, byte
// for byte, the text that version 1 of rockface wrote.
constexpr std::string_view kCaptureColumns = R"sql(  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  calibration_id INTEGER REFERENCES calibration(id),
  label TEXT NOT NULL,
  taken_at TEXT NOT NULL,
  created_at TEXT NOT NULL,
)sql";
constexpr std::string_view kCaptureColumnsMark = "  <capture columns>\n";

std::string with_capture_columns(std::string_view sql) {
  std::string out(sql);
  const std::size_t at = out.find(kCaptureColumnsMark);
  if (at != std::string::npos) out.replace(at, kCaptureColumnsMark.size(), kCaptureColumns);
  return out;
}

// A random (version 4) UUID in SQL, for schema 6's "<uuid>" marks.
constexpr std::string_view kUuidMark = "<uuid>";
constexpr std::string_view kUuidExpression =
    "lower(hex(randomblob(4)) || '-' || hex(randomblob(2)) || '-4' || "
    "substr(hex(randomblob(2)), 2) || '-' || substr('89ab', 1 + (abs(random()) % 4), 1) || "
    "substr(hex(randomblob(2)), 2) || '-' || hex(randomblob(6)))";

std::string with_uuid_expression(std::string sql) {
  for (std::size_t at = sql.find(kUuidMark); at != std::string::npos;
       at = sql.find(kUuidMark, at + kUuidExpression.size()))
    sql.replace(at, kUuidMark.size(), kUuidExpression);
  return sql;
}

// Version 1, as first released. Coordinates are project-frame (datum
// relative) metres; angles degrees; times UTC ISO 8601 text.
constexpr const char* kVersion1 = R"sql(
CREATE TABLE project (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  name TEXT NOT NULL,
  datum_x REAL NOT NULL, datum_y REAL NOT NULL, datum_z REAL NOT NULL,
  datum_crs TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL,
  created_by TEXT NOT NULL
);
CREATE TABLE visit (
  id INTEGER PRIMARY KEY,
  started_at TEXT NOT NULL,
  source TEXT NOT NULL,
  note TEXT NOT NULL DEFAULT ''
);
CREATE TABLE camera_body (
  id INTEGER PRIMARY KEY,
  make TEXT NOT NULL, model TEXT NOT NULL, serial TEXT NOT NULL,
  UNIQUE (make, model, serial)
);
CREATE TABLE calibration (
  id INTEGER PRIMARY KEY,
  body_id INTEGER REFERENCES camera_body(id),
  created_at TEXT NOT NULL,
  width INTEGER NOT NULL, height INTEGER NOT NULL,
  fx REAL NOT NULL, fy REAL NOT NULL, cx REAL NOT NULL, cy REAL NOT NULL,
  k1 REAL NOT NULL, k2 REAL NOT NULL, p1 REAL NOT NULL, p2 REAL NOT NULL, k3 REAL NOT NULL,
  rms_px REAL NOT NULL,
  body TEXT NOT NULL, lens TEXT NOT NULL, focus TEXT NOT NULL,
  focal_setting_mm REAL NOT NULL,
  method TEXT NOT NULL
);
CREATE TABLE capture (
  <capture columns>
  left_format TEXT NOT NULL, right_format TEXT NOT NULL,
  left_image BLOB NOT NULL, right_image BLOB NOT NULL
);
CREATE INDEX capture_by_visit ON capture(visit_id);
CREATE TABLE capture_setting (
  capture_id INTEGER NOT NULL REFERENCES capture(id) ON DELETE CASCADE,
  key TEXT NOT NULL, value TEXT NOT NULL,
  PRIMARY KEY (capture_id, key)
);
CREATE TABLE capture_exif (
  capture_id INTEGER NOT NULL REFERENCES capture(id) ON DELETE CASCADE,
  side TEXT NOT NULL CHECK (side IN ('left', 'right')),
  key TEXT NOT NULL, value TEXT NOT NULL,
  PRIMARY KEY (capture_id, side, key)
);
CREATE TABLE model (
  id INTEGER PRIMARY KEY,
  capture_id INTEGER REFERENCES capture(id),
  created_at TEXT NOT NULL,
  preset TEXT NOT NULL,
  vertex_count INTEGER NOT NULL, face_count INTEGER NOT NULL,
  mesh BLOB NOT NULL,
  texture_capture_id INTEGER REFERENCES capture(id),
  texture_side TEXT NOT NULL CHECK (texture_side IN ('', 'left', 'right')),
  registration_kind TEXT NOT NULL,
  scale REAL NOT NULL,
  qw REAL NOT NULL, qx REAL NOT NULL, qy REAL NOT NULL, qz REAL NOT NULL,
  tx REAL NOT NULL, ty REAL NOT NULL, tz REAL NOT NULL,
  registration_parameters TEXT NOT NULL,
  registration_rms_m REAL NOT NULL
);
CREATE INDEX model_by_capture ON model(capture_id);
CREATE TABLE registration_residual (
  model_id INTEGER NOT NULL REFERENCES model(id) ON DELETE CASCADE,
  idx INTEGER NOT NULL,
  label TEXT NOT NULL,
  dx REAL NOT NULL, dy REAL NOT NULL, dz REAL NOT NULL,
  PRIMARY KEY (model_id, idx)
);
CREATE TABLE measurement (
  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  model_id INTEGER REFERENCES model(id),
  kind TEXT NOT NULL CHECK (kind IN ('trace', 'area', 'point_orientation')),
  label TEXT NOT NULL,
  joint_label TEXT NOT NULL,
  points BLOB NOT NULL,
  dip REAL, dipdir REAL,
  fit_rms_m REAL NOT NULL,
  rock_side TEXT NOT NULL CHECK (rock_side IN ('', 'upper', 'lower')),
  created_at TEXT NOT NULL
);
CREATE INDEX measurement_by_visit ON measurement(visit_id);
CREATE TABLE joint_set (
  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  label TEXT NOT NULL,
  dip REAL NOT NULL, dipdir REAL NOT NULL,
  fisher_k REAL NOT NULL,
  count INTEGER NOT NULL,
  UNIQUE (visit_id, label)
);
CREATE TABLE joint (
  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  set_id INTEGER REFERENCES joint_set(id),
  measurement_id INTEGER REFERENCES measurement(id),
  label TEXT NOT NULL,
  dip REAL NOT NULL, dipdir REAL NOT NULL,
  px REAL, py REAL, pz REAL,
  friction_deg REAL, cohesion_pa REAL,
  source TEXT NOT NULL,
  UNIQUE (visit_id, label)
);
CREATE TABLE analysis (
  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  model_id INTEGER REFERENCES model(id),
  created_at TEXT NOT NULL,
  preset TEXT NOT NULL,
  effects TEXT NOT NULL,
  effects_json TEXT NOT NULL
);
CREATE TABLE block (
  id INTEGER PRIMARY KEY,
  analysis_id INTEGER NOT NULL REFERENCES analysis(id) ON DELETE CASCADE,
  label TEXT NOT NULL,
  source TEXT NOT NULL,
  code TEXT NOT NULL,
  volume_m3 REAL NOT NULL,
  finite INTEGER NOT NULL, removable INTEGER NOT NULL, marginal INTEGER NOT NULL,
  mode TEXT NOT NULL,
  fos REAL,
  report_json TEXT NOT NULL
);
CREATE INDEX block_by_analysis ON block(analysis_id);
CREATE TABLE action_log (
  id INTEGER PRIMARY KEY,
  at TEXT NOT NULL,
  visit_id INTEGER REFERENCES visit(id),
  action TEXT NOT NULL,
  detail TEXT NOT NULL
);
)sql";

// Version 2: the images move out of the capture row into `image`, one row per
// distinct byte string. The capture table is rebuilt (SQLite cannot drop
// NOT NULL blob columns in place) following SQLite's documented procedure for
// general table changes: foreign keys off, new table, copy, drop, rename,
// foreign_key_check, all in one transaction.
constexpr const char* kVersion1To2 = R"sql(
CREATE TABLE image (
  id INTEGER PRIMARY KEY,
  format TEXT NOT NULL CHECK (format IN ('jpeg', 'png')),
  byte_size INTEGER NOT NULL,
  bytes BLOB NOT NULL
);
CREATE INDEX image_by_size ON image(byte_size);
INSERT INTO image (format, byte_size, bytes)
  SELECT left_format, length(left_image), left_image FROM capture
  UNION
  SELECT right_format, length(right_image), right_image FROM capture;
CREATE TABLE capture_v2 (
  <capture columns>
  left_image_id INTEGER NOT NULL REFERENCES image(id),
  right_image_id INTEGER NOT NULL REFERENCES image(id)
);
INSERT INTO capture_v2 (id, visit_id, calibration_id, label, taken_at, created_at,
                        left_image_id, right_image_id)
  SELECT c.id, c.visit_id, c.calibration_id, c.label, c.taken_at, c.created_at,
    (SELECT i.id FROM image i WHERE i.byte_size = length(c.left_image)
       AND i.format = c.left_format AND i.bytes = c.left_image),
    (SELECT i.id FROM image i WHERE i.byte_size = length(c.right_image)
       AND i.format = c.right_format AND i.bytes = c.right_image)
  FROM capture c;
DROP TABLE capture;
ALTER TABLE capture_v2 RENAME TO capture;
CREATE INDEX capture_by_visit ON capture(visit_id);
CREATE INDEX capture_by_left_image ON capture(left_image_id);
CREATE INDEX capture_by_right_image ON capture(right_image_id);
)sql";

// Version 3: what measuring on the 3D image adds (core/measure). Columns
// only, so ALTER TABLE suffices; old rows get "not measured" defaults.
constexpr const char* kVersion2To3 = R"sql(
ALTER TABLE measurement ADD COLUMN photo TEXT NOT NULL DEFAULT '';
ALTER TABLE measurement ADD COLUMN photo_capture_id INTEGER REFERENCES capture(id);
ALTER TABLE measurement ADD COLUMN pixels TEXT NOT NULL DEFAULT '[]';
ALTER TABLE measurement ADD COLUMN sigma_deg REAL;
ALTER TABLE measurement ADD COLUMN trace_length_m REAL;
ALTER TABLE measurement ADD COLUMN censored INTEGER NOT NULL DEFAULT 0;
ALTER TABLE measurement ADD COLUMN note TEXT NOT NULL DEFAULT '';
ALTER TABLE joint_set ADD COLUMN alpha95_deg REAL;
ALTER TABLE joint_set ADD COLUMN spacing_m REAL;
ALTER TABLE joint_set ADD COLUMN mean_trace_length_m REAL;
ALTER TABLE joint_set ADD COLUMN censored_traces INTEGER NOT NULL DEFAULT 0;
ALTER TABLE joint_set ADD COLUMN persistence_m REAL;
ALTER TABLE joint_set ADD COLUMN note TEXT NOT NULL DEFAULT '';
ALTER TABLE joint ADD COLUMN type TEXT NOT NULL DEFAULT '';
ALTER TABLE joint ADD COLUMN persistence_m REAL;
)sql";

// Version 4: the map from a model's camera frame to its mesh's frame, for
// the views of its photographs (Model::camera_to_mesh). Until now that was
// the registration for every model but a further pair's of a visit
// ("face_images"), whose registration maps its 3D image onto the face and
// whose camera's map was not kept: those rows stay without one.
constexpr const char* kVersion3To4 = R"sql(
ALTER TABLE model ADD COLUMN camera_scale REAL;
ALTER TABLE model ADD COLUMN camera_qw REAL;
ALTER TABLE model ADD COLUMN camera_qx REAL;
ALTER TABLE model ADD COLUMN camera_qy REAL;
ALTER TABLE model ADD COLUMN camera_qz REAL;
ALTER TABLE model ADD COLUMN camera_tx REAL;
ALTER TABLE model ADD COLUMN camera_ty REAL;
ALTER TABLE model ADD COLUMN camera_tz REAL;
UPDATE model SET camera_scale = scale, camera_qw = qw, camera_qx = qx, camera_qy = qy,
  camera_qz = qz, camera_tx = tx, camera_ty = ty, camera_tz = tz
  WHERE registration_kind <> 'face_images';
)sql";

// Version 5: the tunnel (core/tunnel). New tables only; an earlier project
// simply has no tunnel and no placed visits. Stations keep the surveyor's
// survey coordinates as typed (REAL holds 10^6 m to 1e-10 m); the profile
// keeps its segments in the cross-section frame (u right, v up, metres).
constexpr const char* kVersion4To5 = R"sql(
CREATE TABLE tunnel (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  name TEXT NOT NULL,
  alignment_kind TEXT NOT NULL CHECK (alignment_kind IN ('elements', 'polyline')),
  drive TEXT NOT NULL CHECK (drive IN ('ascending', 'descending')),
  underbreak_tolerance_m REAL NOT NULL,
  profile_name TEXT NOT NULL DEFAULT '',
  ray_centre_u REAL, ray_centre_v REAL,
  alignment_source TEXT NOT NULL DEFAULT '',
  profile_source TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL
);
CREATE TABLE tunnel_station (
  tunnel_id INTEGER NOT NULL REFERENCES tunnel(id) ON DELETE CASCADE,
  idx INTEGER NOT NULL,
  chainage REAL NOT NULL,
  easting REAL NOT NULL, northing REAL NOT NULL, elevation REAL NOT NULL,
  radius_m REAL,
  PRIMARY KEY (tunnel_id, idx)
);
CREATE TABLE tunnel_profile_segment (
  tunnel_id INTEGER NOT NULL REFERENCES tunnel(id) ON DELETE CASCADE,
  idx INTEGER NOT NULL,
  kind TEXT NOT NULL CHECK (kind IN ('line', 'arc')),
  from_u REAL NOT NULL, from_v REAL NOT NULL, to_u REAL NOT NULL, to_v REAL NOT NULL,
  centre_u REAL, centre_v REAL, ccw INTEGER,
  PRIMARY KEY (tunnel_id, idx)
);
CREATE TABLE visit_placement (
  visit_id INTEGER PRIMARY KEY REFERENCES visit(id),
  method TEXT NOT NULL CHECK (method IN ('ground_control', 'chainage_compass')),
  chainage REAL NOT NULL,
  offset_m REAL NOT NULL,
  height_m REAL,
  rms_m REAL,
  compass_azimuth_deg REAL,
  note TEXT NOT NULL DEFAULT '',
  created_at TEXT NOT NULL
);
CREATE TABLE visit_placement_residual (
  visit_id INTEGER NOT NULL REFERENCES visit_placement(visit_id) ON DELETE CASCADE,
  idx INTEGER NOT NULL,
  label TEXT NOT NULL,
  dx REAL NOT NULL, dy REAL NOT NULL, dz REAL NOT NULL,
  PRIMARY KEY (visit_id, idx)
);
)sql";

// Version 6 (issue 24, the office server): every record that a tablet makes
// gets a UUID when it is created (a trigger, so no writer can forget it; the
// rows of an older project get theirs here), so that the visits of several
// tablets never collide on the site's server; and the tablet keeps a record
// of what it synced where (sync_target, sync_record, sync_blob, sync_run),
// nothing else. The UUID is version 4 (random), made by SQLite's randomblob.
// "<uuid>" stands for that expression (with_uuid_expression).
constexpr const char* kVersion5To6 = R"sql(
ALTER TABLE project ADD COLUMN uuid TEXT;
UPDATE project SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS project_by_uuid ON project(uuid);
CREATE TRIGGER IF NOT EXISTS project_gets_uuid AFTER INSERT ON project FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE project SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE visit ADD COLUMN uuid TEXT;
UPDATE visit SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS visit_by_uuid ON visit(uuid);
CREATE TRIGGER IF NOT EXISTS visit_gets_uuid AFTER INSERT ON visit FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE visit SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE camera_body ADD COLUMN uuid TEXT;
UPDATE camera_body SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS camera_body_by_uuid ON camera_body(uuid);
CREATE TRIGGER IF NOT EXISTS camera_body_gets_uuid AFTER INSERT ON camera_body FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE camera_body SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE calibration ADD COLUMN uuid TEXT;
UPDATE calibration SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS calibration_by_uuid ON calibration(uuid);
CREATE TRIGGER IF NOT EXISTS calibration_gets_uuid AFTER INSERT ON calibration FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE calibration SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE image ADD COLUMN uuid TEXT;
UPDATE image SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS image_by_uuid ON image(uuid);
CREATE TRIGGER IF NOT EXISTS image_gets_uuid AFTER INSERT ON image FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE image SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE capture ADD COLUMN uuid TEXT;
UPDATE capture SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS capture_by_uuid ON capture(uuid);
CREATE TRIGGER IF NOT EXISTS capture_gets_uuid AFTER INSERT ON capture FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE capture SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE model ADD COLUMN uuid TEXT;
UPDATE model SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS model_by_uuid ON model(uuid);
CREATE TRIGGER IF NOT EXISTS model_gets_uuid AFTER INSERT ON model FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE model SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE measurement ADD COLUMN uuid TEXT;
UPDATE measurement SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS measurement_by_uuid ON measurement(uuid);
CREATE TRIGGER IF NOT EXISTS measurement_gets_uuid AFTER INSERT ON measurement FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE measurement SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE joint_set ADD COLUMN uuid TEXT;
UPDATE joint_set SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS joint_set_by_uuid ON joint_set(uuid);
CREATE TRIGGER IF NOT EXISTS joint_set_gets_uuid AFTER INSERT ON joint_set FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE joint_set SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE joint ADD COLUMN uuid TEXT;
UPDATE joint SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS joint_by_uuid ON joint(uuid);
CREATE TRIGGER IF NOT EXISTS joint_gets_uuid AFTER INSERT ON joint FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE joint SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE analysis ADD COLUMN uuid TEXT;
UPDATE analysis SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS analysis_by_uuid ON analysis(uuid);
CREATE TRIGGER IF NOT EXISTS analysis_gets_uuid AFTER INSERT ON analysis FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE analysis SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE block ADD COLUMN uuid TEXT;
UPDATE block SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS block_by_uuid ON block(uuid);
CREATE TRIGGER IF NOT EXISTS block_gets_uuid AFTER INSERT ON block FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE block SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
ALTER TABLE action_log ADD COLUMN uuid TEXT;
UPDATE action_log SET uuid = <uuid> WHERE uuid IS NULL;
CREATE UNIQUE INDEX IF NOT EXISTS action_log_by_uuid ON action_log(uuid);
CREATE TRIGGER IF NOT EXISTS action_log_gets_uuid AFTER INSERT ON action_log FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE action_log SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
CREATE TABLE IF NOT EXISTS sync_target (
  id INTEGER PRIMARY KEY,
  server_id TEXT NOT NULL UNIQUE,
  server_label TEXT NOT NULL,
  tunnel TEXT NOT NULL,
  last_sync_at TEXT,
  last_outcome TEXT NOT NULL DEFAULT ''
);
CREATE TABLE IF NOT EXISTS sync_record (
  target_id INTEGER NOT NULL REFERENCES sync_target(id) ON DELETE CASCADE,
  kind TEXT NOT NULL,
  uuid TEXT NOT NULL,
  content_sha256 TEXT NOT NULL,
  revision INTEGER NOT NULL,
  synced_at TEXT NOT NULL,
  PRIMARY KEY (target_id, kind, uuid)
);
CREATE TABLE IF NOT EXISTS sync_blob (
  kind TEXT NOT NULL,
  uuid TEXT NOT NULL,
  sha256 TEXT NOT NULL,
  byte_size INTEGER NOT NULL,
  PRIMARY KEY (kind, uuid)
);
CREATE TABLE IF NOT EXISTS sync_run (
  id INTEGER PRIMARY KEY,
  target_id INTEGER NOT NULL REFERENCES sync_target(id) ON DELETE CASCADE,
  started_at TEXT NOT NULL,
  finished_at TEXT,
  outcome TEXT NOT NULL DEFAULT '',
  records_sent INTEGER NOT NULL DEFAULT 0,
  blobs_sent INTEGER NOT NULL DEFAULT 0,
  bytes_sent INTEGER NOT NULL DEFAULT 0
);
)sql";

// Version 7: the rock-mass classification form per visit (issue 23): the
// parameters the geologist entered on site (core/rockmass/classification_form.h)
// as the JSON of storage/scene/rockmass_form_json.h, one row per visit, replaced
// on each save. A new table only: earlier visits simply have no form.
constexpr const char* kVersion6To7 = R"sql(
CREATE TABLE IF NOT EXISTS rockmass_form (
  visit_id INTEGER PRIMARY KEY REFERENCES visit(id),
  form_json TEXT NOT NULL,
  updated_at TEXT NOT NULL
);
)sql";

// Version 8: where a trace came from (issue 25): tapped by hand, a proposal
// accepted as found, or a proposal corrected by least-cost tracing. A column
// only: every earlier trace (and every area and point) was tapped by hand.
constexpr const char* kVersion7To8 = R"sql(
ALTER TABLE measurement ADD COLUMN origin TEXT NOT NULL DEFAULT 'hand'
  CHECK (origin IN ('hand', 'proposed', 'corrected'));
)sql";

// Version 9: a trace's compass reading (issue 27): the dip and dip direction
// a Clar compass read on the joint where the trace runs (the trace's plane
// then), and the angle by which the trace leaves that plane. Columns only:
// no earlier trace had a reading.
constexpr const char* kVersion8To9 = R"sql(
ALTER TABLE measurement ADD COLUMN compass_dip REAL CHECK (compass_dip BETWEEN 0 AND 90);
ALTER TABLE measurement ADD COLUMN compass_dipdir REAL
  CHECK (compass_dipdir >= 0 AND compass_dipdir <= 360);
ALTER TABLE measurement ADD COLUMN compass_off_deg REAL;
)sql";

// Version 10: the support of the rounds (issue 44): the designer's support
// classes of the project's tunnel (the JSON of
// storage/support/support_classes_json.h), and the support decision of a
// visit (the class chosen, changes with reasons, who and when). Each save
// adds a row, so that a changed decision keeps the ones before it; the
// latest row is the one in force. New tables only, each row with its UUID
// for the office.
constexpr const char* kVersion9To10 = R"sql(
CREATE TABLE IF NOT EXISTS support_classes (
  id INTEGER PRIMARY KEY,
  classes_json TEXT NOT NULL,
  source TEXT NOT NULL,
  saved_at TEXT NOT NULL,
  uuid TEXT
);
CREATE UNIQUE INDEX IF NOT EXISTS support_classes_by_uuid ON support_classes(uuid);
CREATE TRIGGER IF NOT EXISTS support_classes_gets_uuid AFTER INSERT ON support_classes FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE support_classes SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
CREATE TABLE IF NOT EXISTS support_decision (
  id INTEGER PRIMARY KEY,
  visit_id INTEGER NOT NULL REFERENCES visit(id),
  class_name TEXT NOT NULL,
  decision_json TEXT NOT NULL,
  decided_at TEXT NOT NULL,
  uuid TEXT
);
CREATE INDEX IF NOT EXISTS support_decision_by_visit ON support_decision(visit_id);
CREATE UNIQUE INDEX IF NOT EXISTS support_decision_by_uuid ON support_decision(uuid);
CREATE TRIGGER IF NOT EXISTS support_decision_gets_uuid AFTER INSERT ON support_decision FOR EACH ROW WHEN NEW.uuid IS NULL
  BEGIN UPDATE support_decision SET uuid = <uuid> WHERE rowid = NEW.rowid; END;
)sql";

// Version 11: a model's mesh in parts (issue 43): a scanner's 30 million
// points make a 1.8 GB mesh, over SQLite's 1 GB blob, and a blob is built
// whole in memory when written (a 10-million-point import peaked at 3 GB).
// A model saved from now on keeps an empty model.mesh and its encoded mesh
// in model_mesh_part, storage/project/blob_parts.h's parts of 8 MiB; a model
// saved before keeps its mesh whole in model.mesh and is read as it is
// (rewriting every mesh here would make opening an old project slow).
constexpr const char* kVersion10To11 = R"sql(
CREATE TABLE IF NOT EXISTS model_mesh_part (
  model_id INTEGER NOT NULL REFERENCES model(id) ON DELETE CASCADE,
  idx INTEGER NOT NULL,
  bytes BLOB NOT NULL,
  PRIMARY KEY (model_id, idx)
);
)sql";

// Version 12: the heading a visit was taken at (issue 46,
// storage/tunnel/visit_heading.h): the name of the face ("North portal",
// "Bench") when the tunnel is driven from more than one. A table of its
// own, one row per named visit: the visit rows of a project synced before
// stay as they were on the office server. And a visit's analyses found by
// index (a drive's rounds read each visit's latest analysis).
constexpr const char* kVersion11To12 = R"sql(
CREATE TABLE IF NOT EXISTS visit_heading (
  visit_id INTEGER PRIMARY KEY REFERENCES visit(id),
  heading TEXT NOT NULL CHECK (heading <> '')
);
CREATE INDEX IF NOT EXISTS analysis_by_visit ON analysis(visit_id);
)sql";

// Version 13: the geologist who mapped a visit (issue 46: the office's drive
// lists "every visit (date, tablet, geologist)"), by name, as typed on the
// tablet or given to the command line (storage/project/visit_geologist.h).
// A table of its own, one row per visit with a geologist: a visit of an
// earlier project has none ("not recorded", never an empty name), and the
// visit rows already on the office server stay as they were.
constexpr const char* kVersion12To13 = R"sql(
CREATE TABLE IF NOT EXISTS visit_geologist (
  visit_id INTEGER PRIMARY KEY REFERENCES visit(id),
  geologist TEXT NOT NULL CHECK (geologist <> '')
);
)sql";

struct Step {
  int to_version;
  const char* sql;
};
constexpr Step kSteps[] = {{2, kVersion1To2},    {3, kVersion2To3},    {4, kVersion3To4},
                           {5, kVersion4To5},    {6, kVersion5To6},    {7, kVersion6To7},
                           {8, kVersion7To8},    {9, kVersion8To9},    {10, kVersion9To10},
                           {11, kVersion10To11}, {12, kVersion11To12}, {13, kVersion12To13}};

}  // namespace

int version_of(sqlite::Connection& db) {
  return static_cast<int>(db.query_int("PRAGMA user_version", "reading the schema version"));
}

void create_version_1(sqlite::Connection& db) {
  sqlite::WriteTransaction tx(db, "creating the project tables");
  db.exec(with_capture_columns(kVersion1), "creating the project tables");
  db.exec("PRAGMA application_id = " + std::to_string(kApplicationId), "marking the project file");
  db.exec("PRAGMA user_version = 1", "marking the project file");
  tx.commit();
}

void migrate_to(sqlite::Connection& db, int target) {
  if (target < 1 || target > kCurrentVersion)
    throw Error("upgrading the project: no schema " + std::to_string(target));
  if (version_of(db) == target) return;
  // foreign_keys cannot change inside a transaction; table rebuilds need it off.
  db.exec("PRAGMA foreign_keys = OFF", "upgrading the project");
  struct RestoreForeignKeys {
    sqlite::Connection& db;
    ~RestoreForeignKeys() {
      try {
        db.exec("PRAGMA foreign_keys = ON", "upgrading the project");
      } catch (...) {
      }
    }
  } restore{db};

  sqlite::WriteTransaction tx(db, "upgrading the project");
  // Read again under the write lock: another process may have upgraded it.
  const int from = version_of(db);
  if (from == target) return;
  if (from > kCurrentVersion)
    throw Error(db.file().string() +
                ": upgrading the project: it was written by a newer rockface "
                "(project schema " +
                std::to_string(from) + ", this program knows up to " +
                std::to_string(kCurrentVersion) + ")");
  if (from < 1)
    throw InputError(db.file().string(),
                     "not a rockface project (schema version " + std::to_string(from) + ")");
  if (from > target)
    throw Error(db.file().string() + ": upgrading the project: it is at schema " +
                std::to_string(from) + ", past " + std::to_string(target));
  for (const Step& step : kSteps) {
    if (step.to_version <= from || step.to_version > target) continue;
    db.exec(with_uuid_expression(with_capture_columns(step.sql)),
            "upgrading the project to schema " + std::to_string(step.to_version));
  }
  sqlite::Statement check(db, "PRAGMA foreign_key_check", "upgrading the project");
  if (check.step())
    throw Error(db.file().string() + ": upgrading the project: table " + check.column_text(0) +
                " row " + std::to_string(check.column_int(1)) +
                " refers to a missing record; the project was left at schema " +
                std::to_string(from));
  db.exec("PRAGMA user_version = " + std::to_string(target), "upgrading the project");
  tx.commit();
}

void migrate_to_current(sqlite::Connection& db) {
  migrate_to(db, kCurrentVersion);
}

}  // namespace rockface::storage::schema
