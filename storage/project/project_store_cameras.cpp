// ProjectStore: camera bodies and calibrations.
#include "storage/project/project_store.h"

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "storage/project/project_store_rows.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

// ---------------------------------------------------------------- cameras

RecordId ProjectStore::save_camera_body(const CameraBody& body) {
  const std::string doing = "saving camera body " + body.make + " " + body.model;
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  Statement find(db_, "SELECT id FROM camera_body WHERE make = ? AND model = ? AND serial = ?",
                 doing);
  find.bind(1, body.make).bind(2, body.model).bind(3, body.serial);
  if (find.step()) return find.column_int(0);
  Statement st(db_, "INSERT INTO camera_body (make, model, serial) VALUES (?, ?, ?)", doing);
  st.bind(1, body.make).bind(2, body.model).bind(3, body.serial);
  st.run();
  const RecordId id = db_.last_insert_id();
  insert_log(
      std::nullopt, "camera body saved",
      "body " + std::to_string(id) + ": " + body.make + " " + body.model + " #" + body.serial);
  tx.commit();
  return id;
}

std::vector<CameraBody> ProjectStore::list_camera_bodies() {
  Statement st(db_, "SELECT id, make, model, serial FROM camera_body ORDER BY id",
               "listing camera bodies");
  std::vector<CameraBody> out;
  while (st.step()) {
    RowReader row(st);
    CameraBody& b = out.emplace_back();
    b.id = row.next_int64();
    b.make = row.next_text();
    b.model = row.next_text();
    b.serial = row.next_text();
  }
  return out;
}

RecordId ProjectStore::save_calibration(const Calibration& calibration) {
  const std::string doing = "saving a calibration";
  require_writable(doing);
  const auto& k = calibration.intrinsics;
  if (k.width <= 0 || k.height <= 0)
    throw InputError("calibration", "image size must be positive, got " + std::to_string(k.width) +
                                        " x " + std::to_string(k.height));
  for (auto [value, name] : {std::pair{k.fx, "fx"}, {k.fy, "fy"}, {k.cx, "cx"}, {k.cy, "cy"}}) {
    require_finite(value, std::string("calibration.") + name);
  }
  if (k.fx <= 0 || k.fy <= 0) throw InputError("calibration", "fx and fy must be positive");
  for (std::size_t i = 0; i < k.distortion.size(); ++i)
    require_finite(k.distortion[i], "calibration.distortion[" + std::to_string(i) + "]");
  require_finite(k.rms_px, "calibration.rms_px");
  require_finite(calibration.focal_setting_mm, "calibration.focal_setting_mm");

  WriteTransaction tx(db_, doing);
  {
    // The same calibration saved again (a second replay, a re-sync) is the
    // stored one, not a duplicate.
    Statement same(db_,
                   "SELECT id FROM calibration WHERE body_id IS ? AND width = ? AND height = ? "
                   "AND fx = ? AND fy = ? AND cx = ? AND cy = ? AND k1 = ? AND k2 = ? AND p1 = ? "
                   "AND p2 = ? AND k3 = ? AND rms_px = ? AND body = ? AND lens = ? AND focus = ? "
                   "AND focal_setting_mm = ? AND method = ? LIMIT 1",
                   doing);
    same.bind(1, calibration.body_id)
        .bind(2, k.width)
        .bind(3, k.height)
        .bind(4, k.fx)
        .bind(5, k.fy)
        .bind(6, k.cx)
        .bind(7, k.cy);
    for (int i = 0; i < 5; ++i) same.bind(8 + i, k.distortion[static_cast<std::size_t>(i)]);
    same.bind(13, k.rms_px)
        .bind(14, k.body)
        .bind(15, k.lens)
        .bind(16, k.focus)
        .bind(17, calibration.focal_setting_mm)
        .bind(18, calibration.method);
    if (same.step()) return same.column_int(0);
  }
  Statement st(db_,
               "INSERT INTO calibration (body_id, created_at, width, height, fx, fy, cx, cy, k1, "
               "k2, p1, p2, k3, rms_px, body, lens, focus, focal_setting_mm, method) VALUES "
               "(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
               doing);
  st.bind(1, calibration.body_id)
      .bind(2, or_now(calibration.created_at))
      .bind(3, k.width)
      .bind(4, k.height)
      .bind(5, k.fx)
      .bind(6, k.fy)
      .bind(7, k.cx)
      .bind(8, k.cy);
  for (int i = 0; i < 5; ++i) st.bind(9 + i, k.distortion[static_cast<std::size_t>(i)]);
  st.bind(14, k.rms_px)
      .bind(15, k.body)
      .bind(16, k.lens)
      .bind(17, k.focus)
      .bind(18, calibration.focal_setting_mm)
      .bind(19, calibration.method);
  st.run();
  const RecordId id = db_.last_insert_id();
  insert_log(std::nullopt, "calibration saved",
             "calibration " + std::to_string(static_cast<long long>(id)) + ": " +
                 std::to_string(k.width) + "x" + std::to_string(k.height) + " fx " +
                 format_fixed(k.fx, 1) + " fy " + format_fixed(k.fy, 1) + " rms " +
                 format_fixed(k.rms_px, 3, " px"));
  tx.commit();
  return id;
}

namespace {
constexpr const char* kCalibrationColumns =
    "id, body_id, created_at, width, height, fx, fy, cx, cy, k1, k2, p1, p2, k3, rms_px, body, "
    "lens, focus, focal_setting_mm, method";

Calibration read_calibration(const Statement& st) {
  RowReader row(st);
  Calibration c;
  c.id = row.next_int64();
  c.body_id = row.next_optional_int64();
  c.created_at = row.next_text();
  auto& k = c.intrinsics;
  k.width = row.next_int();
  k.height = row.next_int();
  k.fx = row.next_double();
  k.fy = row.next_double();
  k.cx = row.next_double();
  k.cy = row.next_double();
  for (double& coefficient : k.distortion) coefficient = row.next_double();  // k1 k2 p1 p2 k3
  k.rms_px = row.next_double();
  k.body = row.next_text();
  k.lens = row.next_text();
  k.focus = row.next_text();
  c.focal_setting_mm = row.next_double();
  c.method = row.next_text();
  return c;
}
}  // namespace

Calibration ProjectStore::load_calibration(RecordId id) {
  Statement st(db_, std::string("SELECT ") + kCalibrationColumns + " FROM calibration WHERE id = ?",
               "loading calibration " + std::to_string(id));
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no calibration " + std::to_string(id) + " in this project");
  return read_calibration(st);
}

std::vector<Calibration> ProjectStore::list_calibrations() {
  Statement st(db_, std::string("SELECT ") + kCalibrationColumns + " FROM calibration ORDER BY id",
               "listing calibrations");
  std::vector<Calibration> out;
  while (st.step()) out.push_back(read_calibration(st));
  return out;
}

}  // namespace rockface::storage
