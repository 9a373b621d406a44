#include "core/faces/trace_blocks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "core/blocks/construction.h"
#include "core/blocks/mass_properties.h"
#include "core/blocks/slab_pairs.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/faces/tolerances.h"
#include "core/faces/trace_block_phases.h"
#include "core/geometry/parallel_planes.h"
#include "core/geometry/tolerances.h"

namespace rockface::faces {

namespace {

using geometry::HalfSpace;

// A joint corner turning right by more than this (radians) is reflex: below
// it the two joints are collinear to rounding and either construction gives
// the same block.
constexpr double kReflexCornerRad = 1e-6;

double sweep_ccw(double from, double to, double total) {
  double d = std::fmod(to - from, total);
  if (d < 0) d += total;
  return d;
}

// The block plane a polyhedron plane came from (names are unique within a
// kind: trace ids, patch ids).
int local_plane(const blocks::BlockPlane& bp, const std::vector<TraceBlockPlane>& planes) {
  for (size_t i = 0; i < planes.size(); ++i)
    if (planes[i].kind == bp.kind && planes[i].name == bp.name) return static_cast<int>(i);
  throw Error("trace block: polyhedron plane " + bp.name + " is none of the loop's planes");
}

// Assembles the union of convex cells that meet face to face: faces two
// cells share (same plane, opposite sides, same corners) are inside it.
struct CellUnion {
  std::vector<Eigen::Vector3d> vertices;  // datum-relative
  std::vector<blocks::FaceInput> faces;   // the boundary of the union
};

CellUnion union_faces(const std::vector<blocks::Polyhedron>& cells,
                      const std::vector<TraceBlockPlane>& planes) {
  double size = 0;
  for (const auto& c : cells) size = std::max(size, c.size());
  // Cells computed separately repeat shared corners to ~1e-15 relative;
  // 1e-7 of the size merges them and nothing else.
  const double merge = 1e-7 * size;
  std::vector<Eigen::Vector3d> vertices;
  auto vertex_id = [&](const Eigen::Vector3d& x) {
    for (size_t i = 0; i < vertices.size(); ++i)
      if ((vertices[i] - x).norm() <= merge) return static_cast<int>(i);
    vertices.push_back(x);
    return static_cast<int>(vertices.size() - 1);
  };
  struct CellFace {
    int plane;
    HalfSpace side;
    std::vector<int> loop;
    std::vector<int> sorted;
  };
  std::vector<CellFace> faces;
  for (const auto& c : cells)
    for (const auto& f : c.faces()) {
      CellFace cf;
      const blocks::BlockPlane& bp = c.planes()[f.plane];
      cf.plane = local_plane(bp, planes);
      cf.side = bp.side;
      for (int v : f.loop) cf.loop.push_back(vertex_id(c.vertices()[v]));
      cf.sorted = cf.loop;
      std::sort(cf.sorted.begin(), cf.sorted.end());
      faces.push_back(std::move(cf));
    }
  std::vector<bool> inside(faces.size(), false);
  for (size_t i = 0; i < faces.size(); ++i)
    for (size_t j = i + 1; j < faces.size(); ++j)
      if (faces[i].plane == faces[j].plane && faces[i].side != faces[j].side &&
          faces[i].sorted == faces[j].sorted)
        inside[i] = inside[j] = true;
  std::vector<blocks::FaceInput> input;
  std::vector<int> used(vertices.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (size_t i = 0; i < faces.size(); ++i) {
    if (inside[i]) continue;
    blocks::FaceInput fi;
    fi.index = planes[faces[i].plane].scene_index;
    fi.name = planes[faces[i].plane].name;
    fi.kind = planes[faces[i].plane].kind;
    fi.reference_normal = planes[faces[i].plane].plane.normal;
    for (int v : faces[i].loop) {
      if (used[v] < 0) {
        used[v] = static_cast<int>(kept.size());
        kept.push_back(vertices[v]);
      }
      fi.loop.push_back(used[v]);
    }
    input.push_back(std::move(fi));
  }
  return {std::move(kept), std::move(input)};
}

// Where the union is not one manifold solid without holes - cells that only
// touch along an edge or at a corner where joints cross behind the loop, or
// a ring of cells round a column of rock outside the block - it cannot be
// one Polyhedron. The verdicts still follow from its pieces: it is finite
// because every piece is bounded (with the least shut margin of the
// pieces), and it can move only along directions that leave every joint
// face of its boundary.
kinematics::Finiteness union_finiteness(const CellUnion& u, double shut_margin,
                                        double uncertainty) {
  kinematics::Finiteness f;
  for (const auto& face : u.faces) {
    if (face.kind != blocks::PlaneKind::Joint) continue;
    Eigen::Vector3d area2 = Eigen::Vector3d::Zero();  // along the outward normal
    for (size_t k = 0; k < face.loop.size(); ++k)
      area2 += u.vertices[face.loop[k]].cross(u.vertices[face.loop[(k + 1) % face.loop.size()]]);
    if (!(area2.norm() > 0)) continue;
    // Faces of one plane give one constraint (the margin search is O(m^4)).
    const Eigen::Vector3d inward = -area2.normalized();
    bool seen = false;
    for (const auto& n : f.joint_pyramid.normals()) seen = seen || (n - inward).norm() < 1e-9;
    if (!seen) f.joint_pyramid.add(inward);
  }
  f.jp_ep_margin = -shut_margin;
  f.finite = geometry::decide(shut_margin, uncertainty);
  kinematics::decide_removability(f, shut_margin, uncertainty);
  return f;
}

// The verdicts of a piece open between two joints taken as parallel.
struct SlabVerdict {
  kinematics::Finiteness finiteness;
  std::string note;
};

// A piece (its half-spaces, joints then patches, and their block-side
// normals) with two joints parallel within the block's uncertainty on both
// sides of it, meeting further than kParallelMeetInLoopSizes loop sizes
// from its loop: its finiteness with them exactly parallel, when that
// leaves it open (infinite); none when there are no such joints or they
// leave it shut (the construction then builds it, its corners near).
std::optional<SlabVerdict> open_slab(const std::vector<blocks::HalfSpaceInput>& hs,
                                     const std::vector<Eigen::Vector3d>& joint_in,
                                     const std::vector<Eigen::Vector3d>& free_in,
                                     const TraceBlock& block) {
  if (block.surface_polygon.empty()) return std::nullopt;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& x : block.surface_polygon) centre += x;
  centre /= static_cast<double>(block.surface_polygon.size());
  double size = 0;
  for (const auto& x : block.surface_polygon)
    for (const auto& y : block.surface_polygon) size = std::max(size, (x - y).norm());
  const double tolerance = std::max(block.uncertainty, geometry::kParallelRoundingRad);
  std::vector<std::pair<int, int>> parallel;
  const blocks::SlabPair* widest = nullptr;
  const std::vector<blocks::SlabPair> pairs =
      blocks::slab_pairs(hs, tolerance, centre, kParallelMeetInLoopSizes * size);
  for (const auto& p : pairs) {
    // The joints only: a joint parallel to a free face is another case.
    if (hs[p.first].kind != blocks::PlaneKind::Joint ||
        hs[p.second].kind != blocks::PlaneKind::Joint)
      continue;
    parallel.emplace_back(p.first, p.second);
    if (!widest || p.angle > widest->angle) widest = &p;
  }
  if (parallel.empty()) return std::nullopt;
  SlabVerdict v;
  v.finiteness = kinematics::halfspace_finiteness(joint_in, free_in, block.uncertainty, parallel);
  if (v.finiteness.finite.value) return std::nullopt;
  std::vector<Eigen::Vector3d> all = joint_in;
  all.insert(all.end(), free_in.begin(), free_in.end());
  const Eigen::Vector3d open =
      geometry::margin_with_parallel_planes(
          all, geometry::parallel_reduction(all, parallel,
                                            std::max(tolerance, v.finiteness.parallel_angle)))
          .direction;
  const std::string meet =
      std::isfinite(widest->meet_distance)
          ? "they would meet " + format_significant(widest->meet_distance, 3) + " m from the loop"
          : "they never meet";
  v.note = "infinite: joints " + hs[widest->first].name + " and " + hs[widest->second].name +
           " are parallel within " + format_significant(rad_to_deg(widest->angle), 3) +
           " degrees (taken as parallel: " + meet +
           "), and the block never ends between them in direction (" +
           format_significant(open.x(), 3) + ", " + format_significant(open.y(), 3) + ", " +
           format_significant(open.z(), 3) + ")";
  return v;
}

}  // namespace

namespace trace_block_phases {

std::string Piece::code() const {
  std::string c;
  for (auto s : sides) c += geometry::code_digit(s);
  return c;
}

std::vector<int> neighbouring_patches(const FreeSurface& surface, const SurfaceLoops& loops,
                                      const TraceNetwork& net, const SurfaceRegion& region,
                                      double tol) {
  const auto& patches = surface.patches();
  std::vector<Eigen::Vector3d> footprint;
  for (int f : region.faces)
    for (int h : loops.faces()[f].half_edges) footprint.push_back(net.vertices()[net.origin(h)]);
  const std::vector<int>& covered = region.patches;
  std::vector<int> extra;
  auto shares_corner = [&](int a, int b) {
    for (const auto& p : patches[a].polygon)
      for (const auto& q : patches[b].polygon)
        if ((p - q).norm() <= tol) return true;
    return false;
  };
  for (size_t q = 0; q < patches.size(); ++q) {
    const int qi = static_cast<int>(q);
    if (std::find(covered.begin(), covered.end(), qi) != covered.end()) continue;
    bool next_to = false, salient = true, behind = true;
    for (int p : covered) {
      next_to = next_to || shares_corner(p, qi);
      salient = salient && !surface.rock_is_union(p, qi, tol);
    }
    for (const auto& x : footprint) behind = behind && patches[q].height(x) <= tol;
    if (next_to && salient && behind) extra.push_back(qi);
  }
  return extra;
}

LoopPlanes loop_planes(const FreeSurface& surface, const TraceNetwork& net,
                       const SurfaceLoops& loops, const SurfaceRegion& region,
                       const TraceBlockOptions& options) {
  const auto& patches = surface.patches();
  LoopPlanes out;
  // The joints of the loop, by name.
  std::vector<int> groups = region.groups;
  std::sort(groups.begin(), groups.end(),
            [&](int a, int b) { return net.groups()[a].name < net.groups()[b].name; });
  out.uncertainty = options.orientation_uncertainty;
  for (int g : groups) {
    const PlaneGroup& pg = net.groups()[g];
    out.plane_of_group[g] = static_cast<int>(out.planes.size());
    out.planes.push_back(
        {pg.name, blocks::PlaneKind::Joint, pg.plane.plane, g, -1,
         pg.joint && pg.plane.source == TracePlaneSource::Joint ? pg.joint->index : -1});
    if (pg.plane.source == TracePlaneSource::Fitted) {
      out.uncertainty = std::max(out.uncertainty, pg.plane.uncertainty);
      out.notes.push_back("plane " + pg.name + " is fitted to its trace (uncertainty " +
                          format_significant(rad_to_deg(pg.plane.uncertainty), 3) + " degrees)");
    }
  }
  out.n_joints = static_cast<int>(out.planes.size());
  // The covered patches, then their neighbours.
  out.covered = region.patches;
  const std::vector<int> extra =
      neighbouring_patches(surface, loops, net, region, options.snap_tolerance);
  for (int p : out.covered)
    out.planes.push_back({patches[p].id, blocks::PlaneKind::FreeFace, patches[p].plane, -1, p});
  for (int p : extra)
    out.planes.push_back({patches[p].id, blocks::PlaneKind::FreeFace, patches[p].plane, -1, p});
  return out;
}

LoopShape loop_shape(const FreeSurface& surface, const TraceNetwork& net, const SurfaceLoops& loops,
                     const SurfaceRegion& region, const LoopPlanes& planes, double tol) {
  const auto& patches = surface.patches();
  const auto& edges = net.edges();
  LoopShape out;
  out.joint_sides.resize(static_cast<size_t>(planes.n_joints));
  out.reflex = region.loops.size() > 1;
  for (const auto& loop : region.loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const int h = loop[i], nx = loop[(i + 1) % loop.size()];
      const int g = edges[h / 2].group;
      const int patch = loops.faces()[loops.half_edge_face()[h]].patch;
      const Eigen::Vector3d d = net.vertices()[net.target(h)] - net.vertices()[net.origin(h)];
      const Eigen::Vector3d left = patches[patch].outward.cross(d);
      const double s = net.groups()[g].plane.plane.normal.dot(left);
      out.joint_sides[planes.plane_of_group.at(g)].insert(s > 0 ? HalfSpace::Upper
                                                                : HalfSpace::Lower);
      if (edges[nx / 2].group == g) continue;  // the same joint goes on: no corner
      const AroundVertex& av = net.around()[net.target(h)];
      const double corner = sweep_ccw(av.angle[net.slot(nx)], av.angle[net.slot(h ^ 1)], av.total);
      if (corner > std::numbers::pi + kReflexCornerRad) out.reflex = true;
    }
  const std::vector<int>& covered = planes.covered;
  for (size_t a = 0; a < covered.size(); ++a)
    for (size_t b = 0; b < covered.size(); ++b)
      if (a != b && surface.rock_is_union(covered[a], covered[b], tol)) out.rock_convex = false;
  for (const auto& s : out.joint_sides) out.one_side = out.one_side && s.size() == 1;
  return out;
}

// Their joints persist behind the island and bound the island's own block;
// the block around it is the outer loop's block without that one (cut by
// the island's planes into cells, all kept but the island's), so that it
// stays one solid without the pinch two crossing island joints would
// otherwise leave where they meet inside the rock.
Islands island_joints(const TraceNetwork& net, const SurfaceRegion& region,
                      const LoopPlanes& planes) {
  const auto& edges = net.edges();
  Islands out;
  out.island.assign(static_cast<size_t>(planes.n_joints), false);
  if (region.loops.size() > 1) {
    std::set<int> outer_groups;
    for (int h : region.loops.front()) outer_groups.insert(edges[h / 2].group);
    for (int j = 0; j < planes.n_joints; ++j)
      if (!outer_groups.count(planes.planes[j].group)) {
        out.island[j] = true;
        out.planes.push_back(j);
      }
  }
  return out;
}

Piece convex_piece(const FreeSurface& surface, const LoopPlanes& planes, const LoopShape& shape) {
  const int n_planes = static_cast<int>(planes.planes.size());
  Piece p;
  for (int j = 0; j < planes.n_joints; ++j) p.sides.push_back(*shape.joint_sides[j].begin());
  for (int k = planes.n_joints; k < n_planes; ++k)
    p.sides.push_back(surface.patches()[planes.planes[k].patch].rock_side);
  return p;
}

// Named by its first joint, not by the region index, so that the same loop
// gives the same block whatever the other traces (incremental analysis,
// trace_session.h).
std::string block_id(const TraceNetwork& net, const SurfaceRegion& region) {
  const int first_group = net.edges()[region.loops.front().front() / 2].group;
  return "loop along " + (first_group >= 0 ? net.groups()[first_group].name : std::string("?"));
}

PieceCells build_piece_cells(const std::string& id, const std::vector<Piece>& pieces,
                             const TraceBlockOptions& options, TraceBlock& block) {
  const int n_planes = static_cast<int>(block.planes.size());
  PieceCells out;
  out.shut_margin = std::numbers::pi / 2;
  for (size_t k = 0; k < pieces.size() && !out.unbounded; ++k) {
    std::vector<blocks::HalfSpaceInput> hs;
    std::vector<Eigen::Vector3d> joint_in, free_in;
    for (int j = 0; j < n_planes; ++j) {
      const TraceBlockPlane& bp = block.planes[j];
      hs.push_back({bp.scene_index, bp.name, bp.kind, bp.plane, pieces[k].sides[j]});
      (bp.kind == blocks::PlaneKind::Joint ? joint_in : free_in)
          .push_back(bp.plane.inward_normal(pieces[k].sides[j]));
    }
    // Two joints on both sides of the piece, parallel within the
    // uncertainty and meeting only far from the loop: the piece is open or
    // shut as it is with them exactly parallel, never by which way the
    // last hundredth of a degree turns them (a slab open along them came
    // out finite with corners 1,000 km out, issue 43).
    const std::optional<SlabVerdict> slab = open_slab(hs, joint_in, free_in, block);
    std::optional<blocks::ConvexConstruction> cc;
    try {
      if (hs.size() >= 4) cc = blocks::build_convex_block(id, hs, options.datum);
    } catch (const Error& e) {
      if (slab) {
        // The corners the construction could not close lie where the
        // parallel joints would meet: the piece is open between them.
        out.unbounded = true;
        block.finiteness = slab->finiteness;
        block.notes.push_back(slab->note);
        break;
      }
      // One loop whose geometry cannot be assembled must not stop the map:
      // its finiteness still follows from the cones alone, and the note
      // says what is missing.
      out.geometry_failed = true;
      block.finiteness = kinematics::halfspace_finiteness(joint_in, free_in, block.uncertainty);
      block.finite = block.finiteness.finite.value;
      block.notes.push_back(std::string("block geometry not assembled: ") + e.what());
      break;
    }
    if (slab && !(cc && cc->outcome == blocks::ConvexOutcome::Empty)) {
      out.unbounded = true;
      block.finiteness = slab->finiteness;
      block.notes.push_back(slab->note);
    } else if (!cc || cc->outcome == blocks::ConvexOutcome::Unbounded) {
      out.unbounded = true;
      block.finiteness = kinematics::halfspace_finiteness(joint_in, free_in, block.uncertainty);
      if (cc) {
        const Eigen::Vector3d& open = cc->open_direction;
        block.notes.push_back(
            "infinite: the block never ends in direction (" + format_significant(open.x(), 3) +
            ", " + format_significant(open.y(), 3) + ", " + format_significant(open.z(), 3) + ")");
      }
    } else if (cc->outcome == blocks::ConvexOutcome::Empty) {
      if (!pieces[k].may_be_empty)
        block.notes.push_back("piece " + pieces[k].code() +
                              " is empty: its joints leave no rock behind the loop");
    } else {
      if (block.convex)
        for (int j : cc->redundant) block.codes[0][j] = '2';
      out.cells.push_back(std::move(*cc->polyhedron));
      out.shut_margin = std::min(out.shut_margin, -cc->recession_margin);
    }
  }
  return out;
}

void analyse_cells(const std::string& id, std::vector<blocks::Polyhedron>& cells,
                   double shut_margin, const TraceNetwork& net, const TraceBlockOptions& options,
                   TraceBlock& block) {
  // The boundary of a union of pieces, kept for the verdicts should it
  // not make one polyhedron.
  std::optional<CellUnion> united;
  if (cells.size() > 1) united = union_faces(cells, block.planes);
  try {
    block.polyhedron =
        united ? blocks::build_block_from_faces(id, united->vertices, united->faces, options.datum)
               : std::move(cells.front());
    kinematics::BlockAnalysisInput in;
    in.density = options.density;
    in.effects = options.effects;
    in.uncertainty = block.uncertainty;
    for (const auto& bp : block.polyhedron->planes()) {
      kinematics::JointStrength s;
      const TraceBlockPlane& tp = block.planes[local_plane(bp, block.planes)];
      if (tp.kind == blocks::PlaneKind::Joint && net.groups()[tp.group].joint) {
        s.friction = net.groups()[tp.group].joint->friction;
        s.cohesion = net.groups()[tp.group].joint->cohesion;
      }
      in.strengths.push_back(s);
    }
    block.analysis = kinematics::analyse_block(*block.polyhedron, in);
    block.strengths = std::move(in.strengths);
    block.finiteness = block.analysis->finiteness;
    block.finite = block.finiteness.finite.value;
  } catch (const InputError& e) {
    block.polyhedron.reset();
    block.analysis.reset();
    block.notes.push_back(std::string("block geometry not assembled: ") + e.what());
    if (united) {
      block.finiteness = union_finiteness(*united, shut_margin, block.uncertainty);
      block.finite = block.finiteness.finite.value;
      double volume = 0;
      for (const auto& c : cells) volume += blocks::mass_properties(c, options.density).volume;
      block.notes.push_back("finite as the union of " + std::to_string(cells.size()) +
                            " bounded convex pieces (" + format_significant(volume, 3) +
                            " m^3); removability from the joint faces of its boundary; "
                            "no mode or factor of safety without one polyhedron");
    }
  }
}

}  // namespace trace_block_phases

std::optional<TraceBlock> trace_block(const FreeSurface& surface, const TraceNetwork& net,
                                      const SurfaceLoops& loops, int r,
                                      const TraceBlockOptions& options) {
  using namespace trace_block_phases;
  const double tol = options.snap_tolerance;
  const SurfaceRegion& region = loops.regions()[r];
  if (region.loops.empty()) return std::nullopt;
  TraceBlock block;
  block.region = static_cast<int>(r);
  block.traces = region.traces;
  for (int h : region.loops.front()) block.surface_polygon.push_back(net.vertices()[net.origin(h)]);

  LoopPlanes planes = loop_planes(surface, net, loops, region, options);
  block.uncertainty = planes.uncertainty;
  block.notes = planes.notes;
  const LoopShape shape = loop_shape(surface, net, loops, region, planes, tol);
  // Islands: joints whose traces lie only on loops inside the outer one.
  const Islands islands = island_joints(net, region, planes);

  std::vector<Piece> pieces;
  if (shape.convex()) {
    pieces.push_back(convex_piece(surface, planes, shape));
  } else {
    block.convex = false;
    NonConvexPieces found = nonconvex_pieces(surface, net, loops, region, planes, islands, tol);
    pieces = std::move(found.pieces);
    block.notes.insert(block.notes.end(), found.notes.begin(), found.notes.end());
  }
  block.planes = std::move(planes.planes);
  for (const auto& p : pieces) block.codes.push_back(p.code());

  const std::string id = block_id(net, region);
  PieceCells built = build_piece_cells(id, pieces, options, block);
  if (built.geometry_failed) return block;
  if (!built.unbounded && !built.cells.empty())
    analyse_cells(id, built.cells, built.shut_margin, net, options, block);
  else if (!built.unbounded)
    return std::nullopt;  // every piece empty: no block behind this loop
  if (built.unbounded) block.finite = false;
  return block;
}

void order_trace_blocks(std::vector<TraceBlock>& out) {
  // An order that does not depend on the order of the traces.
  auto key = [](const TraceBlock& b) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& x : b.surface_polygon) c += x;
    c /= static_cast<double>(std::max<size_t>(1, b.surface_polygon.size()));
    return std::array<long long, 3>{std::llround(c.x() * 1000), std::llround(c.y() * 1000),
                                    std::llround(c.z() * 1000)};
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const TraceBlock& a, const TraceBlock& b) { return key(a) < key(b); });
}

std::vector<TraceBlock> trace_blocks(const FreeSurface& surface, const TraceNetwork& net,
                                     const SurfaceLoops& loops, const TraceBlockOptions& options,
                                     Progress& progress) {
  std::vector<TraceBlock> out;
  for (size_t r = 0; r < loops.regions().size(); ++r) {
    progress.step("blocks from trace loops",
                  static_cast<double>(r) / static_cast<double>(loops.regions().size()));
    if (auto block = trace_block(surface, net, loops, static_cast<int>(r), options))
      out.push_back(std::move(*block));
  }
  order_trace_blocks(out);
  return out;
}

}  // namespace rockface::faces
