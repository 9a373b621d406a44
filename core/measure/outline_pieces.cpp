#include "core/measure/outline_pieces.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/progress.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/measure/facets/facets.h"
#include "core/measure/free_face_side.h"
#include "core/measure/outline_pieces_phases.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

// A face outlined at one stand is a few walls at most; more planes than
// this are the facets of a rough surface, not pieces of a folded face.
constexpr std::size_t kMaxPieces = 8;
// Points given to the nearest plane and the planes refitted: the labels
// settle in two or three passes (each moves only points near a fold).
constexpr int kRefinePasses = 3;
// Two planes closer than this in attitude meet far outside the outline
// (0.5 degrees: their line lies more than 100 m away for a metre of offset),
// so no fold line between them can be drawn.
constexpr double kParallelDeg = 0.5;
// An outline whose corners enclose less than one square pixel has no
// inside: its corners lie on one line (a tap repeated, a slip of the finger).
constexpr double kMinOutlinePx2 = 1.0;
// With three pieces or more, each cut by straight fold lines: a piece whose
// polygon holds less than this share of its points is not bounded by those
// lines (a piece wrapping around another), which the geologist is told.
constexpr double kMinCoveredShare = 0.9;

std::string outline_mm(double m) {
  return format_fixed(m * 1000, 0) + " mm";
}
std::string outline_m2(double v) {
  return format_fixed(v, 2) + " m2";
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

bool inside_polygon(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& q) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y() > q.y()) != (poly[j].y() > q.y()) &&
        q.x() < (poly[j].x() - poly[i].x()) * (q.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) +
                    poly[i].x())
      in = !in;
  return in;
}

// Whether segments ab and cd cross at a point inside both (touching ends
// do not count).
bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
  const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

void check_outline(const std::vector<Eigen::Vector2d>& p, const std::string& where) {
  if (p.size() < 3)
    throw InputError(where, "needs 3 or more corners, got " + std::to_string(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p[i].allFinite())
      throw InputError(where, "corner " + std::to_string(i + 1) + " is not a finite pixel");
  // Crossing edges first: a bow-tie's two halves cancel in the area.
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      if (segments_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]))
        throw InputError(where, "its edges cross (corners " + std::to_string(i + 1) + "-" +
                                    std::to_string(i + 2) + " and " + std::to_string(j + 1) + "-" +
                                    std::to_string((j + 1) % n + 1) +
                                    "): tap the corners in order around the face");
    }
  if (std::abs(polygon_area(p)) < kMinOutlinePx2)
    throw InputError(where, "its " + std::to_string(p.size()) +
                                " corners enclose no area (they lie on one line)");
}

// measure_area's verdict on an area's plane: known unless a sliver or too
// few points for a reliable plane.
void judge_area_plane(PlaneEstimate& e, const MeasureSettings& settings) {
  if (e.fit.relief() < kMinReliefInSigmas * settings.point_sigma)
    e.problem =
        "orientation unknown: the area is a sliver (width " + outline_mm(e.fit.relief()) + " RMS)";
  else if (rad_to_deg(e.sigma) > settings.max_plane_sigma_deg)
    e.problem = "orientation unknown: too few points for a reliable plane";
  else
    e.known = true;
}

double outline_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return rad_to_deg(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

std::string attitude(const geometry::Plane& p) {
  const auto o = geometry::plane_orientation(p.normal);
  return format_fixed(rad_to_deg(o.dip), 0) + "/" + format_fixed(rad_to_deg(o.dipdir), 0);
}

}  // namespace

std::vector<Eigen::Vector2d> clip_polygon(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& a, const Eigen::Vector2d& d) {
  std::vector<Eigen::Vector2d> out;
  auto side = [&](const Eigen::Vector2d& p) { return cross2(d, p - a); };
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& p = polygon[i];
    const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  // Corners repeated where the line runs through one.
  std::vector<Eigen::Vector2d> kept;
  for (const auto& p : out)
    if (kept.empty() || (p - kept.back()).norm() > 1e-9) kept.push_back(p);
  while (kept.size() > 1 && (kept.front() - kept.back()).norm() <= 1e-9) kept.pop_back();
  return kept;
}

