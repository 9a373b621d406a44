#include "firmware-app/import/import_surface.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/photogrammetry/surface/cloud_meshing.h"
#include "core/photogrammetry/surface/cloud_noise.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "core/photogrammetry/surface/virtual_view.h"
#include "firmware-app/import/import_control_points.h"
#include "firmware-app/import/round_meshing.h"
#include "firmware-app/records/project_visit.h"
#include "storage/project/model_registration.h"

namespace rockface::app {

namespace import_detail {

std::string words_of(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << p.x() << " " << p.y() << " " << p.z();
  return s.str();
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
  std::ostringstream s_how;
  s_how.precision(3);
  s_how << "from bearing " << bearing
        << " deg (the file says no side: give --view-from if that is behind the rock)";
  how = s_how.str();
  return n;
}

nlohmann::json json_vector(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace import_detail

ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request) {
  NoProgress quiet;
  return import_surface(store, request, quiet);
}

ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request,
                            Progress& progress) {
  using namespace import_detail;
  if (store.read_only())
    throw InputError(store.file().string(), "cannot import: " + store.read_only_reason());
  if (request.visit) require_visit(store, *request.visit);
  if (!request.frame.empty() && request.frame != "survey" && request.frame != "local")
    throw InputError("--frame", "'" + request.frame + "' (survey or local)");

  if (request.pole && !request.gcp_file.empty())
    throw InputError("--pole", "the range pole or ground control (--gcp), not both");
  if (request.north && !request.pole)
    throw InputError("--azimuth",
                     "a compass line turns a cloud the range pole has levelled: give --pole");
  std::optional<double> pole_length = request.pole_length_m;
  if (request.pole && !pole_length) {
    // The length the geologist typed for this project's photographs.
    if (const auto typed = store.latest_capture_setting("range_pole_m")) try {
        pole_length = std::stod(*typed);
      } catch (const std::exception&) {
      }
    if (!pole_length)
      throw InputError("--range-pole",
                       "give the pole's length between its targets (the project has none typed)");
  }

  // Everything read and checked before anything is stored.
  progress.step("reading the file", 0.02);
  storage::ImportedSurface s = storage::read_imported_surface(request.file, request.file_options);
  const std::string source = request.file.string();
  ImportResult r;
  r.format = s.format;
  r.points = s.mesh.vertices.size();
  r.skipped_points = s.skipped_points;
  r.frame =
      !request.frame.empty() ? request.frame : (s.datum.isZero() ? std::string("local") : "survey");
  r.registration_kind = r.frame == "survey" ? storage::kScannerRegistration : "none";
  r.file_datum = s.datum;

  // The stored frame: the project's (datum-relative) for survey
  // coordinates, the file's own for a local frame.
  const storage::ProjectInfo project = store.project();
  r.project_datum = project.datum;
  Eigen::Vector3d shift = s.datum;  // stored = read + shift
  if (r.frame == "survey") {
    if (project.datum.isZero() && store.list_models().empty()) {
      r.project_datum = s.datum;
      r.project_datum_set = !s.datum.isZero();
    }
    shift = s.datum - r.project_datum;
  }
  for (auto& p : s.mesh.vertices) p += shift;
  std::optional<Eigen::Vector3d> view_from;
  bool from_scanner = false;
  if (request.view_from) {
    view_from =
        *request.view_from - (r.frame == "survey" ? r.project_datum : Eigen::Vector3d::Zero());
  } else if (!s.scanner_positions.empty()) {
    // Where the scanner stood (PTX's header): the side it saw; several
    // scans, their mean.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : s.scanner_positions) sum += p;
    view_from = sum / static_cast<double>(s.scanner_positions.size()) + shift;
    from_scanner = true;
  }

  // A cloud becomes a surface; a mesh keeps its faces.
  progress.step(s.mesh.faces.empty() ? "meshing the cloud" : "reading its faces", 0.3);
  const bool from_file = !s.mesh.faces.empty();
  std::vector<std::array<int, 3>> triangles;
  photogrammetry::CloudMesh meshed;
  if (from_file) {
    triangles.reserve(s.mesh.faces.size());
    for (const auto& f : s.mesh.faces) triangles.push_back({f[0], f[1], f[2]});
    const photogrammetry::BestPlane plane = photogrammetry::best_plane(s.mesh.vertices);
    meshed.centroid = plane.centroid;
    meshed.normal = plane.normal;
    photogrammetry::SurfaceMesh edges;  // for its median edge length: the spacing
    edges.vertices = s.mesh.vertices;
    edges.triangles = triangles;
    meshed.median_spacing = edges.median_edge_length();
  } else {
    // A scan of a whole round in a project with a tunnel: on the tunnel's
    // developed view (round_meshing.h); any other cloud over its best plane.
    std::optional<RoundMesh> round;
    // (A cloud with texture coordinates but no faces keeps its order: the
    // round's reordering moves points and colours only.)
    if (r.frame == "survey" && s.mesh.texcoords.empty())
      if (const auto tunnel = store.load_tunnel())
        round = mesh_round(s.mesh.vertices, s.mesh.colours, tunnel->alignment(r.project_datum),
                           tunnel->profile);
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
    triangles = std::move(meshed.triangles);
    r.meshed = true;
    r.unused_points = meshed.unused_points;
  }
  if (triangles.empty())
    throw InputError(source,
                     "no surface: every triangle bridged a gap wider than " +
                         std::to_string(photogrammetry::CloudMeshingOptions{}.max_edge_to_spacing) +
                         " point spacings");
  r.triangles = triangles.size();
  r.point_spacing_m = meshed.median_spacing;
  Eigen::Vector3d viewer = meshed.normal;
  if (!r.round_meshing.empty()) {
    // Its triangles already face the inside; the view looks at the face
    // from behind it, along the drive.
    r.view_side = "from behind the face, along the tunnel";
  } else {
    viewer = toward_viewer(s, triangles, meshed.centroid, meshed.normal, view_from, from_file,
                           r.view_side);
    if (from_scanner) r.view_side = "from the side the scanner stood on (the file's header)";
    if (r.meshed && viewer.dot(meshed.normal) < 0)  // counter-clockwise seen from the viewer
      for (auto& t : triangles) std::swap(t[1], t[2]);
  }

  progress.step("drawing the view to map on", 0.6);
  cv::Mat texture;
  if (!s.texture_file.empty()) {
    texture = cv::imread(s.texture_file, cv::IMREAD_COLOR);
    if (texture.empty())
      throw InputError(source, "its texture " + s.texture_file + " is not an image OpenCV reads");
  }
  photogrammetry::VirtualViewInput in;
  in.vertices = &s.mesh.vertices;
  in.triangles = &triangles;
  in.colours = &s.mesh.colours;
  in.texcoords = &s.mesh.texcoords;
  in.texture = texture;
  in.centre = meshed.centroid;
  in.toward_viewer = viewer;
  in.point_spacing = meshed.median_spacing;
  photogrammetry::VirtualView view = photogrammetry::render_virtual_view(in);
  photogrammetry::Similarity camera;
  camera.R = view.pose.R.transpose();
  camera.t = view.pose.centre;
  // Ground control picked on the view: the cloud (and the view's camera)
  // scaled, levelled and turned onto the survey, stored in the project's
  // frame (import_control_points.h).
  std::optional<photogrammetry::ControlPointRegistration> control;
  if (!request.gcp_file.empty()) {
    if (r.frame != "local")
      throw InputError("--gcp",
                       "the cloud is in survey coordinates already (give --frame local "
                       "if they are a local frame's)");
    control = register_import_to_control(request.gcp_file, s.mesh.vertices, triangles, view.pixels,
                                         view.pose.centre);
    if (project.datum.isZero() && store.list_models().empty()) {
      r.project_datum = control->datum;
      r.project_datum_set = true;
    }
    photogrammetry::Similarity onto = control->transform;
    onto.t += control->datum - r.project_datum;
    for (auto& p : s.mesh.vertices) p = onto.apply(p);
    camera = camera.then(onto);
    r.registration_kind = "ground_control";
    r.control_points = control->residuals.size();
    r.control_rms_m = control->rms_m;
    r.control_scale = onto.scale;
  }
  // The range pole's targets picked on the cloud (import_range_pole.h): the
  // cloud and the view's camera scaled, levelled and, by a compass line,
  // turned to north; the lower target at the origin as a photographed pole's.
  std::optional<ImportPoleRegistration> pole;
  nlohmann::json pole_targets = nlohmann::json::array();
  if (request.pole) {
    if (r.frame != "local")
      throw InputError("--pole",
                       "the cloud is in survey coordinates already (give --frame local "
                       "if they are a local frame's)");
    pole = register_import_to_pole(*request.pole, *pole_length, request.north, camera);
    const char* which[2] = {"lower", "upper"};
    const Eigen::Vector3d ends[2] = {request.pole->lower, request.pole->upper};
    for (int k = 0; k < 2; ++k) {
      // Its pixel in the view, where the 3D view and the report show it.
      const Eigen::Vector3d c = view.pose.to_camera(ends[k]);
      const Eigen::Vector2d px(view.intrinsics.fx * c.x() / c.z() + view.intrinsics.cx,
                               view.intrinsics.fy * c.y() / c.z() + view.intrinsics.cy);
      pole_targets.push_back({{"which", which[k]},
                              {"left_px", {px.x(), px.y()}},
                              {"file", {ends[k].x(), ends[k].y(), ends[k].z()}},
                              {"world", json_vector(pole->transform.apply(ends[k]))}});
    }
    for (auto& p : s.mesh.vertices) p = pole->transform.apply(p);
    camera = camera.then(pole->transform);
    r.registration_kind =
        storage::registration_kind("range pole", request.north ? "compass" : "none");
    r.pole_length_m = pole_length;
    r.north_rotation_deg = pole->north_rotation_deg;
  }
  view.pixels = {};  // the texture coordinates say the same; memory for the store
  r.view_width = view.intrinsics.width;
  r.view_height = view.intrinsics.height;
  // A texture's colour for every vertex too (the 3D view draws vertex colours).
  if (s.mesh.colours.empty() && !texture.empty()) {
    s.mesh.colours.reserve(s.mesh.vertices.size());
    for (const auto& t : s.mesh.texcoords) {
      const int x = std::clamp(static_cast<int>(t[0] * static_cast<float>(texture.cols)), 0,
                               texture.cols - 1);
      const int y = std::clamp(static_cast<int>(t[1] * static_cast<float>(texture.rows)), 0,
                               texture.rows - 1);
      const cv::Vec3b c = texture.at<cv::Vec3b>(y, x);
      s.mesh.colours.push_back({c[2], c[1], c[0]});
    }
  }
  std::vector<unsigned char> jpeg;
  // Quality 95: the view is what the geologist traces joints on.
  if (!cv::imencode(".jpg", view.image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95}))
    throw Error("cannot encode the virtual view of " + source);

