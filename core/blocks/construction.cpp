#include "core/blocks/construction.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include <Eigen/Dense>

#include "core/blocks/convex_clipping.h"
#include "core/blocks/tolerances.h"
#include "core/common/error.h"
#include "core/geometry/cone.h"
#include "core/geometry/tolerances.h"

namespace rockface::blocks {

namespace {

// Planes whose least-squares point lies within this (x size) of each meet
// there to rounding (~1e-15 relative per operation, a few operations): a
// survey's snap leaves them as given, so exact input gives the block it
// always gave.
constexpr double kMeetToRoundingRel = 1e-12;

// Determinant of three unit normals below this: the planes share a direction
// to working precision and meet in no single point.
constexpr double kSingularTriple = 1e-15;

// An in-plane basis (u, w) with u x w = n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_basis(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = helper.cross(n).normalized();
  return {u, n.cross(u)};
}

// All feasible intersections of three planes, with a feasibility tolerance
// relative to the size of the point set.
std::vector<Eigen::Vector3d> feasible_corners(const std::vector<Eigen::Vector3d>& n,
                                              const std::vector<double>& b,
                                              const Eigen::Vector3d& ref, double scale_hint) {
  const int m = static_cast<int>(n.size());
  std::vector<Eigen::Vector3d> all;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        Eigen::Matrix3d M;
        M.row(0) = n[i];
        M.row(1) = n[j];
        M.row(2) = n[k];
        if (!(std::abs(M.determinant()) > kSingularTriple)) continue;
        const Eigen::Vector3d x = M.colPivHouseholderQr().solve(Eigen::Vector3d(b[i], b[j], b[k]));
        if (x.allFinite()) all.push_back(x);
      }
  auto violation = [&](const Eigen::Vector3d& x) {
    double v = 0;
    for (int l = 0; l < m; ++l) v = std::max(v, b[l] - n[l].dot(x));
    return v;
  };
  // First pass: tolerance relative to the point's distance from the
  // reference (rounding of the solve grows with |x|), giving the block size.
  std::vector<Eigen::Vector3d> first;
  for (const auto& x : all)
    if (violation(x) <= kOnPlaneRel * std::max((x - ref).norm(), scale_hint)) first.push_back(x);
  if (first.empty()) return first;
  Eigen::Vector3d lo = first[0], hi = first[0];
  for (const auto& x : first) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double size = std::max((hi - lo).norm(), scale_hint);
  std::vector<Eigen::Vector3d> out;
  for (const auto& x : all)
    if (violation(x) <= kOnPlaneRel * size) out.push_back(x);
  return out;
}

// Each corner of the clipped solid at the mean of the intersections of
// three of its planes that lie within `merge` of it (the exact corner where
// they meet; for four or more planes through one point, the mean of their
// triple points), or where the cuts left it when none does (planes that
// miss each other by more than that, merged into one corner).
std::vector<Eigen::Vector3d> corners_on_their_planes(const ClippedSolid& solid,
                                                     const std::vector<Eigen::Vector3d>& n,
                                                     const std::vector<double>& b, double merge) {
  std::vector<std::vector<int>> planes_at(solid.vertices.size());
  for (const ClippedFace& f : solid.faces)
    for (int v : f.loop) planes_at[v].push_back(f.plane);
  std::vector<Eigen::Vector3d> out = solid.vertices;
  for (size_t v = 0; v < out.size(); ++v) {
    auto& p = planes_at[v];
    std::sort(p.begin(), p.end());
    const int k = static_cast<int>(p.size());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j)
        for (int l = j + 1; l < k; ++l) {
          Eigen::Matrix3d M;
          M.row(0) = n[p[i]];
          M.row(1) = n[p[j]];
          M.row(2) = n[p[l]];
          if (!(std::abs(M.determinant()) > kSingularTriple)) continue;
          const Eigen::Vector3d x =
              M.colPivHouseholderQr().solve(Eigen::Vector3d(b[p[i]], b[p[j]], b[p[l]]));
          if (x.allFinite() && (x - solid.vertices[v]).norm() <= merge) {
            sum += x;
            ++count;
          }
        }
    if (count > 0) out[v] = sum / count;
  }
  return out;
}

