// ProjectStore: captures (image pairs) and the models reconstructed from them.
#include "storage/project/project_store.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "storage/project/blob_parts.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_store_rows.h"

namespace rockface::storage {

using namespace rows;  // row helpers and the SQLite wrappers

// ---------------------------------------------------------------- captures

RecordId ProjectStore::store_image(const ImageBlob& image, const std::string& where) {
  if (image.bytes.empty()) throw InputError(where, "the image is empty");
  const std::string format = blobs::detect_image_format(image.bytes);
  if (format.empty()) throw InputError(where, "not a JPEG or PNG image");
  if (!image.format.empty() && image.format != format)
    throw InputError(where, "said to be " + image.format + " but the bytes are " + format);
  const std::string doing = "saving " + where;
  const auto size = static_cast<std::int64_t>(image.bytes.size());
  Statement find(
      db_, "SELECT id FROM image WHERE byte_size = ? AND format = ? AND bytes = ? LIMIT 1", doing);
  find.bind(1, size).bind(2, format).bind_blob(3, image.bytes);
  if (find.step()) return find.column_int(0);
  Statement st(db_, "INSERT INTO image (format, byte_size, bytes) VALUES (?, ?, ?)", doing);
  st.bind(1, format).bind(2, size).bind_blob(3, image.bytes);
  st.run();
  return db_.last_insert_id();
}

RecordId ProjectStore::save_capture(const Capture& capture) {
  const std::string doing = "saving capture '" + capture.label + "'";
  require_writable(doing);
  WriteTransaction tx(db_, doing);
  {
    Statement visit(db_, "SELECT 1 FROM visit WHERE id = ?", doing);
    visit.bind(1, capture.visit_id);
    if (!visit.step())
      throw InputError("capture.visit_id",
                       "no visit " + std::to_string(capture.visit_id) + " in " + file_.string());
  }
  const RecordId left = store_image(capture.left, "capture '" + capture.label + "' left image");
  const RecordId right = store_image(capture.right, "capture '" + capture.label + "' right image");
  Statement st(db_,
               "INSERT INTO capture (visit_id, calibration_id, label, taken_at, created_at, "
               "left_image_id, right_image_id) VALUES (?, ?, ?, ?, ?, ?, ?)",
               doing);
  const std::string now = utc_now_iso8601();
  st.bind(1, capture.visit_id)
      .bind(2, capture.calibration_id)
      .bind(3, capture.label)
      .bind(4, capture.taken_at.empty() ? now : capture.taken_at)
      .bind(5, now)
      .bind(6, left)
      .bind(7, right);
  st.run();
  const RecordId id = db_.last_insert_id();
  Statement setting(db_, "INSERT INTO capture_setting (capture_id, key, value) VALUES (?, ?, ?)",
                    doing);
  for (const auto& [key, value] : capture.settings) {
    setting.reset();
    setting.bind(1, id).bind(2, key).bind(3, value);
    setting.run();
  }
  Statement exif(db_, "INSERT INTO capture_exif (capture_id, side, key, value) VALUES (?, ?, ?, ?)",
                 doing);
  for (const auto* side : {"left", "right"}) {
    const auto& entries = std::string(side) == "left" ? capture.left_exif : capture.right_exif;
    for (const auto& [key, value] : entries) {
      exif.reset();
      exif.bind(1, id).bind(2, side).bind(3, key).bind(4, value);
      exif.run();
    }
  }
  insert_log(capture.visit_id, "capture saved",
             "capture " + std::to_string(id) + " '" + capture.label + "': left " +
                 std::to_string(capture.left.bytes.size()) + " bytes, right " +
                 std::to_string(capture.right.bytes.size()) + " bytes");
  tx.commit();
  return id;
}

namespace {

// A model's mesh: in its parts (schema 11), read part by part into the mesh's
// arrays; or, saved before schema 11, whole in the model row's column.
Mesh load_model_mesh(sqlite::Connection& db, RecordId model_id,
                     const std::vector<std::uint8_t>& whole, const std::string& where) {
  if (!whole.empty()) return blobs::decode_mesh(whole, where);
  const parts::PartsReader stored(db, *parts::parts_table_of("model", "mesh"), model_id, where);
  std::uint64_t at = 0;
  return blobs::decode_mesh(
      stored.size(),
      [&](void* dst, std::size_t n) {
        stored.read(at, {static_cast<std::uint8_t*>(dst), n});
        at += n;
      },
      where);
}

// What the stored reconstruction report says gave north ('' when it does
// not say): SQL, so that a listing need not parse every model's parameters.
constexpr const char* kStoredNorthSource =
    "COALESCE(CASE WHEN json_valid(registration_parameters) THEN "
    "json_extract(registration_parameters, '$.registration.north_source') END, '')";
constexpr const char* kCaptureSummarySelect =
    "SELECT c.id, c.visit_id, c.calibration_id, c.label, c.taken_at, l.format, l.byte_size, "
    "r.format, r.byte_size FROM capture c JOIN image l ON l.id = c.left_image_id "
    "JOIN image r ON r.id = c.right_image_id";

CaptureSummary read_capture_summary(const Statement& st) {
  RowReader row(st);
  CaptureSummary s;
  s.id = row.next_int64();
  s.visit_id = row.next_int64();
  s.calibration_id = row.next_optional_int64();
  s.label = row.next_text();
  s.taken_at = row.next_text();
  s.left_format = row.next_text();
  s.left_bytes = row.next_int64();
  s.right_format = row.next_text();
  s.right_bytes = row.next_int64();
  return s;
}
}  // namespace

Capture ProjectStore::load_capture(RecordId id) {
  const std::string doing = "loading capture " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_,
               "SELECT c.id, c.visit_id, c.calibration_id, c.label, c.taken_at, l.format, "
               "l.bytes, r.format, r.bytes FROM capture c JOIN image l ON l.id = "
               "c.left_image_id JOIN image r ON r.id = c.right_image_id WHERE c.id = ?",
               doing);
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no capture " + std::to_string(id) + " in this project");
  RowReader row(st);
  Capture c;
  c.id = row.next_int64();
  c.visit_id = row.next_int64();
  c.calibration_id = row.next_optional_int64();
  c.label = row.next_text();
  c.taken_at = row.next_text();
  c.left.format = row.next_text();
  c.left.bytes = row.next_blob();
  c.right.format = row.next_text();
  c.right.bytes = row.next_blob();
  Statement settings(db_, "SELECT key, value FROM capture_setting WHERE capture_id = ?", doing);
  settings.bind(1, id);
  while (settings.step()) {
    RowReader setting(settings);
    const std::string key = setting.next_text();
    c.settings[key] = setting.next_text();
  }
  Statement exif(db_, "SELECT side, key, value FROM capture_exif WHERE capture_id = ?", doing);
  exif.bind(1, id);
  while (exif.step()) {
    RowReader entry(exif);
    const std::string side = entry.next_text();
    const std::string key = entry.next_text();
    (side == "left" ? c.left_exif : c.right_exif)[key] = entry.next_text();
  }
  return c;
}