namespace {

// The notes joined into one ("a; b").
std::string joined(const std::vector<std::string>& notes) {
  std::string all;
  for (const auto& note : notes) all += (all.empty() ? "" : "; ") + note;
  return all;
}

// The share of a piece's points (seen_at) that its outline holds, when
// under kMinCoveredShare: its part of the face is not bounded by straight
// fold lines.
std::optional<std::string> uncovered_note(const std::string& name,
                                          const std::vector<Eigen::Vector2d>& outline,
                                          const std::vector<Eigen::Vector2d>& seen_at) {
  std::size_t in = 0, all = 0;
  for (const auto& q : seen_at)
    if (q.allFinite()) {
      ++all;
      in += inside_polygon(outline, q);
    }
  if (all > 0 && static_cast<double>(in) < kMinCoveredShare * static_cast<double>(all))
    return "piece " + name + "'s outline holds " +
           format_fixed(100.0 * static_cast<double>(in) / static_cast<double>(all), 0) +
           " % of its points: its part of the face is not bounded by straight "
           "fold lines";
  return std::nullopt;
}

}  // namespace

namespace outline_phases {

Labelled label_points(const photogrammetry::SurfaceMesh& sub,
                      const std::vector<geometry::Plane>& planes, std::vector<int>& label) {
  Labelled out;
  out.points.resize(planes.size());
  out.area.assign(planes.size(), 0.0);
  label.assign(sub.size(), 0);
  for (std::size_t v = 0; v < sub.size(); ++v) {
    double best = 1e300;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const double d = std::abs(planes[k].signed_distance(sub.vertices[v]));
      if (d < best) {
        best = d;
        label[v] = static_cast<int>(k);
      }
    }
    out.points[label[v]].push_back(sub.vertices[v]);
  }
  for (const auto& t : sub.triangles) {
    const int a = label[t[0]], b = label[t[1]], c = label[t[2]];
    const int k = (b == c) ? b : a;
    out.area[k] += 0.5 * (sub.vertices[t[1]] - sub.vertices[t[0]])
                             .cross(sub.vertices[t[2]] - sub.vertices[t[0]])
                             .norm();
  }
  return out;
}

// The point precision the pieces are judged with: the stated one, or finer
// where the analysis needs it (the planarity gate then is half the snap
// tolerance). A model's predicted sigma_Z (14 mm for the demo's fast preset)
// would let a 12-degree fold two metres wide pass as one plane whose edges
// and fold lie 5-6 cm off it, beyond the snap tolerance.
MeasureSettings piece_settings(const MeasureSettings& measured, const FacetOptions& options,
                               double snap_tolerance) {
  MeasureSettings settings = measured;
  settings.point_sigma =
      std::min(measured.point_sigma, 0.5 * snap_tolerance / options.planarity_in_sigmas);
  return settings;
}

photogrammetry::SurfaceMesh outline_submesh(const MeshPicker& picker, const PhotoView& view,
                                            const std::vector<Eigen::Vector2d>& polygon) {
  const auto& mesh = picker.mesh();
  photogrammetry::SurfaceMesh sub;
  std::vector<int> local(mesh.size(), -1);
  for (const int v : picker.vertices_inside(view, polygon)) {
    local[v] = static_cast<int>(sub.vertices.size());
    sub.vertices.push_back(mesh.vertices[v]);
  }
  for (const auto& t : mesh.triangles)
    if (local[t[0]] >= 0 && local[t[1]] >= 0 && local[t[2]] >= 0)
      sub.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
  return sub;
}

