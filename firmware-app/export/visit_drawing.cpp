#include "firmware-app/export/visit_drawing.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/analysis/block_reading.h"
#include "core/analysis/block_verdict.h"
#include "core/blocks/construction.h"
#include "core/blocks/triangulation.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/orientation.h"
#include "firmware-app/export/block_hull.h"

namespace rockface::app {

namespace {

// AutoCAD Color Index by set, in the sets' order: red, yellow, green, cyan,
// blue, magenta, then round again; grey (8) for joints of no set.
int set_colour(const std::string& set_label, const std::vector<std::string>& order) {
  if (set_label.empty()) return 8;
  for (std::size_t i = 0; i < order.size(); ++i)
    if (order[i] == set_label) return 1 + static_cast<int>(i % 6);
  return 7;
}

int verdict_colour(analysis::BlockVerdict v) {
  switch (v) {
    case analysis::BlockVerdict::moves:
      return 1;
    case analysis::BlockVerdict::marginal:
      return 2;
    case analysis::BlockVerdict::holds:
      return 3;
    case analysis::BlockVerdict::keyed:
      return 4;
    case analysis::BlockVerdict::infinite:
      return 8;
  }
  return 7;
}

std::vector<std::string> set_order(const std::vector<storage::Joint>& joints) {
  std::vector<std::string> order;
  for (const auto& j : joints)
    if (!j.set_label.empty() && std::find(order.begin(), order.end(), j.set_label) == order.end())
      order.push_back(j.set_label);
  std::sort(order.begin(), order.end());
  return order;
}

// The disc's outline: 36 points, 10° apart, so its chords stray from the
// circle by 1 - cos 5° = 0.4 % of the radius: invisible at a drawing's scale.
std::vector<Eigen::Vector3d> disc_outline(const Eigen::Vector3d& centre,
                                          const Eigen::Vector3d& normal, double radius) {
  const Eigen::Vector3d a = normal.unitOrthogonal();
  const Eigen::Vector3d b = normal.cross(a).normalized();
  std::vector<Eigen::Vector3d> points;
  constexpr int kCorners = 36;
  for (int k = 0; k < kCorners; ++k) {
    const double t = 2 * M_PI * k / kCorners;
    points.push_back(centre + radius * (std::cos(t) * a + std::sin(t) * b));
  }
  return points;
}

// The design outline sampled every 2 cm of arc length (arcs of a 3 m radius
// then stray by 0.02² / (8 * 3) < 0.02 mm from their chords).
std::vector<Eigen::Vector2d> design_outline(const tunnel::DesignProfile& profile) {
  constexpr double kStepM = 0.02;
  const double perimeter = profile.perimeter();
  const int n = std::max(8, static_cast<int>(std::ceil(perimeter / kStepM)));
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < n; ++k) points.push_back(profile.point_at_length(perimeter * k / n));
  return points;
}

// The block's faces (loops) split into triangles by core/blocks' ear
// clipping in each face's plane (a non-convex block's faces may be
// non-convex), rebuilt about the first corner so that survey coordinates
// keep their digits through the planes' fits.
std::optional<std::vector<std::array<int, 3>>> face_triangles(const analysis::ReportBlock& b,
                                                              std::vector<std::string>& notes) {
  const Eigen::Vector3d origin = b.vertices.front();
  std::vector<Eigen::Vector3d> relative;
  for (const auto& v : b.vertices) relative.push_back(v - origin);
  std::vector<blocks::FaceInput> faces;
  for (std::size_t f = 0; f < b.faces.size(); ++f) {
    blocks::FaceInput face;
    face.index = static_cast<int>(f);
    face.name = "face " + std::to_string(f);
    face.loop = b.faces[f];
    faces.push_back(std::move(face));
  }
  try {
    const blocks::Polyhedron poly = blocks::build_block_from_faces(b.id, relative, faces);
    return blocks::triangulate(poly).triangles;
  } catch (const Error& e) {
    notes.push_back("block " + b.id + " left out of the DXF: its faces do not close (" + e.what() +
                    ")");
    return std::nullopt;
  }
}

}  // namespace

std::string set_layer(const std::string& prefix, const std::string& set_label) {
  return storage::dxf_layer_name(prefix + "_" + (set_label.empty() ? "unassigned" : set_label));
}

std::string verdict_layer(const analysis::ReportBlock& block) {
  return storage::dxf_layer_name(std::string("BLOCKS_") +
                                 analysis::verdict_name(analysis::verdict_of(block)));
}

std::size_t add_traces(storage::DxfDrawing& drawing,
                       const std::vector<storage::Measurement>& measurements,
                       const std::vector<storage::Joint>& joints, const Eigen::Vector3d& datum,
                       std::vector<std::string>& notes) {
  std::map<std::string, std::string> set_of_joint;
  for (const auto& j : joints) set_of_joint[j.label] = j.set_label;
  const auto order = set_order(joints);
  std::size_t added = 0;
  for (const auto& m : measurements) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    if (m.points.size() < 2) {
      notes.push_back("trace " + m.label + " left out of the DXF: fewer than two points");
      continue;
    }
    const auto set = set_of_joint.find(m.joint_label);
    const std::string set_label = set == set_of_joint.end() ? std::string() : set->second;
    const std::string layer = set_layer("TRACES", set_label);
    drawing.add_layer(layer, set_colour(set_label, order));
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : m.points) points.push_back(p + datum);
    drawing.add_polyline(layer, points, false);
    ++added;
  }
  return added;
}