ImageBlob ProjectStore::load_capture_image(RecordId capture_id, const std::string& side) {
  if (side != "left" && side != "right")
    throw InputError("capture image side", "must be 'left' or 'right', got '" + side + "'");
  Statement st(db_,
               "SELECT i.format, i.bytes FROM capture c JOIN image i ON i.id = c." + side +
                   "_image_id WHERE c.id = ?",
               "loading the " + side + " image of capture " + std::to_string(capture_id));
  st.bind(1, capture_id);
  if (!st.step())
    throw InputError(file_.string(),
                     "no capture " + std::to_string(capture_id) + " in this project");
  RowReader row(st);
  const std::string format = row.next_text();
  return {row.next_blob(), format};
}

std::optional<std::string> ProjectStore::latest_capture_setting(const std::string& key) {
  Statement st(db_,
               "SELECT value FROM capture_setting WHERE key = ? ORDER BY capture_id DESC LIMIT 1",
               "reading the capture setting " + key);
  st.bind(1, key);
  if (!st.step()) return std::nullopt;
  RowReader row(st);
  return row.next_text();
}

std::vector<CaptureSummary> ProjectStore::list_captures(std::optional<RecordId> visit_id) {
  Statement st(db_,
               std::string(kCaptureSummarySelect) + " WHERE " +
                   (visit_id ? "c.visit_id = ?1" : "?1 IS NULL") + " ORDER BY c.id",
               "listing captures");
  st.bind(1, visit_id);
  std::vector<CaptureSummary> out;
  while (st.step()) out.push_back(read_capture_summary(st));
  return out;
}

// ---------------------------------------------------------------- models

photogrammetry::Similarity similarity_of(const Registration& r) {
  photogrammetry::Similarity s;
  s.scale = r.scale;
  s.R = Eigen::Quaterniond(r.rotation_wxyz[0], r.rotation_wxyz[1], r.rotation_wxyz[2],
                           r.rotation_wxyz[3])
            .normalized()
            .toRotationMatrix();
  s.t = r.translation;
  return s;
}