// Two facets of one wall join and two walls of a fold (a few degrees apart
// but centimetres off each other's plane a metre from the fold) do not.
std::vector<geometry::Plane> facet_planes(const photogrammetry::SurfaceMesh& sub,
                                          const std::vector<Facet>& facets,
                                          const FacetOptions& options, double gate,
                                          std::size_t max_planes) {
  std::vector<geometry::Plane> planes;
  std::vector<Eigen::Vector3d> group_normals;
  std::vector<char> seen(sub.size(), 0);
  for (const Facet& f : facets) {
    std::vector<Eigen::Vector3d> pts;
    for (const int t : f.mesh_triangles)
      for (const int v : sub.triangles[t])
        if (!seen[v]) {
          seen[v] = 1;
          pts.push_back(sub.vertices[v]);
        }
    for (const int t : f.mesh_triangles)
      for (const int v : sub.triangles[t]) seen[v] = 0;
    bool joined = false;
    for (std::size_t g = 0; g < planes.size() && !joined; ++g) {
      if (outline_angle_deg(f.plane.fit.normal, group_normals[g]) > options.angle_tolerance_deg)
        continue;
      double ss = 0;
      for (const auto& p : pts) ss += std::pow(planes[g].signed_distance(p), 2);
      joined = std::sqrt(ss / static_cast<double>(pts.size())) <= gate;
    }
    if (!joined && planes.size() < max_planes) {
      planes.push_back(f.plane.fit.plane());
      group_normals.push_back(f.plane.fit.normal);
    }
  }
  return planes;
}

SettledPlanes settle_planes(const photogrammetry::SurfaceMesh& sub,
                            std::vector<geometry::Plane> planes, const MeasureSettings& measured,
                            const FacetOptions& options, double gate) {
  SettledPlanes out;
  for (int pass = 0;; ++pass) {
    out.parts = label_points(sub, planes, out.label);
    out.estimates.assign(planes.size(), PlaneEstimate{});
    for (std::size_t k = 0; k < planes.size(); ++k)
      if (out.parts.points[k].size() >= 3) {
        out.estimates[k] = plane_of_points(out.parts.points[k], measured);
        if (pass < kRefinePasses) planes[k] = out.estimates[k].fit.plane();
      }
    if (pass < kRefinePasses) continue;
    // The worst part: the smallest under the area limit, else the roughest
    // over the planarity limit.
    std::optional<std::size_t> worst;
    std::string why;
    for (std::size_t k = 0; k < planes.size(); ++k)
      if (out.parts.area[k] < options.min_area_m2 &&
          (!worst || out.parts.area[k] < out.parts.area[*worst])) {
        worst = k;
        why = "too small to be a flat piece (under " + outline_m2(options.min_area_m2) + ")";
      }
    if (!worst)
      for (std::size_t k = 0; k < planes.size(); ++k) {
        const double rms = out.estimates[k].fit.rms_off_plane();
        if (rms > gate && (!worst || rms > out.estimates[*worst].fit.rms_off_plane())) {
          worst = k;
          why = "too rough to be one plane (RMS " + outline_mm(rms) + ", more than the " +
                outline_mm(gate) + " the 3D image's precision allows)";
        }
      }
    if (!worst) break;
    out.notes.push_back("a part of " + outline_m2(out.parts.area[*worst]) + " (" +
                        attitude(planes[*worst]) + ") is " + why +
                        ": its area goes to the pieces around it");
    planes.erase(planes.begin() + static_cast<std::ptrdiff_t>(*worst));
    if (planes.size() < 2) {
      out.too_few = true;
      break;
    }
    pass = kRefinePasses - 2;  // relabel and refit once more without it
  }
  out.planes = std::move(planes);
  return out;
}

std::vector<std::vector<char>> touching_pieces(const photogrammetry::SurfaceMesh& sub,
                                               const std::vector<int>& label, std::size_t n) {
  std::vector<std::vector<char>> touch(n, std::vector<char>(n, 0));
  for (const auto& t : sub.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = label[t[i]], b = label[t[(i + 1) % 3]];
      if (a != b) touch[a][b] = touch[b][a] = 1;
    }
  return touch;
}