std::size_t add_joint_discs(storage::DxfDrawing& drawing, const std::vector<storage::Joint>& joints,
                            const std::vector<storage::JointSet>& sets,
                            const std::vector<storage::Measurement>& measurements,
                            const Eigen::Vector3d& datum, std::vector<std::string>& notes) {
  const auto order = set_order(joints);
  std::size_t added = 0, default_size = 0;
  for (const auto& j : joints) {
    if (!j.point) {
      notes.push_back("joint " + j.label +
                      " left out of the DXF: its orientation alone is known, not where it lies");
      continue;
    }
    // Its persistence: as measured, else its longest trace, else its set's
    // mean trace length.
    double diameter = j.persistence_m.value_or(0);
    if (diameter <= 0)
      for (const auto& m : measurements)
        if (m.kind == storage::Measurement::Kind::trace && m.joint_label == j.label &&
            m.trace_length_m)
          diameter = std::max(diameter, *m.trace_length_m);
    if (diameter <= 0)
      for (const auto& s : sets)
        if (s.label == j.set_label && s.mean_trace_length_m && *s.mean_trace_length_m > 0)
          diameter = *s.mean_trace_length_m;
    if (diameter <= 0) {
      diameter = 1.0;
      ++default_size;
    }
    const std::string layer = set_layer("JOINTS", j.set_label);
    drawing.add_layer(layer, set_colour(j.set_label, order));
    drawing.add_polyline(
        layer,
        disc_outline(*j.point + datum, geometry::plane_normal_deg(j.dip_deg, j.dipdir_deg),
                     diameter / 2),
        true);
    ++added;
  }
  if (default_size)
    notes.push_back(std::to_string(default_size) +
                    " joint disc(s) drawn 1 m across: neither the joint, its traces nor its set "
                    "has a measured length");
  return added;
}

std::size_t add_blocks(storage::DxfDrawing& drawing,
                       const std::vector<analysis::ReportBlock>& blocks,
                       std::vector<std::string>& notes) {
  std::size_t added = 0;
  for (const auto& b : blocks) {
    if (analysis::vertices_are_surface_loop(b)) {
      notes.push_back("block " + b.id +
                      " left out of the DXF: its points are its loop on the free surface, not "
                      "its corners");
      continue;
    }
    std::optional<std::vector<std::array<int, 3>>> triangles;
    if (!b.faces.empty()) {
      triangles = face_triangles(b, notes);
    } else if (b.convex) {
      // Stored before faces were reported: a convex block is the hull of
      // its corners.
      triangles = convex_hull_triangles(b.vertices);
      if (!triangles)
        notes.push_back("block " + b.id + " left out of the DXF: its corners span no volume");
    } else {
      notes.push_back("block " + b.id +
                      " left out of the DXF: it is not convex and was analysed before its faces "
                      "were reported (analyse the visit again)");
    }
    if (!triangles) continue;
    const std::string layer = verdict_layer(b);
    drawing.add_layer(layer, verdict_colour(analysis::verdict_of(b)));
    drawing.add_mesh(layer, b.vertices, *triangles);
    ++added;
  }
  return added;
}

std::size_t add_profile(storage::DxfDrawing& drawing, const VisitProfile& profile,
                        const Eigen::Vector3d& datum, std::vector<std::string>& notes) {
  // The round's own heading's direction (round_start.h), as its sections
  // were measured in: the developed view's arc length runs from the right
  // of the drive, so a heading driven toward descending chainage read in the
  // tunnel's ascending frame would be drawn mirrored about the axis.
  tunnel::Alignment alignment = profile.tunnel.alignment(datum);
  alignment.set_drive(profile.sense > 0 ? tunnel::Drive::ascending : tunnel::Drive::descending);
  const tunnel::DesignProfile& design = profile.tunnel.profile;
  const auto outline = design_outline(design);
  const auto& view = profile.deviation.view;
  drawing.add_layer("PROFILE_DESIGN", 7);
  drawing.add_layer("PROFILE_MEASURED", 6);
  std::size_t added = 0, unseen = 0;
  for (const auto& section : profile.deviation.sections) {
    const tunnel::TunnelFrame frame = alignment.frame_at(section.chainage);
    std::vector<Eigen::Vector3d> design_points;
    for (const auto& p : outline) design_points.push_back(frame.to_local(p.x(), p.y()) + datum);
    drawing.add_polyline("PROFILE_DESIGN", design_points, true);
    ++added;
    if (view.chainage.empty() || view.s.empty()) continue;
    // The developed view's row nearest the section (they are laid on the
    // same chainages; nearest guards against rounding).
    std::size_t row = 0;
    for (std::size_t r = 1; r < view.chainage.size(); ++r)
      if (std::abs(view.chainage[r] - section.chainage) <
          std::abs(view.chainage[row] - section.chainage))
        row = r;
    std::vector<Eigen::Vector3d> run;
    auto flush = [&] {
      if (run.size() >= 2) {
        drawing.add_polyline("PROFILE_MEASURED", run, false);
        ++added;
      }
      run.clear();
    };
    for (std::size_t col = 0; col < view.s.size(); ++col) {
      const float d = view.at(row, col);
      if (!std::isfinite(d)) {
        flush();
        continue;
      }
      const Eigen::Vector2d p =
          design.point_at_length(view.s[col]) +
          static_cast<double>(d) * design.outward_normal_at_length(view.s[col]);
      run.push_back(frame.to_local(p.x(), p.y()) + datum);
    }
    flush();
    if (section.seen_fraction <= 0) ++unseen;
  }
  if (unseen)
    notes.push_back(std::to_string(unseen) +
                    " cross-section(s) drawn without a measured outline: the 3D image does not "
                    "see the wall there");
  return added;
}

}  // namespace rockface::app
