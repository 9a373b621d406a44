#include "firmware-app/import/import_surface.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/photogrammetry/surface/cloud_meshing.h"
#include "core/photogrammetry/surface/cloud_noise.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "core/photogrammetry/surface/virtual_view.h"
#include "core/photogrammetry/targets/cloud_range_pole.h"
#include "firmware-app/import/import_control_points.h"
#include "firmware-app/import/round_meshing.h"
#include "firmware-app/records/project_visit.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace import_detail {

std::string words_of(const Eigen::Vector3d& p) {
  return format_fixed(p.x(), 3) + " " + format_fixed(p.y(), 3) + " " + format_fixed(p.z(), 3);
}

// The side the view looks from: the --view-from point, the file's own
// normals or faces, else up for a surface lying flat, else the side of the
// best plane's normal whose bearing is in [0, 180) (named in the note).
Eigen::Vector3d toward_viewer(const storage::ImportedSurface& s,
                              const std::vector<std::array<int, 3>>& triangles,
                              const Eigen::Vector3d& centre, const Eigen::Vector3d& plane_normal,
                              const std::optional<Eigen::Vector3d>& view_from, bool faces_from_file,
                              std::string& how) {
  Eigen::Vector3d n = plane_normal;
  if (view_from) {
    if ((*view_from - centre).dot(n) < 0) n = -n;
    how = "from the side of the given --view-from point";
    return n;
  }
  if (faces_from_file) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double area = 0;
    const auto& V = s.mesh.vertices;
    for (const auto& t : triangles) {
      const Eigen::Vector3d c =
          (V[static_cast<std::size_t>(t[1])] - V[static_cast<std::size_t>(t[0])])
              .cross(V[static_cast<std::size_t>(t[2])] - V[static_cast<std::size_t>(t[0])]);
      sum += c;
      area += c.norm();
    }
    // 0.2: the faces agree on a side (an open surface seen from one side);
    // a closed mesh's or a folded one's sum is near zero and says nothing.
    if (area > 0 && sum.norm() > 0.2 * area) {
      how = "from the side its faces look to";
      return sum.dot(n) < 0 ? Eigen::Vector3d(-n) : n;
    }
  }
  if (!s.normals.empty()) {
    double vote = 0;
    for (const auto& m : s.normals) vote += m.cast<double>().dot(n);
    if (vote != 0) {
      how = "from the side the file's normals point to";
      return vote < 0 ? Eigen::Vector3d(-n) : n;
    }
  }
  // 0.5: steeper than 60 degrees is a face or a wall, flatter a floor or a
  // slope seen from above.
  if (std::abs(n.z()) > 0.5) {
    how = "from above";
    return n.z() < 0 ? Eigen::Vector3d(-n) : n;
  }
  if (std::atan2(n.x(), n.y()) < 0) n = -n;
  const double bearing = std::atan2(n.x(), n.y()) * 180 / M_PI;
  how = "from bearing " + format_significant(bearing, 3) +
        " deg (the file says no side: give --view-from if that is behind the rock)";
  return n;
}