// Planes that pass within `snap` of a corner where four or more of them
// meet, moved (offsets b only) to pass through the least-squares point of
// that group, when none moves by more than `snap` and one by more than
// `rounding`. corners: the feasible
// intersections of three planes. A plane already moved for one corner is
// not moved for another (the second group keeps its planes): each move
// stays within the precision. Returns the planes moved and the largest move.
std::pair<std::vector<int>, double> snap_shared_corners(const std::vector<Eigen::Vector3d>& n,
                                                        std::vector<double>& b,
                                                        const std::vector<Eigen::Vector3d>& corners,
                                                        double snap, double rounding) {
  const int m = static_cast<int>(n.size());
  std::vector<bool> moved(m, false);
  std::vector<std::vector<int>> groups;
  for (const auto& x : corners) {
    std::vector<int> g;
    for (int i = 0; i < m; ++i)
      if (std::abs(n[i].dot(x) - b[i]) <= snap) g.push_back(i);
    if (g.size() >= 4 && std::find(groups.begin(), groups.end(), g) == groups.end())
      groups.push_back(std::move(g));
  }
  // The largest group first: with five or six planes through a corner,
  // four of them may pass within `snap` of one of its triple points and all
  // of them of another; taking the four first left the others unmoved.
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& x, const auto& y) { return x.size() > y.size(); });
  std::vector<int> out;
  double largest = 0;
  for (const auto& g : groups) {
    if (std::any_of(g.begin(), g.end(), [&](int i) { return moved[i]; })) continue;
    const int k = static_cast<int>(g.size());
    Eigen::MatrixXd A(k, 3);
    Eigen::VectorXd rhs(k);
    for (int r = 0; r < k; ++r) {
      A.row(r) = n[g[r]].transpose();
      rhs[r] = b[g[r]];
    }
    const Eigen::Vector3d y = A.colPivHouseholderQr().solve(rhs);
    if (!y.allFinite()) continue;
    double worst = 0;
    for (int i : g) worst = std::max(worst, std::abs(n[i].dot(y) - b[i]));
    // Planes that meet to rounding are one corner already (the clipping's
    // merge): they keep their places, and the block stays what it was.
    if (worst > snap || worst <= rounding) continue;
    for (int i : g) {
      b[i] = n[i].dot(y);
      moved[i] = true;
      out.push_back(i);
    }
    largest = std::max(largest, worst);
  }
  std::sort(out.begin(), out.end());
  return {out, largest};
}

// A face's loop turned to start at its corner of least angle about its
// mean, in the plane basis of its outward normal.
std::vector<int> loop_from_least_angle(const std::vector<int>& loop,
                                       const std::vector<Eigen::Vector3d>& corners,
                                       const Eigen::Vector3d& outward) {
  const auto [u, w] = plane_basis(outward);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int c : loop) mean += corners[c];
  mean /= static_cast<double>(loop.size());
  size_t first = 0;
  double least = INFINITY;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector3d r = corners[loop[k]] - mean;
    const double a = std::atan2(r.dot(w), r.dot(u));
    if (a < least) {
      least = a;
      first = k;
    }
  }
  std::vector<int> out(loop.begin() + static_cast<std::ptrdiff_t>(first), loop.end());
  out.insert(out.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(first));
  return out;
}

}  // namespace