void set_similarity(Registration& r, const photogrammetry::Similarity& s) {
  r.scale = s.scale;
  const Eigen::Quaterniond q(s.R);
  r.rotation_wxyz = {q.w(), q.x(), q.y(), q.z()};
  r.translation = s.t;
}

RecordId ProjectStore::save_model(const Model& model) {
  const std::string doing = "saving a model";
  require_writable(doing);
  const auto& r = model.registration;
  if (model.texture_capture_id && model.texture_side != "left" && model.texture_side != "right")
    throw InputError("model.texture_side", "must be 'left' or 'right' when a texture is given");
  if (!model.texture_capture_id && !model.texture_side.empty())
    throw InputError("model.texture_side", "given without a texture capture");
  if (!std::isfinite(r.scale) || r.scale <= 0)
    throw InputError("model.registration.scale", "must be a positive number");
  if (!r.rotation_wxyz.allFinite() || std::abs(r.rotation_wxyz.norm() - 1) > 1e-6)
    // 1e-6: a quaternion normalised in double precision is unit to ~1e-15;
    // anything further off was not normalised at all.
    throw InputError("model.registration.rotation", "must be a unit quaternion");
  require_finite(r.translation, "model.registration.translation");
  std::optional<photogrammetry::Similarity> camera = model.camera_to_mesh;
  if (!camera && r.kind != "face_images") camera = similarity_of(r);
  if (camera) {
    if (!std::isfinite(camera->scale) || camera->scale <= 0)
      throw InputError("model.camera_to_mesh.scale", "must be a positive number");
    // 1e-6: a rotation matrix from a quaternion or a product of rotations
    // is orthonormal to ~1e-15; anything further off is no rotation.
    if (!camera->R.allFinite() ||
        (camera->R.transpose() * camera->R - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
        camera->R.determinant() < 0)
      throw InputError("model.camera_to_mesh.R", "must be a rotation");
    require_finite(camera->t, "model.camera_to_mesh.t");
  }
  for (std::size_t i = 0; i < model.mesh.vertices.size(); ++i)
    if (!model.mesh.vertices[i].allFinite())
      throw InputError("model.mesh.vertices[" + std::to_string(i) + "]", "not finite");

  WriteTransaction tx(db_, doing);
  Statement st(db_,
               "INSERT INTO model (capture_id, created_at, preset, vertex_count, face_count, "
               "mesh, texture_capture_id, texture_side, registration_kind, scale, qw, qx, qy, "
               "qz, tx, ty, tz, registration_parameters, registration_rms_m, camera_scale, "
               "camera_qw, camera_qx, camera_qy, camera_qz, camera_tx, camera_ty, camera_tz) "
               "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
               "?, ?, ?)",
               doing);
  st.bind(1, model.capture_id)
      .bind(2, or_now(model.created_at))
      .bind(3, model.preset)
      .bind(4, static_cast<std::int64_t>(model.mesh.vertices.size()))
      .bind(5, static_cast<std::int64_t>(model.mesh.faces.size()))
      .bind_blob(6, {})  // the mesh goes into model_mesh_part below (schema 11)
      .bind(7, model.texture_capture_id)
      .bind(8, model.texture_side)
      .bind(9, r.kind)
      .bind(10, r.scale);
  for (int i = 0; i < 4; ++i) st.bind(11 + i, r.rotation_wxyz[i]);
  for (int i = 0; i < 3; ++i) st.bind(15 + i, r.translation[i]);
  st.bind(18, r.parameters_json).bind(19, r.rms_m);
  if (camera) {
    const Eigen::Quaterniond q(camera->R);
    st.bind(20, camera->scale).bind(21, q.w()).bind(22, q.x()).bind(23, q.y()).bind(24, q.z());
    for (int i = 0; i < 3; ++i) st.bind(25 + i, camera->t[i]);
  }  // else the columns stay NULL: no camera pose
  st.run();
  const RecordId id = db_.last_insert_id();
  // Encoded straight into parts of a few megabytes: the mesh is never held
  // encoded whole, neither here nor in an SQLite record.
  parts::PartWriter mesh_parts(db_, *parts::parts_table_of("model", "mesh"), id);
  blobs::encode_mesh(model.mesh,
                     [&](const void* bytes, std::size_t n) { mesh_parts.append(bytes, n); });
  mesh_parts.finish();
  Statement res(db_,
                "INSERT INTO registration_residual (model_id, idx, label, dx, dy, dz) VALUES (?, "
                "?, ?, ?, ?, ?)",
                doing);
  for (std::size_t i = 0; i < model.residuals.size(); ++i) {
    const auto& e = model.residuals[i];
    require_finite(e.residual, "model.residuals[" + std::to_string(i) + "]");
    res.reset();
    res.bind(1, id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, e.label)
        .bind(4, e.residual.x())
        .bind(5, e.residual.y())
        .bind(6, e.residual.z());
    res.run();
  }
  insert_log(std::nullopt, "model saved",
             "model " + std::to_string(id) + ": " + std::to_string(model.mesh.vertices.size()) +
                 " vertices, " + std::to_string(model.mesh.faces.size()) + " faces, " +
                 (r.kind.empty() ? "unregistered" : r.kind));
  tx.commit();
  return id;
}

Model ProjectStore::load_model(RecordId id) {
  const std::string where = file_.string() + ": model " + std::to_string(id);
  ReadTransaction snapshot(db_);
  Statement st(db_,
               "SELECT id, capture_id, created_at, preset, mesh, texture_capture_id, "
               "texture_side, registration_kind, scale, qw, qx, qy, qz, tx, ty, tz, "
               "registration_parameters, registration_rms_m, " +
                   std::string(kStoredNorthSource) +
                   ", camera_scale, camera_qw, camera_qx, camera_qy, camera_qz, camera_tx, "
                   "camera_ty, camera_tz FROM model WHERE id = ?",
               "loading model " + std::to_string(id));
  st.bind(1, id);
  if (!st.step())
    throw InputError(file_.string(), "no model " + std::to_string(id) + " in this project");
  RowReader row(st);
  Model m;
  m.id = row.next_int64();
  m.capture_id = row.next_optional_int64();
  m.created_at = row.next_text();
  m.preset = row.next_text();
  m.mesh = load_model_mesh(db_, id, row.next_blob(), where);
  m.texture_capture_id = row.next_optional_int64();
  m.texture_side = row.next_text();
  auto& r = m.registration;
  r.kind = row.next_text();
  r.scale = row.next_double();
  r.rotation_wxyz = next_vector4(row);
  r.translation = next_vector3(row);
  r.parameters_json = row.next_text();
  r.rms_m = row.next_double();
  r.kind = honest_registration_kind(r.kind, row.next_text());
  if (!row.next_is_null()) {  // NULL: no camera map was kept (project_schema.cpp, version 4)
    photogrammetry::Similarity camera;
    camera.scale = row.next_double();
    const Eigen::Vector4d wxyz = next_vector4(row);
    camera.R =
        Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
    camera.t = next_vector3(row);
    m.camera_to_mesh = camera;
  }
  Statement res(db_,
                "SELECT label, dx, dy, dz FROM registration_residual WHERE model_id = ? ORDER "
                "BY idx",
                "loading model " + std::to_string(id));
  res.bind(1, id);
  while (res.step()) {
    RowReader residual(res);
    const std::string label = residual.next_text();
    m.residuals.push_back({label, next_vector3(residual)});
  }
  return m;
}

std::vector<ModelSummary> ProjectStore::list_models(std::optional<RecordId> capture_id) {
  Statement st(db_,
               "SELECT id, capture_id, preset, created_at, registration_kind, vertex_count, "
               "face_count, registration_rms_m, " +
                   std::string(kStoredNorthSource) + " FROM model WHERE " +
                   (capture_id ? "capture_id = ?1" : "?1 IS NULL") + " ORDER BY id",
               "listing models");
  st.bind(1, capture_id);
  std::vector<ModelSummary> out;
  while (st.step()) {
    RowReader row(st);
    ModelSummary s;
    s.id = row.next_int64();
    s.capture_id = row.next_optional_int64();
    s.preset = row.next_text();
    s.created_at = row.next_text();
    s.registration_kind = row.next_text();
    s.vertex_count = row.next_int64();
    s.face_count = row.next_int64();
    s.registration_rms_m = row.next_double();
    s.registration_kind = honest_registration_kind(s.registration_kind, row.next_text());
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<ModelSummary> ProjectStore::list_visit_models(RecordId visit_id) {
  std::vector<ModelSummary> out;
  for (const auto& c : list_captures(visit_id)) {
    auto models = list_models(c.id);
    if (!models.empty()) out.push_back(std::move(models.back()));
  }
  return out;
}

}  // namespace rockface::storage