  storage::Model model;
  model.preset = "standard";
  model.mesh.vertices = std::move(s.mesh.vertices);
  static_assert(std::is_same_v<std::array<int, 3>, std::array<std::int32_t, 3>>);
  model.mesh.faces = std::move(triangles);  // no copy: a 10-million-point cloud's are 240 MB
  model.mesh.colours = std::move(s.mesh.colours);
  model.mesh.texcoords = std::move(view.texcoords);  // into the view, the model's texture
  model.texture_side = "left";
  model.registration.kind = r.registration_kind;
  model.camera_to_mesh = camera;
  if (control) {
    for (const auto& e : control->residuals) model.residuals.push_back({e.id, e.residual});
    model.registration.rms_m = control->rms_m;
  }

  std::ostringstream words;
  words << request.file.filename().string() << ": " << s.format << ", " << r.points << " points";
  if (r.skipped_points) words << " (" << r.skipped_points << " without a return left out)";
  words << (!r.round_meshing.empty() ? ", meshed here as " + r.round_meshing
            : r.meshed               ? ", meshed here (2.5D Delaunay, holes kept)"
                                     : ", its own faces");
  words << (r.frame == "survey" ? ", survey coordinates (file offset " + words_of(s.datum) + ")"
                                : ", a local frame");
  if (pole)
    words << (request.north ? " scaled and levelled by the range pole, north by the compass line"
                            : " scaled and levelled by the range pole (no north)");
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
                 {"words", words.str()}};
  p["point_spacing"] = r.point_spacing_m;
  // What the over- and underbreak take as the surface's precision (a
  // deviation within twice it is not counted): a scan's own scatter.
  if (r.noise_sigma_m) {
    p["predicted_depth_sigma_mm"] = *r.noise_sigma_m * 1000;
    p["import"]["noise_sigma_mm"] = *r.noise_sigma_m * 1000;
  }
  if (control) {
    nlohmann::json residuals = nlohmann::json::array();
    for (const auto& e : control->residuals)
      residuals.push_back({{"id", e.id}, {"distance_m", e.distance}});
    p["registration"] = {{"scale_source", "ground control points"},
                         {"vertical_source", "ground control points"},
                         {"north_source", "ground control points"},
                         {"scaled", true},
                         {"scale", r.control_scale},
                         {"control_points",
                          {{"rms_m", control->rms_m},
                           {"worst", control->worst_id},
                           {"worst_m", control->worst_m},
                           {"residuals", residuals}}}};
  } else if (pole) {
    p["registration"] = {{"scale_source", "range pole"},
                         {"vertical_source", "range pole"},
                         {"north_source", request.north ? "compass" : "none"},
                         {"scaled", true},
                         {"scale", pole->transform.scale},
                         {"range_pole", {{"length_m", *pole_length}, {"targets", pole_targets}}}};
    if (request.north)
      p["registration"]["north"] = {
          {"azimuth_deg", request.north->azimuth_deg},
          {"declination_deg", request.north->declination_deg},
          {"reference_line", {json_vector(request.north->from), json_vector(request.north->to)}},
          {"rotation_about_vertical_deg", pole->north_rotation_deg.value_or(0.0)}};
  } else if (r.frame == "survey")
    p["registration"] = {{"scale_source", storage::kScannerRegistrationWords},
                         {"vertical_source", storage::kScannerRegistrationWords},
                         {"north_source", storage::kScannerRegistrationWords},
                         {"scaled", true},
                         {"scale", 1.0}};
  else
    p["registration"] = {{"scale_source", "none"},
                         {"vertical_source", "none"},
                         {"north_source", "none"},
                         {"scaled", false}};
  model.registration.parameters_json = p.dump();

  storage::Calibration calibration;
  calibration.intrinsics = view.intrinsics;
  calibration.method = "virtual view of an imported 3D image";
  storage::Capture capture;
  capture.label = "imported " + request.file.filename().string();
  capture.left.bytes.assign(jpeg.begin(), jpeg.end());
  capture.right = capture.left;  // one view: the image is stored once
  capture.settings = {{"source", "import"}, {"file", source}, {"format", s.format}};

  progress.step("storing the 3D image", 0.85);
  store.in_one_transaction("importing " + source, [&] {
    if (r.project_datum_set) {
      storage::ProjectInfo info = project;
      info.datum = r.project_datum;
      store.update_project(info);
    }
    r.visit = request.visit ? *request.visit : store.begin_visit("import " + source);
    capture.visit_id = r.visit;
    capture.calibration_id = store.save_calibration(calibration);
    r.capture = store.save_capture(capture);
    model.capture_id = r.capture;
    model.texture_capture_id = r.capture;
    r.model = store.save_model(model);
    store.log_action(r.visit, "import", words.str());
  });
  return r;
}

}  // namespace rockface::app