ConvexConstruction build_convex_block(const std::string& block_id,
                                      const std::vector<HalfSpaceInput>& halfspaces,
                                      const Eigen::Vector3d& datum, double survey_precision) {
  const std::string where = "block " + block_id;
  ConvexConstruction out;
  const int m = static_cast<int>(halfspaces.size());
  std::vector<Eigen::Vector3d> n(m);
  std::vector<double> b(m);
  for (int i = 0; i < m; ++i) {
    const auto& h = halfspaces[i];
    const double len = h.plane.normal.norm();
    if (!(len > 0) || !std::isfinite(len) || !std::isfinite(h.plane.offset))
      throw InputError(where, "plane " + h.name + " has a zero or non-finite normal");
    if (h.side == geometry::HalfSpace::NotInvolved)
      throw InputError(where, "plane " + h.name + " has no side (code 2) but is listed");
    // Inward form n . x >= b.
    const double s = geometry::side_sign(h.side);
    n[i] = s * h.plane.normal / len;
    b[i] = s * h.plane.offset / len;
  }

  // Recession cone: the directions in which the intersection never ends.
  if (m > 0) {
    const geometry::ConeMargin rec = geometry::Cone(n).margin();
    out.recession_margin = rec.angle;
    out.open_direction = rec.direction;
  } else {
    out.recession_margin = std::numbers::pi / 2;
  }

  // A reference point near the planes (least squares) and their spread give
  // the scale for the first feasibility pass.
  Eigen::Vector3d ref = Eigen::Vector3d::Zero();
  double spread = 0;
  if (m > 0) {
    Eigen::MatrixXd A(m, 3);
    Eigen::VectorXd rhs(m);
    for (int i = 0; i < m; ++i) {
      A.row(i) = n[i].transpose();
      rhs[i] = b[i];
    }
    ref = A.completeOrthogonalDecomposition().solve(rhs);
    for (int i = 0; i < m; ++i) spread = std::max(spread, std::abs(n[i].dot(ref) - b[i]));
  }

  if (out.recession_margin >= -geometry::kAngleEpsRad) {
    // Unbounded unless empty: look for a common point inside a large box
    // around the reference point (the box only closes the region off).
    out.outcome = ConvexOutcome::Unbounded;
    std::vector<Eigen::Vector3d> nb = n;
    std::vector<double> bb = b;
    const double R = 1e3 * std::max(spread, 1e-3 * std::max(1.0, ref.norm()));
    for (int a = 0; a < 3; ++a)
      for (double s : {1.0, -1.0}) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[a] = s;
        nb.push_back(e);
        bb.push_back(s * ref[a] - R);
      }
    const auto corners = feasible_corners(nb, bb, ref, R);
    // A region with volume has corners spanning three dimensions.
    bool has_volume = false;
    if (corners.size() >= 4) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (const auto& x : corners) c += x;
      c /= static_cast<double>(corners.size());
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (const auto& x : corners) cov += (x - c) * (x - c).transpose();
      const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
      has_volume = ev[0] > 1e-18 * ev[2];
    }
    if (!has_volume) out.outcome = ConvexOutcome::Empty;
    return out;
  }

  std::vector<Eigen::Vector3d> raw = feasible_corners(n, b, ref, 0.0);
  if (raw.size() < 4) {
    out.outcome = ConvexOutcome::Empty;
    return out;
  }
  auto extent = [&](Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
    lo = hi = raw[0];
    for (const auto& x : raw) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    return (hi - lo).norm();
  };
  Eigen::Vector3d lo, hi;
  double size = extent(lo, hi);
  if (!(size > 0)) {
    out.outcome = ConvexOutcome::Empty;
    return out;
  }
  // Planes through one surveyed corner, known to the survey's precision,
  // are taken through one point: their corners then are one vertex, not
  // short edges whose number and lengths follow the survey's rounding.
  const double snap = std::min(survey_precision, kSurveySnapRel * size);
  if (snap > kVertexMergeRel * size) {
    std::tie(out.snapped, out.snap_move) =
        snap_shared_corners(n, b, raw, snap, kMeetToRoundingRel * size);
    if (!out.snapped.empty()) {
      raw = feasible_corners(n, b, ref, 0.0);
      if (raw.size() < 4) {
        out.outcome = ConvexOutcome::Empty;
        return out;
      }
      size = extent(lo, hi);
    }
  }

  // The solid itself: the box around the feasible corners cut by every
  // half-space in turn (core/blocks/convex_clipping.h). One inside / on /
  // outside decision per corner and plane keeps the faces consistent however
  // close the corners come; corners within kVertexMergeRel x size are one.
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(0.25 * size);
  const std::optional<ClippedSolid> solid =
      clip_box(lo - pad, hi + pad, n, b, kVertexMergeRel * size, kVertexMergeRel * size);
  if (!solid)
    throw Error(where +
                ": the half-spaces did not give a consistent polyhedron (a cut through corners "
                "within the tolerance of each other does not close)");
  if (solid->faces.size() < 4) {
    out.outcome = ConvexOutcome::Empty;
    return out;
  }
  for (const ClippedFace& f : solid->faces)
    if (f.plane < 0)
      throw Error(where +
                  ": the half-spaces did not give a consistent polyhedron (the box around its "
                  "corners keeps a face)");
  const std::vector<Eigen::Vector3d> corners =
      corners_on_their_planes(*solid, n, b, kVertexMergeRel * size);

  // Faces in the order of their planes, each loop from the corner of least
  // angle about the face's mean, corners numbered in order of first use:
  // the numbering reports and rotation checks have always had.
  std::vector<BlockPlane> planes;
  std::vector<FaceLoop> loops;
  std::vector<bool> bounds_face(m, false);
  std::vector<int> used_corner(corners.size(), -1);
  std::vector<Eigen::Vector3d> vertices;
  for (const ClippedFace& f : solid->faces) {
    const int i = f.plane;
    bounds_face[i] = true;
    BlockPlane bp;
    bp.index = halfspaces[i].index;
    bp.name = halfspaces[i].name;
    bp.kind = halfspaces[i].kind;
    const double len = halfspaces[i].plane.normal.norm();
    bp.plane.normal = halfspaces[i].plane.normal / len;
    bp.plane.offset = halfspaces[i].plane.offset / len;
    // A plane snapped through a shared corner lies where it was moved to
    // (b is the inward offset: the side's sign turns it back).
    if (std::binary_search(out.snapped.begin(), out.snapped.end(), i))
      bp.plane.offset = geometry::side_sign(halfspaces[i].side) * b[i];
    bp.side = halfspaces[i].side;
    FaceLoop fl;
    fl.plane = static_cast<int>(planes.size());
    for (int c : loop_from_least_angle(f.loop, corners, -n[i])) {
      if (used_corner[c] < 0) {
        used_corner[c] = static_cast<int>(vertices.size());
        vertices.push_back(corners[c]);
      }
      fl.loop.push_back(used_corner[c]);
    }
    loops.push_back(std::move(fl));
    planes.push_back(bp);
  }
  for (int i = 0; i < m; ++i)
    if (!bounds_face[i]) out.redundant.push_back(i);
  try {
    // Corners were found within kOnPlaneRel of their planes.
    out.polyhedron = Polyhedron::assemble(block_id, datum, std::move(planes), std::move(vertices),
                                          loops, 4 * kOnPlaneRel * size);
  } catch (const InputError& e) {
    throw Error(where + ": the half-spaces did not give a consistent polyhedron (" + e.reason() +
                ")");
  }
  out.outcome = ConvexOutcome::Bounded;
  return out;
}

