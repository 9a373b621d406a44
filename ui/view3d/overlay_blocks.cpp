#include "ui/view3d/overlay_blocks.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>

#include "ui/app/app_state.h"

namespace rockface::ui {

namespace {

// A corner is on a patch within 1 cm: the block report gives survey
// coordinates to the millimetre, and the patches are planar within the
// analysis' snapping tolerance (its default is 1 cm).
constexpr double kOnPatchM = 0.01;

bool inside_patch(const SurfacePatchPlane& patch, const Eigen::Vector3d& p) {
  // In the patch plane, with the same slack as the plane test.
  const Eigen::Vector3d e1 = patch.normal.unitOrthogonal(), e2 = patch.normal.cross(e1);
  std::vector<Eigen::Vector2d> polygon;
  for (const auto& q : patch.polygon)
    polygon.emplace_back((q - patch.point).dot(e1), (q - patch.point).dot(e2));
  const Eigen::Vector2d x((p - patch.point).dot(e1), (p - patch.point).dot(e2));
  if (inside_polygon(polygon, x)) return true;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double t =
        std::clamp((x - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-18), 0.0, 1.0);
    if ((a + t * (b - a) - x).norm() <= kOnPatchM) return true;
  }
  return false;
}

// A footprint's straight edge between corners on two patches of the face
// leaves the surface by up to half its length times sin(bend / 2): 0.05
// allows bends between patches up to 11 degrees (a tunnel face's facets; a crown or wall
// meets the face at a larger angle, and the corners there split the edge).
constexpr double kEdgeSag = 0.05;

std::vector<double> key_of(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> key;
  for (const auto& p : points) key.insert(key.end(), {p.x(), p.y(), p.z()});
  return key;
}

std::vector<ImVec2> screen_hull(const std::vector<ImVec2>& points) {
  std::vector<cv::Point2f> in;
  for (const auto& p : points) in.emplace_back(p.x, p.y);
  std::vector<ImVec2> out;
  if (in.size() < 3) return out;
  std::vector<cv::Point2f> hull;
  cv::convexHull(in, hull);
  for (const auto& p : hull) out.emplace_back(p.x, p.y);
  return out;
}

}  // namespace

std::vector<SurfacePatchPlane> surface_patches(
    const std::vector<storage::Measurement>& measurements) {
  std::vector<SurfacePatchPlane> out;
  for (const auto& m : measurements) {
    if (m.kind != storage::Measurement::Kind::area || m.points.size() < 3) continue;
    SurfacePatchPlane p;
    p.polygon = m.points;
    for (const auto& x : m.points) p.point += x;
    p.point /= static_cast<double>(m.points.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& x : m.points) scatter += (x - p.point) * (x - p.point).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    p.normal = solver.eigenvectors().col(0).normalized();
    if (p.normal.allFinite()) out.push_back(std::move(p));
  }
  return out;
}

std::vector<Eigen::Vector3d> block_footprint(const std::vector<Eigen::Vector3d>& vertices,
                                             bool surface_loop,
                                             const std::vector<SurfacePatchPlane>& patches,
                                             const SurfaceDrape& drape) {
  if (surface_loop) return vertices.size() >= 3 ? vertices : std::vector<Eigen::Vector3d>{};
  std::vector<Eigen::Vector3d> on;
  for (const auto& c : vertices) {
    bool surface = false;
    for (const auto& p : patches)
      if (std::abs((c - p.point).dot(p.normal)) <= kOnPatchM && inside_patch(p, c)) surface = true;
    // Without patches the drawn surface stands for the free surface.
    if (patches.empty()) surface = drape.project(c).has_value();
    if (surface) on.push_back(c);
  }
  if (on.size() < 3) return {};
  std::vector<cv::Point2f> plane;
  for (const auto& c : on) {
    const Eigen::Vector2d q = drape.to_plane(c);
    plane.emplace_back(static_cast<float>(q.x()), static_cast<float>(q.y()));
  }
  std::vector<int> hull;
  cv::convexHull(plane, hull);
  std::vector<Eigen::Vector3d> out;
  for (int i : hull) out.push_back(on[static_cast<std::size_t>(i)]);
  return out.size() >= 3 ? out : std::vector<Eigen::Vector3d>{};
}