nlohmann::json json_vector(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

// The request's checks that need no file, and the range pole's length: the
// request's, else the one the geologist typed for this project's photographs.
std::optional<double> checked_pole_length(storage::ProjectStore& store,
                                          const ImportRequest& request) {
  if (store.read_only())
    throw InputError(store.file().string(), "cannot import: " + store.read_only_reason());
  if (request.visit) require_visit(store, *request.visit);
  if (!request.frame.empty() && request.frame != "survey" && request.frame != "local")
    throw InputError("--frame", "'" + request.frame + "' (survey or local)");

  const bool by_pole = request.pole || request.find_pole;
  if (by_pole && !request.gcp_file.empty())
    throw InputError("--pole", "the range pole or ground control (--gcp), not both");
  if (request.north && !by_pole)
    throw InputError("--azimuth",
                     "a compass line turns a cloud the range pole has levelled: give --pole");
  std::optional<double> pole_length = request.pole_length_m;
  if (by_pole && !pole_length) {
    if (const auto typed = store.latest_capture_setting("range_pole_m")) try {
        pole_length = std::stod(*typed);
      } catch (const std::exception&) {
      }
    if (!pole_length)
      throw InputError("--range-pole",
                       "give the pole's length between its targets (the project has none typed)");
  }
  return pole_length;
}

// A project with no datum and no model yet takes the first import's datum.
bool project_takes_datum(storage::ProjectStore& store, const storage::ProjectInfo& project) {
  return project.datum.isZero() && store.list_models().empty();
}

// What the file held, as the result says it, and the frame it is stored in
// (the request's, else survey for coordinates far from the origin).
ImportResult result_of_reading(const storage::ImportedSurface& s, const ImportRequest& request) {
  ImportResult r;
  r.format = s.format;
  r.points = s.mesh.vertices.size();
  r.skipped_points = s.skipped_points;
  r.intensity_as_grey = s.intensity_as_grey;
  r.frame =
      !request.frame.empty() ? request.frame : (s.datum.isZero() ? std::string("local") : "survey");
  r.registration_kind = r.frame == "survey" ? storage::kScannerRegistration : "none";
  r.file_datum = s.datum;
  return r;
}

// Where the surface is seen from, in the stored frame.
struct ImportViewPoint {
  std::optional<Eigen::Vector3d> point;
  bool from_scanner = false;  // the file's header said where the scanner stood
};

// Moves the points into the stored frame: the project's (datum-relative) for
// survey coordinates, the file's own for a local frame. Returns the point the
// surface is seen from in that frame: the request's, else the scanner's.
ImportViewPoint place_in_stored_frame(storage::ProjectStore& store,
                                      const storage::ProjectInfo& project,
                                      const ImportRequest& request, storage::ImportedSurface& s,
                                      ImportResult& r) {
  r.project_datum = project.datum;
  Eigen::Vector3d shift = s.datum;  // stored = read + shift
  if (r.frame == "survey") {
    if (project_takes_datum(store, project)) {
      r.project_datum = s.datum;
      r.project_datum_set = !s.datum.isZero();
    }
    shift = s.datum - r.project_datum;
  }
  for (auto& p : s.mesh.vertices) p += shift;
  ImportViewPoint seen;
  if (request.view_from) {
    seen.point =
        *request.view_from - (r.frame == "survey" ? r.project_datum : Eigen::Vector3d::Zero());
  } else if (!s.scanner_positions.empty()) {
    // Where the scanner stood (PTX's header): the side it saw; several
    // scans, their mean.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : s.scanner_positions) sum += p;
    seen.point = sum / static_cast<double>(s.scanner_positions.size()) + shift;
    seen.from_scanner = true;
  }
  return seen;
}

// The surface's triangles and what the view is drawn around: the meshing's
// plane (or round's view) and point spacing.
struct ImportTriangles {
  std::vector<std::array<int, 3>> triangles;
  photogrammetry::CloudMesh meshed;  // its triangles moved to `triangles`
  bool from_file = false;            // the file's own faces
};

// A mesh keeps its faces, over its best plane.
ImportTriangles faces_of_file(const storage::ImportedSurface& s) {
  ImportTriangles out;
  out.from_file = true;
  out.triangles.reserve(s.mesh.faces.size());
  for (const auto& f : s.mesh.faces) out.triangles.push_back({f[0], f[1], f[2]});
  const photogrammetry::BestPlane plane = photogrammetry::best_plane(s.mesh.vertices);
  out.meshed.centroid = plane.centroid;
  out.meshed.normal = plane.normal;
  photogrammetry::SurfaceMesh edges;  // for its median edge length: the spacing
  edges.vertices = s.mesh.vertices;
  edges.triangles = out.triangles;
  out.meshed.median_spacing = edges.median_edge_length();
  return out;
}

// A cloud meshed here: a scan of a whole round in a project with a tunnel on
// the tunnel's developed view (round_meshing.h); any other cloud over its
// best plane, with its scatter normal to that plane.
ImportTriangles mesh_cloud(storage::ProjectStore& store, storage::ImportedSurface& s,
                           const std::string& source, ImportResult& r) {
  ImportTriangles out;
  std::optional<RoundMesh> round;
  // (A cloud with texture coordinates but no faces keeps its order: the
  // round's reordering moves points and colours only.)
  if (r.frame == "survey" && s.mesh.texcoords.empty())
    if (const auto tunnel = store.load_tunnel())
      round = mesh_round(s.mesh.vertices, s.mesh.colours, tunnel->alignment(r.project_datum),
                         tunnel->profile);
  photogrammetry::CloudMesh& meshed = out.meshed;
  try {
    if (!round) meshed = photogrammetry::mesh_point_cloud(s.mesh.vertices);
  } catch (const InputError& e) {
    throw InputError(source, e.reason());
  }
  if (round) {
    meshed.triangles = std::move(round->triangles);
    meshed.centroid = round->view_centre;
    meshed.normal = round->toward_viewer;
    meshed.median_spacing = round->median_spacing;
    meshed.unused_points = round->unused_points;
    r.round_meshing = round->words;
    r.noise_sigma_m = round->noise_sigma_m;
  } else {
    // The cloud's scatter normal to its surface, in cells over its plane.
    const Eigen::Vector3d u = meshed.normal.unitOrthogonal(), v = meshed.normal.cross(u);
    std::vector<Eigen::Vector2d> uv(s.mesh.vertices.size());
    for (std::size_t i = 0; i < uv.size(); ++i) {
      const Eigen::Vector3d d = s.mesh.vertices[i] - meshed.centroid;
      uv[i] = {d.dot(u), d.dot(v)};
    }
    r.noise_sigma_m = photogrammetry::cloud_noise_sigma(s.mesh.vertices, uv,
                                                        std::max(0.1, 4 * meshed.median_spacing));
  }
  out.triangles = std::move(meshed.triangles);
  r.meshed = true;
  r.unused_points = meshed.unused_points;
  return out;
}

// The side the view looks from (toward_viewer), the file's triangles turned
// counter-clockwise seen from it where they were meshed here.
Eigen::Vector3d face_the_viewer(const storage::ImportedSurface& s, ImportTriangles& surface,
                                const ImportViewPoint& seen, ImportResult& r) {
  if (!r.round_meshing.empty()) {
    // Its triangles already face the inside; the view looks at the face
    // from behind it, along the drive.
    r.view_side = "from behind the face, along the tunnel";
    return surface.meshed.normal;
  }
  const Eigen::Vector3d viewer =
      toward_viewer(s, surface.triangles, surface.meshed.centroid, surface.meshed.normal,
                    seen.point, surface.from_file, r.view_side);
  if (seen.from_scanner) r.view_side = "from the side the scanner stood on (the file's header)";
  if (r.meshed && viewer.dot(surface.meshed.normal) < 0)  // counter-clockwise seen from the viewer
    for (auto& t : surface.triangles) std::swap(t[1], t[2]);
  return viewer;
}

// The file's texture image, empty when it names none.
cv::Mat texture_of(const storage::ImportedSurface& s, const std::string& source) {
  cv::Mat texture;
  if (!s.texture_file.empty()) {
    texture = cv::imread(s.texture_file, cv::IMREAD_COLOR);
    if (texture.empty())
      throw InputError(source, "its texture " + s.texture_file + " is not an image OpenCV reads");
  }
  return texture;
}

// The virtual view the geologist traces joints on.
photogrammetry::VirtualView draw_view(const storage::ImportedSurface& s,
                                      const ImportTriangles& surface, const Eigen::Vector3d& viewer,
                                      const cv::Mat& texture) {
  photogrammetry::VirtualViewInput in;
  in.vertices = &s.mesh.vertices;
  in.triangles = &surface.triangles;
  in.colours = &s.mesh.colours;
  in.texcoords = &s.mesh.texcoords;
  in.texture = texture;
  in.centre = surface.meshed.centroid;
  in.toward_viewer = viewer;
  in.point_spacing = surface.meshed.median_spacing;
  return photogrammetry::render_virtual_view(in);
}

void require_local_frame(const ImportResult& r, const char* option) {
  if (r.frame != "local")
    throw InputError(option,
                     "the cloud is in survey coordinates already (give --frame local "
                     "if they are a local frame's)");
}

// Ground control picked on the view: the cloud (and the view's camera)
// scaled, levelled and turned onto the survey, stored in the project's frame
// (import_control_points.h). None without a --gcp file.
std::optional<photogrammetry::ControlPointRegistration> register_to_control(
    storage::ProjectStore& store, const storage::ProjectInfo& project, const ImportRequest& request,
    storage::ImportedSurface& s, const std::vector<std::array<int, 3>>& triangles,
    const photogrammetry::VirtualView& view, photogrammetry::Similarity& camera, ImportResult& r) {
  if (request.gcp_file.empty()) return std::nullopt;
  require_local_frame(r, "--gcp");
  photogrammetry::ControlPointRegistration control = register_import_to_control(
      request.gcp_file, s.mesh.vertices, triangles, view.pixels, view.pose.centre);
  if (project_takes_datum(store, project)) {
    r.project_datum = control.datum;
    r.project_datum_set = true;
  }
  photogrammetry::Similarity onto = control.transform;
  onto.t += control.datum - r.project_datum;
  for (auto& p : s.mesh.vertices) p = onto.apply(p);
  camera = camera.then(onto);
  r.registration_kind = "ground_control";
  r.control_points = control.residuals.size();
  r.control_rms_m = control.rms_m;
  r.control_scale = onto.scale;
  return control;
}

// `--pole auto`: the pole's two targets found in the cloud's colours (a
// texture's, a scanner's camera's), seen from where the view is drawn, the
// file's z taken as up (cloud_range_pole.h). None without it.
std::optional<ImportPole> find_pole_in_colours(const ImportRequest& request,
                                               const storage::ImportedSurface& s,
                                               const ImportTriangles& surface,
                                               const Eigen::Vector3d& viewer, ImportResult& r) {
  if (!request.find_pole) return std::nullopt;
  require_local_frame(r, "--pole auto");
  try {
    const photogrammetry::CloudRangePole found = photogrammetry::find_range_pole_in_cloud(
        s.mesh.vertices, s.mesh.colours, viewer, surface.meshed.median_spacing,
        Eigen::Vector3d::UnitZ());
    r.pole_found = ImportPole{found.targets[0].centre, found.targets[1].centre};
    return r.pole_found;
  } catch (const InputError& e) {
    throw InputError("--pole auto", e.reason() +
                                        "; give the targets' centres instead: --pole "
                                        "X1,Y1,Z1,X2,Y2,Z2 (lower target first)");
  }
}

// The range pole's registration and its two targets as the parameters list
// them.
struct ImportPoleOnView {
  ImportPoleRegistration registration;
  nlohmann::json targets = nlohmann::json::array();
};

// The range pole's targets picked on the cloud (import_range_pole.h): the
// cloud and the view's camera scaled, levelled and, by a compass line,
// turned to north; the lower target at the origin as a photographed pole's.
// None without --pole.
std::optional<ImportPoleOnView> register_to_pole(
    const ImportRequest& request, const std::optional<ImportPole>& ends_given,
    const std::optional<double>& pole_length, const photogrammetry::VirtualView& view,
    storage::ImportedSurface& s, photogrammetry::Similarity& camera, ImportResult& r) {
  if (!ends_given) return std::nullopt;
  require_local_frame(r, "--pole");
  ImportPoleOnView pole;
  pole.registration = register_import_to_pole(*ends_given, *pole_length, request.north, camera);
  const ImportPoleRegistration& reg = pole.registration;
  const char* which[2] = {"lower", "upper"};
  const Eigen::Vector3d ends[2] = {ends_given->lower, ends_given->upper};
  for (int k = 0; k < 2; ++k) {
    // Its pixel in the view, where the 3D view and the report show it.
    const Eigen::Vector3d c = view.pose.to_camera(ends[k]);
    const Eigen::Vector2d px(view.intrinsics.fx * c.x() / c.z() + view.intrinsics.cx,
                             view.intrinsics.fy * c.y() / c.z() + view.intrinsics.cy);
    pole.targets.push_back({{"which", which[k]},
                            {"left_px", {px.x(), px.y()}},
                            {"file", {ends[k].x(), ends[k].y(), ends[k].z()}},
                            {"world", json_vector(reg.transform.apply(ends[k]))}});
  }
  for (auto& p : s.mesh.vertices) p = reg.transform.apply(p);
  camera = camera.then(reg.transform);
  r.registration_kind =
      storage::registration_kind("range pole", request.north ? "compass" : "none");
  r.pole_length_m = pole_length;
  r.north_rotation_deg = reg.north_rotation_deg;
  return pole;
}

// A texture's colour for every vertex too (the 3D view draws vertex colours).
void colour_from_texture(storage::Mesh& mesh, const cv::Mat& texture) {
  if (!mesh.colours.empty() || texture.empty()) return;
  mesh.colours.reserve(mesh.vertices.size());
  for (const auto& t : mesh.texcoords) {
    const int x =
        std::clamp(static_cast<int>(t[0] * static_cast<float>(texture.cols)), 0, texture.cols - 1);
    const int y =
        std::clamp(static_cast<int>(t[1] * static_cast<float>(texture.rows)), 0, texture.rows - 1);
    const cv::Vec3b c = texture.at<cv::Vec3b>(y, x);
    mesh.colours.push_back({c[2], c[1], c[0]});
  }
}

// The model stored: the points, faces and colours moved in (no copy: a
// 10-million-point cloud's faces are 240 MB), textured by the view.
storage::Model model_of(storage::ImportedSurface& s, std::vector<std::array<int, 3>>& triangles,
                        photogrammetry::VirtualView& view, const photogrammetry::Similarity& camera,
                        const std::optional<photogrammetry::ControlPointRegistration>& control,
                        const ImportResult& r) {
  storage::Model model;
  model.preset = "standard";
  model.mesh.vertices = std::move(s.mesh.vertices);
  static_assert(std::is_same_v<std::array<int, 3>, std::array<std::int32_t, 3>>);
  model.mesh.faces = std::move(triangles);
  model.mesh.colours = std::move(s.mesh.colours);
  model.mesh.texcoords = std::move(view.texcoords);  // into the view, the model's texture
  model.texture_side = "left";
  model.registration.kind = r.registration_kind;
  model.camera_to_mesh = camera;
  if (control) {
    for (const auto& e : control->residuals) model.residuals.push_back({e.id, e.residual});
    model.registration.rms_m = control->rms_m;
  }
  return model;
}

}  // namespace import_detail