FoldOutlines fold_outlines(const PhotoView& view, const std::vector<Eigen::Vector2d>& polygon,
                           const std::vector<geometry::Plane>& planes,
                           const std::vector<PlaneEstimate>& estimates,
                           const std::vector<std::vector<char>>& touch,
                           const std::vector<std::vector<Eigen::Vector2d>>& seen_at) {
  const std::size_t n = planes.size();
  FoldOutlines out;
  std::vector<std::vector<Eigen::Vector2d>>& outline = out.outline;
  outline.assign(n, polygon);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!touch[i][j]) continue;
      const Eigen::Vector3d ni = planes[i].normal, nj = planes[j].normal;
      const Eigen::Vector3d dir = ni.cross(nj);
      const std::string pair = "pieces " + attitude(planes[i]) + " and " + attitude(planes[j]);
      if (dir.norm() < std::sin(deg_to_rad(kParallelDeg))) {
        out.notes.push_back(pair + " are parallel (a step in the face, not a fold): no edge " +
                            "between them is drawn, their outlines overlap");
        continue;
      }
      Eigen::Matrix<double, 2, 3> A;
      A.row(0) = ni;
      A.row(1) = nj;
      Eigen::Vector3d p0 = A.transpose() * (A * A.transpose()).inverse() *
                           Eigen::Vector2d(planes[i].offset, planes[j].offset);
      const Eigen::Vector3d u = dir.normalized();
      const Eigen::Vector3d c = 0.5 * (estimates[i].fit.centroid + estimates[j].fit.centroid);
      p0 += u * u.dot(c - p0);
      // Half a metre each way: far enough that the pixel line is well
      // defined, near enough to stay in front of the camera.
      const auto ends = project_to_view(view, {p0 - 0.5 * u, p0 + 0.5 * u});
      if (!ends[0].allFinite() || !ends[1].allFinite() || (ends[1] - ends[0]).norm() < 1e-6) {
        out.notes.push_back(
            pair + " meet along a line the photograph does not see: " + "their outlines overlap");
        continue;
      }
      const Eigen::Vector2d a = ends[0], d = ends[1] - ends[0];
      auto side = [&](std::size_t k) {
        std::ptrdiff_t s = 0;
        for (const auto& q : seen_at[k])
          if (q.allFinite()) s += cross2(d, q - a) >= 0 ? 1 : -1;
        return s >= 0 ? 1 : -1;
      };
      const int si = side(i), sj = side(j);
      if (si == sj) {
        out.notes.push_back(pair + " lie on one side of the line their planes meet on (a step " +
                            "in the face, not a fold): their outlines overlap");
        continue;
      }
      outline[i] = clip_polygon(outline[i], a, static_cast<double>(si) * d);
      outline[j] = clip_polygon(outline[j], a, static_cast<double>(sj) * d);
    }
  return out;
}

AreaMeasurement measure_piece(const PhotoView& view, const std::string& name,
                              const std::vector<Eigen::Vector2d>& outline,
                              const geometry::Plane& plane, const PlaneEstimate& estimate,
                              std::size_t vertices, double area, const MeasureSettings& measured,
                              const std::string& where) {
  AreaMeasurement a;
  a.id = name;
  for (const auto& q : outline) {
    const Ray ray = ray_through_pixel(view, q, where);
    const double den = plane.normal.dot(ray.direction);
    const double t =
        std::abs(den) < 1e-12 ? -1 : (plane.offset - plane.normal.dot(ray.origin)) / den;
    if (!(t > 0)) continue;  // a ray along or away from the plane: no corner
    a.outline.push_back({view.name, q});
    a.outline_points.push_back(ray.origin + t * ray.direction);
  }
  a.vertices = vertices;
  a.area = area;
  a.plane = estimate;
  judge_area_plane(a.plane, measured);
  return a;
}

void measure_pieces(const PhotoView& view, const std::string& id,
                    const std::vector<geometry::Plane>& planes,
                    const std::vector<PlaneEstimate>& estimates, const Labelled& parts,
                    const std::vector<std::vector<Eigen::Vector2d>>& outline,
                    const std::vector<std::vector<Eigen::Vector2d>>& seen_at,
                    const MeasureSettings& measured, const std::string& where, OutlinePieces& out) {
  const std::size_t n = planes.size();
  // Largest first: the labels a, b, ... in that order.
  std::vector<std::size_t> order(planes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return parts.area[a] > parts.area[b]; });
  char letter = 'a';
  for (const std::size_t k : order) {
    const std::string name = id + letter++;
    if (outline[k].size() < 3 || std::abs(polygon_area(outline[k])) < kMinOutlinePx2) {
      out.notes.push_back("piece " + name + " (" + outline_m2(parts.area[k]) + ", " +
                          attitude(planes[k]) + ") has no outline of its own: left out");
      --letter;
      continue;
    }
    AreaMeasurement a = measure_piece(view, name, outline[k], planes[k], estimates[k],
                                      parts.points[k].size(), parts.area[k], measured, where);
    if (n > 2) {
      if (auto note = uncovered_note(name, outline[k], seen_at[k])) out.notes.push_back(*note);
    }
    wind_toward_camera(a, view);
    out.pieces.push_back(std::move(a));
  }
}

}  // namespace outline_phases

