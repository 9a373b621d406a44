// The scene's explicit blocks: each built as a polyhedron (half-spaces or
// vertices + faces), then mass properties, finiteness and removability, mode
// and factor of safety under the effects the scene lists.
#include <cmath>
#include <memory>

#include "core/analysis/block_dynamics.h"
#include "core/analysis/block_mechanics.h"
#include "core/analysis/block_report.h"
#include "core/analysis/scene_analysis.h"
#include "core/analysis/scene_effects.h"
#include "core/blocks/construction.h"
#include "core/blocks/convexity.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"

namespace rockface::analysis {

namespace {

std::string block_where(const AnalysisInput& scene, size_t i) {
  return scene.source + ": blocks[" + std::to_string(i) + "]";
}

// What analyse_block needs to know of one scene plane (joints, then free faces).
struct ScenePlane {
  std::string id;
  blocks::PlaneKind kind;
  Eigen::Vector3d normal;  // upward
  const std::optional<Eigen::Vector3d>* point;
  std::string field;  // "joints[2]"
};

std::vector<ScenePlane> scene_planes(const AnalysisInput& scene) {
  std::vector<ScenePlane> planes;
  for (size_t k = 0; k < scene.joints.size(); ++k) {
    const auto& j = scene.joints[k];
    planes.push_back({j.id, blocks::PlaneKind::Joint, geometry::plane_normal_deg(j.dip, j.dipdir),
                      &j.point, "joints[" + std::to_string(k) + "]"});
  }
  for (size_t k = 0; k < scene.free_faces.size(); ++k) {
    const auto& f = scene.free_faces[k];
    planes.push_back({f.id, blocks::PlaneKind::FreeFace,
                      geometry::plane_normal_deg(f.dip, f.dipdir), &f.point,
                      "free_faces[" + std::to_string(k) + "]"});
  }
  return planes;
}

std::string vec_text(const Eigen::Vector3d& v) {
  return "(" + format_significant(v.x(), 3) + ", " + format_significant(v.y(), 3) + ", " +
         format_significant(v.z(), 3) + ")";
}

void fill_verdicts(const kinematics::Finiteness& f, ReportBlock& rb) {
  rb.finite = f.finite.value;
  rb.removable = f.removable.value;
  rb.margin_deg = rad_to_deg(f.removable.margin);
  rb.marginal = f.removable.marginal || f.finite.marginal;
}

// A block whose polyhedron could not be built: finiteness and
// removability from its half-spaces alone, marginal, and a note saying why;
// no volume, mode or factor of safety (docs/scene-extensions.md).
ReportBlock unbuilt_block(ReportBlock rb, const std::vector<blocks::HalfSpaceInput>& hs,
                          double uncertainty, const std::string& why) {
  std::vector<Eigen::Vector3d> joint_in, free_in;
  for (const auto& h : hs)
    (h.kind == blocks::PlaneKind::Joint ? joint_in : free_in)
        .push_back(h.plane.inward_normal(h.side));
  fill_verdicts(kinematics::halfspace_finiteness(joint_in, free_in, uncertainty), rb);
  rb.marginal = true;
  rb.notes.push_back("block geometry not assembled (" + why +
                     "): finiteness and removability from its half-spaces alone, marginal; no "
                     "volume, mode or factor of safety");
  return rb;
}

}  // namespace

void analyse_scene_blocks(const AnalysisInput& scene, Report& report, Progress& progress) {
  const double uncertainty = deg_to_rad(scene.analysis.orientation_uncertainty_deg);
  const std::vector<ScenePlane> planes = scene_planes(scene);
  const kinematics::Effects effects = scene_effects(scene);
  for (const char* name : {"insitu_stress", "joint_law"})
    for (const auto& listed : scene.effects.listed())
      if (listed == name && !scene_wants_mechanics(scene))
        report.notes.push_back(std::string("blocks: ") + name +
                               " is not part of limit equilibrium (the equilibrium-path analysis "
                               "uses it)");

  for (size_t i = 0; i < scene.blocks.size(); ++i) {
    progress.step("blocks", 0.3 + 0.3 * static_cast<double>(i) / scene.blocks.size());
    const SceneBlock& sb = scene.blocks[i];
    ReportBlock rb;
    rb.id = sb.id;
    rb.source = "scene";
    rb.code.assign(planes.size(), '2');
    std::optional<blocks::Polyhedron> poly;

    if (sb.has_halfspaces()) {
      // Without a scene datum, the first plane point is the block's datum:
      // survey coordinates then lose no precision either.
      std::vector<blocks::HalfSpaceInput> hs;
      Eigen::Vector3d datum = scene.datum;
      bool have_datum = scene.has_datum;
      for (const auto& [id, code] : sb.halfspaces) {
        const int idx = scene.plane_index(id);
        const ScenePlane& sp = planes[idx];
        if (!*sp.point)
          throw InputError(scene.source + ": " + sp.field + ".point",
                           "missing: block " + sb.id +
                               " is given by half-spaces and needs a point on every plane");
        if (!have_datum) {
          datum = **sp.point;
          have_datum = true;
        }
        blocks::HalfSpaceInput h;
        h.index = idx;
        h.name = id;
        h.kind = sp.kind;
        h.plane.normal = sp.normal;
        h.plane.offset = sp.normal.dot(**sp.point - datum);
        h.side = code == 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
        hs.push_back(h);
        rb.code[idx] = static_cast<char>('0' + code);
      }
      blocks::ConvexConstruction cc;
      try {
        cc = blocks::build_convex_block(sb.id, hs, datum, scene.analysis.survey_precision_m);
      } catch (const InputError& e) {
        throw InputError(block_where(scene, i), e.reason());
      } catch (const Cancelled&) {
        throw;
      } catch (const Error& e) {
        // Valid half-spaces whose corners the construction cannot make into
        // one polyhedron: this block is reported as such, with the verdicts
        // its cones give and flagged marginal (its geometry is in doubt),
        // and the rest of the report is written (issue 40).
        report.blocks.push_back(unbuilt_block(std::move(rb), hs, uncertainty, e.what()));
        continue;
      }
      if (!cc.snapped.empty()) {
        std::string names;
        for (int k : cc.snapped) names += (names.empty() ? "" : ", ") + hs[k].name;
        rb.notes.push_back("planes " + names + " of block " + sb.id +
                           " taken through one corner: they pass within " +
                           format_significant(cc.snap_move, 2, " m") +
                           " of it, inside the survey's precision (analysis.survey_precision_m " +
                           format_significant(scene.analysis.survey_precision_m, 2, " m") + ")");
      }
      for (int r : cc.redundant)
        rb.notes.push_back("plane " + hs[r].name + " bounds no face of block " + sb.id +
                           " (it touches the block at most along an edge or a corner)");
      if (cc.outcome != blocks::ConvexOutcome::Bounded) {
        // An infinite or empty block: its verdicts from the half-spaces alone.
        std::vector<Eigen::Vector3d> joint_in, free_in;
        for (const auto& h : hs)
          (h.kind == blocks::PlaneKind::Joint ? joint_in : free_in)
              .push_back(h.plane.inward_normal(h.side));
        fill_verdicts(kinematics::halfspace_finiteness(joint_in, free_in, uncertainty), rb);
        if (cc.outcome == blocks::ConvexOutcome::Unbounded)
          rb.notes.push_back("block " + sb.id +
                             " is infinite: its half-spaces leave the direction " +
                             vec_text(cc.open_direction) + " open");
        else
          rb.notes.push_back("block " + sb.id +
                             " is empty: its half-spaces have no common interior");
        report.blocks.push_back(std::move(rb));
        continue;
      }
      poly = std::move(cc.polyhedron);
    } else {
      const Eigen::Vector3d datum = scene.has_datum ? scene.datum : sb.vertices.front();
      std::vector<Eigen::Vector3d> rel;
      for (const auto& v : sb.vertices) rel.push_back(v - datum);
      std::vector<blocks::FaceInput> faces;
      for (const auto& f : sb.faces) {
        const int idx = scene.plane_index(f.plane);
        faces.push_back({idx, f.plane, planes[idx].kind, planes[idx].normal, f.loop});
      }
      try {
        poly = blocks::build_block_from_faces(sb.id, rel, faces, datum);
      } catch (const InputError& e) {
        throw InputError(block_where(scene, i), e.what());
      }
      for (const auto& bp : poly->planes()) {
        const char digit = geometry::code_digit(bp.side);
        if (rb.code[bp.index] != '2' && rb.code[bp.index] != digit)
          rb.notes.push_back("block " + sb.id + " lies on both sides of plane " + bp.name +
                             ": its code digit names the first face's side");
        else
          rb.code[bp.index] = digit;
      }
    }

    kinematics::BlockAnalysisInput in;
    in.density = scene.density;
    in.uncertainty = uncertainty;
    in.effects = &effects;
    for (const auto& bp : poly->planes()) {
      kinematics::JointStrength s;
      if (bp.kind == blocks::PlaneKind::Joint) {
        const auto& j = scene.joints[bp.index];
        if (j.friction) s.friction = deg_to_rad(*j.friction);
        s.cohesion = j.cohesion.value_or(0.0);
      }
      in.strengths.push_back(s);
    }
    const kinematics::BlockAnalysis a = kinematics::analyse_block(*poly, in);

    rb.convex = blocks::is_convex(*poly);
    fill_verdicts(a.finiteness, rb);
    fill_block_report(*poly, a, scene.analysis, rb);
    if (scene_wants_mechanics(scene) && a.finiteness.finite.value)
      analyse_block_mechanics(*poly, scene, in.strengths, effects, rb, &progress);
    if (scene_wants_dynamics(scene) && a.finiteness.finite.value)
      analyse_block_dynamics(*poly, scene, effects, rb, &progress);
    report.blocks.push_back(std::move(rb));
  }
}

}  // namespace rockface::analysis