std::string intensity_range_words(const ImportResult& r) {
  if (!r.intensity_as_grey) return {};
  return format_significant((*r.intensity_as_grey)[0], 6) + " black to " +
         format_significant((*r.intensity_as_grey)[1], 6) + " white";
}

namespace import_detail {

// The import in words, as the visit's log and the parameters say it.
std::string import_words(const ImportRequest& request, const storage::ImportedSurface& s,
                         const ImportResult& r, bool by_pole) {
  std::ostringstream words;
  words << request.file.filename().string() << ": " << s.format << ", " << r.points << " points";
  if (r.skipped_points) words << " (" << r.skipped_points << " without a return left out)";
  if (r.intensity_as_grey)
    words << ", no colours: its intensity drawn as grey (" << intensity_range_words(r) << ")";
  words << (!r.round_meshing.empty() ? ", meshed here as " + r.round_meshing
            : r.meshed               ? ", meshed here (2.5D Delaunay, holes kept)"
                                     : ", its own faces");
  words << (r.frame == "survey" ? ", survey coordinates (file offset " + words_of(s.datum) + ")"
                                : ", a local frame");
  if (by_pole)
    words << (request.north ? " scaled and levelled by the range pole, north by the compass line"
                            : " scaled and levelled by the range pole (no north)")
          << (request.find_pole ? ", its targets found in the cloud's colours" : "");
  return words.str();
}

// Where the stored model's scale, vertical and north come from.
nlohmann::json registration_json(
    const ImportRequest& request, const std::optional<double>& pole_length, const ImportResult& r,
    const std::optional<photogrammetry::ControlPointRegistration>& control,
    const std::optional<ImportPoleOnView>& pole) {
  if (control) {
    nlohmann::json residuals = nlohmann::json::array();
    for (const auto& e : control->residuals)
      residuals.push_back({{"id", e.id}, {"distance_m", e.distance}});
    return {{"scale_source", "ground control points"},
            {"vertical_source", "ground control points"},
            {"north_source", "ground control points"},
            {"scaled", true},
            {"scale", r.control_scale},
            {"control_points",
             {{"rms_m", control->rms_m},
              {"worst", control->worst_id},
              {"worst_m", control->worst_m},
              {"residuals", residuals}}}};
  }
  if (pole) {
    nlohmann::json registration = {
        {"scale_source", "range pole"},
        {"vertical_source", "range pole"},
        {"north_source", request.north ? "compass" : "none"},
        {"scaled", true},
        {"scale", pole->registration.transform.scale},
        {"range_pole",
         {{"length_m", *pole_length},
          {"targets", pole->targets},
          {"targets_from", request.find_pole ? "found in the cloud's colours" : "given"}}}};
    if (request.north)
      registration["north"] = {
          {"azimuth_deg", request.north->azimuth_deg},
          {"declination_deg", request.north->declination_deg},
          {"reference_line", {json_vector(request.north->from), json_vector(request.north->to)}},
          {"rotation_about_vertical_deg", pole->registration.north_rotation_deg.value_or(0.0)}};
    return registration;
  }
  if (r.frame == "survey")
    return {{"scale_source", storage::kScannerRegistrationWords},
            {"vertical_source", storage::kScannerRegistrationWords},
            {"north_source", storage::kScannerRegistrationWords},
            {"scaled", true},
            {"scale", 1.0}};
  return {{"scale_source", "none"},
          {"vertical_source", "none"},
          {"north_source", "none"},
          {"scaled", false}};
}

// The model's registration parameters (rockface-import/1): what was read,
// how it was meshed and seen, its precision and its registration.
nlohmann::json import_parameters(const std::string& source, const storage::ImportedSurface& s,
                                 const ImportResult& r, const std::string& words,
                                 nlohmann::json registration) {
  nlohmann::json p;
  p["format"] = "rockface-import/1";
  p["import"] = {{"file", source},
                 {"format", s.format},
                 {"points", r.points},
                 {"skipped_points", r.skipped_points},
                 {"triangles", r.triangles},
                 {"meshed", r.meshed},
                 {"round_meshing", r.round_meshing},
                 {"frame", r.frame},
                 {"file_datum", {s.datum.x(), s.datum.y(), s.datum.z()}},
                 {"view_side", r.view_side},
                 {"words", words}};
  // The colours are the file's intensity, this range drawn black to white.
  if (r.intensity_as_grey)
    p["import"]["intensity_as_grey"] = {(*r.intensity_as_grey)[0], (*r.intensity_as_grey)[1]};
  p["point_spacing"] = r.point_spacing_m;
  // What the over- and underbreak take as the surface's precision (a
  // deviation within twice it is not counted): a scan's own scatter.
  if (r.noise_sigma_m) {
    p["predicted_depth_sigma_mm"] = *r.noise_sigma_m * 1000;
    p["import"]["noise_sigma_mm"] = *r.noise_sigma_m * 1000;
  }
  p["registration"] = std::move(registration);
  return p;
}

// The view as the capture's one image (JPEG quality 95: the view is what the
// geologist traces joints on).
storage::Capture capture_of(const ImportRequest& request, const std::string& source,
                            const storage::ImportedSurface& s,
                            const photogrammetry::VirtualView& view) {
  std::vector<unsigned char> jpeg;
  if (!cv::imencode(".jpg", view.image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95}))
    throw Error("cannot encode the virtual view of " + source);
  storage::Capture capture;
  capture.label = "imported " + request.file.filename().string();
  capture.left.bytes.assign(jpeg.begin(), jpeg.end());
  capture.right = capture.left;  // one view: the image is stored once
  capture.settings = {{"source", "import"}, {"file", source}, {"format", s.format}};
  return capture;
}