Polyhedron build_block_from_faces(const std::string& block_id,
                                  std::vector<Eigen::Vector3d> vertices,
                                  const std::vector<FaceInput>& faces, const Eigen::Vector3d& datum,
                                  double planarity_tolerance) {
  const std::string where = "block " + block_id;
  const int nv = static_cast<int>(vertices.size());
  auto name_of = [&](int f) {
    std::string s = "face " + std::to_string(f);
    if (!faces[f].name.empty()) s += " (" + faces[f].name + ")";
    return s;
  };
  // Indices first: the plane fit needs valid ones.
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const auto& loop = faces[f].loop;
    for (size_t k = 0; k < loop.size(); ++k)
      if (loop[k] < 0 || loop[k] >= nv)
        throw InputError(where, name_of(f) + ": loop[" + std::to_string(k) + "] = vertex " +
                                    std::to_string(loop[k]) + " is out of range (" +
                                    std::to_string(nv) + " vertices)");
    if (loop.size() < 3) throw InputError(where, name_of(f) + ": a loop needs at least 3 vertices");
  }

  // Fit each face's plane (Newell's vector area: exact for a planar polygon
  // of any shape) and its side.
  struct Fit {
    Eigen::Vector3d area2;  // twice the vector area, along the outward normal
    Eigen::Vector3d mean;
    geometry::HalfSpace side;
    Eigen::Vector3d up;  // upward normal of the plane
  };
  std::vector<Fit> fits(faces.size());
  double size = 0;
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (const auto& x : vertices) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    if (nv > 0) size = (hi - lo).norm();
  }
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const auto& loop = faces[f].loop;
    Fit fit;
    fit.mean = Eigen::Vector3d::Zero();
    for (int v : loop) fit.mean += vertices[v];
    fit.mean /= static_cast<double>(loop.size());
    fit.area2 = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < loop.size(); ++k)
      fit.area2 +=
          (vertices[loop[k]] - fit.mean).cross(vertices[loop[(k + 1) % loop.size()]] - fit.mean);
    if (!(fit.area2.norm() > 2 * kFaceAreaRel * size * size))
      throw InputError(where, name_of(f) + " has no area (its vertices are collinear or coincide)");
    const Eigen::Vector3d outward = fit.area2.normalized();
    Eigen::Vector3d up;
    if (faces[f].reference_normal && faces[f].reference_normal->norm() > 0) {
      up = faces[f].reference_normal->normalized();
    } else {
      up = geometry::plane_normal(geometry::plane_orientation(outward));
    }
    fit.side = outward.dot(up) < 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
    fit.up = outward.dot(up) < 0 ? Eigen::Vector3d(-outward) : outward;
    fits[f] = fit;
  }

  // One BlockPlane per (named plane, side); unnamed faces get their own.
  std::vector<BlockPlane> planes;
  std::vector<FaceLoop> loops;
  std::map<std::tuple<int, std::string, int>, int> plane_of;
  std::vector<Eigen::Vector3d> plane_area2;
  std::vector<std::vector<int>> plane_faces;
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const bool named = faces[f].index >= 0 || !faces[f].name.empty();
    const auto key = std::make_tuple(faces[f].index, named ? faces[f].name : std::to_string(f),
                                     static_cast<int>(fits[f].side));
    auto it = plane_of.find(key);
    int p;
    if (it == plane_of.end() || !named) {
      p = static_cast<int>(planes.size());
      plane_of[key] = p;
      BlockPlane bp;
      bp.index = faces[f].index;
      bp.name = faces[f].name;
      bp.kind = faces[f].kind;
      bp.side = fits[f].side;
      planes.push_back(bp);
      plane_area2.push_back(Eigen::Vector3d::Zero());
      plane_faces.push_back({});
    } else {
      p = it->second;
    }
    plane_area2[p] += fits[f].area2;
    plane_faces[p].push_back(f);
    loops.push_back({p, faces[f].loop});
  }
  for (size_t p = 0; p < planes.size(); ++p) {
    // Normal: the summed vector area; offset: area-weighted mean point.
    Eigen::Vector3d outward = plane_area2[p].normalized();
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double w = 0;
    for (int f : plane_faces[p]) {
      const double a = fits[f].area2.norm();
      point += a * fits[f].mean;
      w += a;
    }
    point /= w;
    const Eigen::Vector3d up =
        planes[p].side == geometry::HalfSpace::Upper ? Eigen::Vector3d(-outward) : outward;
    planes[p].plane.normal = up;
    planes[p].plane.offset = up.dot(point);
  }
  return Polyhedron::assemble(block_id, datum, std::move(planes), std::move(vertices), loops,
                              planarity_tolerance);
}

}  // namespace rockface::blocks