BlockOnFace lay_block(const std::vector<Eigen::Vector3d>& footprint, const SurfaceDrape& drape) {
  BlockOnFace out;
  if (footprint.size() < 3) return out;
  for (const auto& p : footprint) out.footprint.push_back(drape.to_plane(p));
  const auto& surface = drape.surface();
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  double area = 0;
  for (const int t : drape.triangles_inside(out.footprint)) {
    const auto& tri = surface.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d &a = surface.vertices[tri[0]], &b = surface.vertices[tri[1]],
                          &c = surface.vertices[tri[2]];
    out.fill.insert(out.fill.end(), {a, b, c});
    const double at = 0.5 * (b - a).cross(c - a).norm();
    weighted += at * (a + b + c) / 3;
    area += at;
  }
  out.edges = drape.drape(footprint, true, kEdgeSag);
  out.open = drape.open_edges_inside(out.footprint);
  if (area > 0)
    if (const auto hit = drape.project(weighted / area)) out.centre = hit->point;
  // A thin footprint may hold no triangle centre: its outline's middle.
  if (!out.centre && !out.edges.empty())
    out.centre = out.edges.front()[out.edges.front().size() / 2];
  return out;
}

const BlockOnFace& BlockFaceCache::get(const std::vector<Eigen::Vector3d>& footprint,
                                       const SurfaceDrape& drape) {
  auto [it, made] = cache_.try_emplace(key_of(footprint));
  if (made) it->second = lay_block(footprint, drape);
  return it->second;
}

void add_block_to_overlay(OverlayScene& overlay, const std::string& label, const BlockOnFace& block,
                          ImU32 colour, bool finite, float width_px) {
  if (finite && !block.fill.empty())
    overlay.fills.push_back({"block " + label, block.fill, (colour & 0x00FFFFFFu) | (80u << 24)});
  // A region that is no block (not finite) is outlined thinner, not tinted.
  const float width = finite ? width_px : 0.6f * width_px;
  for (const auto& e : block.edges)
    overlay.lines.push_back({"block " + label + " edge", e, colour, width, false});
  for (const auto& e : block.open)
    overlay.lines.push_back({"block " + label + " open", e, colour, width, true});
}

namespace {

const BlockOnFace* laid(AppState& app, const BlockView& block) {
  const SurfaceDrape* drape = app.model_view.drape();
  if (!drape || !app.session) return nullptr;
  const auto footprint = block_footprint(block.vertices, block.vertices_are_surface_loop,
                                         surface_patches(app.session->measurements()), *drape);
  if (footprint.empty()) return nullptr;
  return &app.model_view.block_cache().get(footprint, *drape);
}

}  // namespace

void add_blocks_to_overlay(AppState& app) {
  if (!app.session) return;
  const auto& blocks = app.session->blocks();
  const float s = app.targets.scale();
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const BlockOnFace* b = laid(app, blocks[i]);
    if (!b) continue;
    const bool selected = app.blocks.selected_block && *app.blocks.selected_block == i;
    add_block_to_overlay(app.model_view.overlay(), blocks[i].label, *b,
                         verdict_colour(blocks[i].verdict), blocks[i].finite,
                         (selected ? 6.0f : 3.0f) * s);
  }
}

std::vector<ImVec2> block_outline_on_screen(AppState& app, const BlockView& block) {
  const BlockOnFace* b = laid(app, block);
  std::vector<ImVec2> points;
  if (!b) return points;
  for (const auto* lines : {&b->edges, &b->open})
    for (const auto& line : *lines)
      for (const auto& p : line)
        if (const auto q = app.model_view.to_screen(p)) points.push_back(*q);
  return screen_hull(points);
}

std::optional<ImVec2> block_marker_on_screen(AppState& app, const BlockView& block) {
  const BlockOnFace* b = laid(app, block);
  if (!b || !b->centre) return std::nullopt;
  return app.model_view.to_screen(*b->centre);
}

}  // namespace rockface::ui