// Everything in one transaction: the project's datum if it took the file's,
// the visit, the view's calibration and capture, the model, the log.
void store_import(storage::ProjectStore& store, const ImportRequest& request,
                  const storage::ProjectInfo& project, const std::string& source,
                  const photogrammetry::CameraIntrinsics& intrinsics, storage::Capture& capture,
                  storage::Model& model, const std::string& words, ImportResult& r) {
  storage::Calibration calibration;
  calibration.intrinsics = intrinsics;
  calibration.method = "virtual view of an imported 3D image";
  store.in_one_transaction("importing " + source, [&] {
    if (r.project_datum_set) {
      storage::ProjectInfo info = project;
      info.datum = r.project_datum;
      store.update_project(info);
    }
    r.visit = request.visit ? *request.visit
                            : store.begin_visit("import " + source, "", request.geologist);
    capture.visit_id = r.visit;
    capture.calibration_id = store.save_calibration(calibration);
    r.capture = store.save_capture(capture);
    model.capture_id = r.capture;
    model.texture_capture_id = r.capture;
    r.model = store.save_model(model);
    store.log_action(r.visit, "import", words);
  });
}

}  // namespace import_detail

ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request) {
  NoProgress quiet;
  return import_surface(store, request, quiet);
}

ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request,
                            Progress& progress) {
  using namespace import_detail;
  const std::optional<double> pole_length = checked_pole_length(store, request);

  // Everything read and checked before anything is stored.
  progress.step("reading the file", 0.02);
  storage::ImportedSurface s = storage::read_imported_surface(request.file, request.file_options);
  const std::string source = request.file.string();
  ImportResult r = result_of_reading(s, request);
  const storage::ProjectInfo project = store.project();
  const ImportViewPoint seen = place_in_stored_frame(store, project, request, s, r);

  // A cloud becomes a surface; a mesh keeps its faces.
  progress.step(s.mesh.faces.empty() ? "meshing the cloud" : "reading its faces", 0.3);
  ImportTriangles surface =
      s.mesh.faces.empty() ? mesh_cloud(store, s, source, r) : faces_of_file(s);
  if (surface.triangles.empty())
    throw InputError(source,
                     "no surface: every triangle bridged a gap wider than " +
                         std::to_string(photogrammetry::CloudMeshingOptions{}.max_edge_to_spacing) +
                         " point spacings");
  r.triangles = surface.triangles.size();
  r.point_spacing_m = surface.meshed.median_spacing;
  const Eigen::Vector3d viewer = face_the_viewer(s, surface, seen, r);

  progress.step("drawing the view to map on", 0.6);
  const cv::Mat texture = texture_of(s, source);
  photogrammetry::VirtualView view = draw_view(s, surface, viewer, texture);
  photogrammetry::Similarity camera;
  camera.R = view.pose.R.transpose();
  camera.t = view.pose.centre;
  const auto control =
      register_to_control(store, project, request, s, surface.triangles, view, camera, r);
  colour_from_texture(s.mesh, texture);  // a textured mesh's targets are in its texture
  const std::optional<ImportPole> pole_ends =
      request.find_pole ? find_pole_in_colours(request, s, surface, viewer, r) : request.pole;
  const auto pole = register_to_pole(request, pole_ends, pole_length, view, s, camera, r);
  view.pixels = {};  // the texture coordinates say the same; memory for the store
  r.view_width = view.intrinsics.width;
  r.view_height = view.intrinsics.height;
  storage::Capture capture = capture_of(request, source, s, view);

  storage::Model model = model_of(s, surface.triangles, view, camera, control, r);
  const std::string words = import_words(request, s, r, pole.has_value());
  model.registration.parameters_json =
      import_parameters(source, s, r, words,
                        registration_json(request, pole_length, r, control, pole))
          .dump();

  progress.step("storing the 3D image", 0.85);
  store_import(store, request, project, source, view.intrinsics, capture, model, words, r);
  return r;
}

}  // namespace rockface::app