OutlinePieces split_outline(const MeshPicker& picker, const PhotoView& view, const std::string& id,
                            const std::vector<Eigen::Vector2d>& polygon,
                            const MeasureSettings& measured, const FacetOptions& options,
                            double snap_tolerance, const std::string& where) {
  using namespace outline_phases;
  check_outline(polygon, where);
  check_facet_options(options);
  if (!(snap_tolerance > 0))
    throw InputError(where, "the snap tolerance must be a positive length (m), got " +
                                std::to_string(snap_tolerance));
  const MeasureSettings settings = piece_settings(measured, options, snap_tolerance);
  OutlinePieces out;
  AreaMeasurement whole = measure_area(picker, view, id, polygon, measured, where);
  // The planarity test of measuring, with the facet finder's limit: a face
  // within it is one plane to the precision of the 3D image.
  const std::string bent =
      planarity_problem(whole.plane, settings, options.planarity_in_sigmas, "the outlined face");
  auto one_piece = [&](const std::string& why) {
    if (!why.empty())
      out.notes.push_back("the face outline stays one piece, " + why + "; " +
                          bent.substr(bent.find(':') + 2));
    wind_toward_camera(whole, view);
    out.pieces.push_back(std::move(whole));
    return out;
  };
  if (bent.empty()) return one_piece("");

  // The facets inside the outline, grouped by the plane they lie in.
  const photogrammetry::SurfaceMesh sub = outline_submesh(picker, view, polygon);
  NoProgress quiet;
  const FacetSearch found = find_facets(sub, settings, options, quiet);
  const double gate = options.planarity_in_sigmas * settings.point_sigma;
  std::vector<geometry::Plane> planes = facet_planes(sub, found.facets, options, gate, kMaxPieces);
  if (planes.size() < 2)
    return one_piece(planes.empty()
                         ? "no flat part was found in it (" +
                               (found.notes.empty() ? std::string("facets") : found.notes.front()) +
                               ")"
                         : "one flat part was found in it, and the rest is no plane");

  // Every point to its nearest plane, the planes refitted to their points;
  // then each piece judged as a plane: a part too small or too rough is
  // said and its points go to the other planes.
  SettledPlanes settled = settle_planes(sub, std::move(planes), measured, options, gate);
  if (settled.too_few)
    return one_piece("no two flat pieces remain (" + joined(settled.notes) + ")");
  out.notes = std::move(settled.notes);
  planes = std::move(settled.planes);
  const std::vector<PlaneEstimate>& estimates = settled.estimates;
  const Labelled& parts = settled.parts;

  // The planes the pieces are measured with: their outlines lie in them.
  for (std::size_t k = 0; k < planes.size(); ++k) planes[k] = estimates[k].fit.plane();

  // Which pieces touch, each piece's points seen in the photograph, and
  // each piece's outline cut along the fold lines.
  const std::size_t n = planes.size();
  const auto touch = touching_pieces(sub, settled.label, n);
  std::vector<std::vector<Eigen::Vector2d>> seen_at(n);
  for (std::size_t k = 0; k < n; ++k) seen_at[k] = project_to_view(view, parts.points[k]);
  FoldOutlines folds = fold_outlines(view, polygon, planes, estimates, touch, seen_at);
  out.notes.insert(out.notes.end(), folds.notes.begin(), folds.notes.end());
  const auto& outline = folds.outline;

  // The pieces, each measured as an area, largest first.
  measure_pieces(view, id, planes, estimates, parts, outline, seen_at, measured, where, out);
  if (out.pieces.size() < 2) {
    const std::string notes = joined(out.notes);
    out.notes.clear();
    out.pieces.clear();
    return one_piece("its pieces have no outlines of their own (" + notes + ")");
  }
  return out;
}

}  // namespace rockface::measure
