#pragma once
// The excavated surface against the design profile: over- and underbreak.
//
// A visit's 3D image (face, walls, roof; several pairs concatenated into one
// mesh) is cut by cross-sections every `section_spacing_m` of chainage. In
// each section, rays leave the profile's ray centre (design_profile.h) in the
// cross-section plane, one every `ray_spacing_m` of design outline, and are
// cast against the mesh (a bounding-volume hierarchy over its triangles).
// The first triangle a ray meets is the excavated surface there; a ray that
// meets a "not rock" triangle first (range pole, the camera's shadow) is
// excluded, and one that meets nothing within reach is "not seen".
//
// Deviation is measured ALONG THE RAY from the ray centre, not along the
// outline's normal: one ray gives one unambiguous surface point per
// direction (normals of a polygonal outline cross inside concave corners and
// leave gaps outside convex ones), and the area between design and surface
// is then exact in polar form, A = 1/2 integral (r_surface^2 - r_design^2)
// dtheta, with no error from the outline's curvature. For a circle about its
// centre the two measures coincide. Because specifications give the
// underbreak tolerance as a thickness normal to the design line, the
// tolerance is checked against the NORMAL depth, the ray deviation times the
// cosine of the angle between the ray and the outline's normal (exact on
// straight segments; on arcs to second order in deviation / radius).
//
// Positive deviation = overbreak (the surface lies outside the design line),
// negative = underbreak (rock inside it).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/preset.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/lining_statistics.h"
#include "core/tunnel/mesh_raycast.h"

namespace rockface::tunnel {

struct DeviationOptions {
  // The round: ascending or not, both included. Keep its end ~0.5 m behind
  // the face (FacePlace::face_chainage in tunnel_relative.h): a section
  // closer to the face meets the face's own relief, which is not wall.
  double chainage_from = 0, chainage_to = 0;
  double section_spacing_m = 0.25;  // between cross-sections
  // Between rays along the design outline (the angular resolution expressed
  // at the outline: angle = spacing / distance from the ray centre). The
  // area error of a section is of the order of the deviation's variation
  // between two rays; a patch edge is placed within half a spacing.
  double ray_spacing_m = 0.05;
  double underbreak_tolerance_m = 0.05;  // normal depth of rock allowed inside the line
  // A ray meeting the surface more than this beyond the design line (a
  // cross passage, a hole in the mesh to something far) counts as not seen.
  double max_overbreak_m = 3.0;
  // A section seeing less than this fraction of its outline is "partly seen";
  // a visit whose sections see nothing of walls / roof is "no walls in view".
  double min_seen_fraction = 0.5;
  // Issue 38: robust figures. Each cell of the developed view is sampled by
  // n x n rays (n along the outline, n along the chainage, evenly inside the
  // cell) and its deviation is the median of those that meet rock: a speck
  // of noise or a stray triangle that fewer than half of them meet makes no
  // figure. A cell is rock when its rays meet more rock than not rock.
  int rays_per_cell_side = 3;
  // The 3D image's stated precision: its predicted depth sigma (m, the
  // reconstruction's record); 0 = not stated (then nothing is taken for
  // noise and the figures carry no uncertainty).
  double depth_sigma_m = 0;
  // Deviations within this many depth sigmas of the lining are the
  // reconstruction's noise and are not counted as over- or underbreak (2:
  // 95 % of the cells of a surface on the design line stay within it).
  double noise_sigmas = 2;
  // How steeply the excavated surface plausibly turns between neighbouring
  // cells (m of deviation per m on the developed view; 2 = a rock face at
  // 63 degrees to the design line, steeper than the flank of any break a
  // blast leaves that is wider than two cells): a cell no neighbour agrees
  // with within it (plus twice the noise threshold) is off the lining, and
  // so is a piece of agreeing cells smaller than min_break_chainage_m x
  // min_break_outline_m that meets the seen lining only across such a jump
  // (lining_statistics.h).
  double plausible_slope = 2.0;
  // How far below the design invert a floor ray's surface plausibly lies
  // (m, normal to the invert): the lifters' overbreak and the muck left on
  // the floor are a few decimetres. A floor cell met deeper is a stray sheet
  // seen through a hole in the floor's mesh (a reconstruction's background,
  // issue 38: 1.8 m below the floor was counted as the round's largest
  // overbreak), not rock: it is left out as below the invert, and said.
  double max_invert_overbreak_m = 0.5;
  // Unseen cells inside the measured lining (lining_interpolation.h): a hole
  // of the 3D image no wider than this (m of developed surface, along the
  // outline or the chainage) between measured cells is filled by
  // interpolating them, counted in the volumes with its share and its
  // uncertainty said; a wider hole stays unseen. 0.75 m: the length of the
  // smallest break the round counts (min_break_chainage_m, the patch rule
  // below), so that a hole filled cannot hide a whole counted break along
  // the chainage (a break within it is missed, and its volume is within
  // the uncertainty stated). It was 0.5 m before the patch rule (tenth
  // session: the sample heading's pocket has a near flank seen at about 78
  // deg of incidence by its geometry, holes of 0.5-0.75 m along the chainage
  // between its lip and its crest, 0.042 m3 of its 0.748 left out with 0.5
  // m; issue 38). 0 = never.
  double max_interpolated_hole_m = 0.75;
  // The robust patch rule (break_patches.h): a cell beyond the noise counts
  // only inside a patch of its sign at least this long (m of chainage) and
  // this wide (m of outline), as whole cells allow (at the standard preset
  // 3 sections by 5 rays, 0.74 x 0.25 m). The reconstruction's systematic
  // errors that pass the noise threshold lie in narrower bands (issue 38:
  // on the D heading 0.29 of its 0.38 m3 of underbreak, where the scene has
  // 0.09), while the smallest break that matters for a round's volume is a
  // metre or more across. 0 = every counted cell counts. A patch so kept
  // counts when it is deeper than the lining around it is rough
  // (break_significance.h: noise_sigmas x the larger of its cells'
  // predicted sigma and the spread of the lining within 1 m around it).
  double min_break_chainage_m = 0.75;
  double min_break_outline_m = 0.25;
};

// The options of a preset (the knobs beside their component, issue 37):
// section spacing and ray spacing, fast 0.5 m / 0.1 m, standard 0.25 m /
// 0.05 m, precise 0.1 m / 0.02 m (their cost and accuracy are in
// docs/accuracy-cost.md, "The tunnel drive"); the rest as above.
DeviationOptions deviation_options(Preset preset);

// The visit's surface: datum-relative vertices (the alignment's local frame)
// and triangles. Optional masks of what is not rock: one flag per vertex (a
// triangle with any flagged vertex is excluded) and/or one per triangle;
// empty = all rock.
struct SurfaceInput {
  std::span<const Eigen::Vector3d> vertices;
  std::span<const std::array<int, 3>> triangles;
  std::span<const std::uint8_t> not_rock_vertex;
  std::span<const std::uint8_t> not_rock_triangle;
};

// Where on the tunnel a sample lies.
struct ProfilePosition {
  double chainage = 0;
  double s = 0;      // arc length along the design outline (design_profile.h)
  double angle = 0;  // radians, of the ray, counter-clockwise from right
  Eigen::Vector3d local = Eigen::Vector3d::Zero();   // the surface point, datum-relative
  Eigen::Vector3d survey = Eigen::Vector3d::Zero();  // the same in survey coordinates
};

struct SectionDeviation {
  double chainage = 0;
  double overbreak_area_m2 = 0;   // of the seen part of the outline
  double underbreak_area_m2 = 0;  // of the seen part
  double seen_fraction = 0;       // of the outline's length, in [0, 1]
  double excluded_fraction = 0;   // rays stopped by "not rock"
  // Seen fraction of the roof (v above the ray centre), walls (between) and
  // floor (below the lowest third): what the camera saw of each.
  double roof_seen = 0, walls_seen = 0, floor_seen = 0;
  double max_overbreak_m = 0, max_underbreak_m = 0;  // normal depths, >= 0 (counted cells)
};

// Sections at the ends of the asked range that met nothing of the surface
// (the photographs do not reach there): left out of the round.
struct SectionsLeftOut {
  double chainage_from = 0, chainage_to = 0;
  std::size_t sections = 0;
  std::string why;
};

// A connected stretch of underbreak beyond tolerance on the developed view.
struct UnderbreakPatch {
  double chainage_from = 0, chainage_to = 0;
  double s_from = 0, s_to = 0;  // on the developed view (may wrap past 0)
  std::size_t cells = 0;
  double area_m2 = 0;      // of excavated surface (developed cells)
  double max_depth_m = 0;  // normal depth at its deepest
  ProfilePosition deepest;
};

// The developed view: rows = chainage (row i at chainage[i]), columns = arc
// length (column j at s[j]); value = normal deviation (m, + over; less the
// lining's offset when that was removed), NaN where not seen, excluded, left
// out or out of reach. `state` says which (0 seen, 1 not seen, 2 excluded as
// not rock, 3 left out: off any plausible lining or below the invert,
// 4 interpolated from measured neighbours: its deviation is the
// interpolation's).
struct DevelopedView {
  std::vector<double> chainage, s;
  std::vector<float> deviation_m;  // row-major, chainage.size() x s.size()
  std::vector<std::uint8_t> state;
  float at(std::size_t row, std::size_t col) const { return deviation_m[row * s.size() + col]; }
};

enum class DeviationStatus {
  ok,                // every section saw at least min_seen_fraction
  partly_seen,       // some sections saw less (their areas cover only what was seen)
  no_walls_in_view,  // no section saw walls or roof: nothing to compare, not zero
  outside_alignment  // the chainage range is not on the alignment
};
const char* deviation_status_name(DeviationStatus status);

struct ProfileDeviation {
  DeviationStatus status = DeviationStatus::no_walls_in_view;
  std::string message;  // for the geologist: what was seen, what was not
  std::vector<SectionDeviation> sections;
  // Over the round, trapezoidal in chainage over the sections (the unseen
  // parts contribute nothing: read with seen_fraction).
  double overbreak_volume_m3 = 0, underbreak_volume_m3 = 0;
  double seen_fraction = 0;  // of the developed view's cells, measured
  // Of the developed view's cells, interpolated across a hole of the 3D
  // image (max_interpolated_hole_m); their part of the volumes.
  double interpolated_fraction = 0;
  double interpolated_overbreak_m3 = 0, interpolated_underbreak_m3 = 0;
  double max_interpolated_hole_m = 0;  // the bound applied (options)
  double excluded_fraction = 0;        // cells excluded as not rock
  bool has_underbreak = false;
  ProfilePosition max_underbreak;  // deepest normal underbreak (valid if has_underbreak)
  double max_underbreak_m = 0;
  double max_overbreak_m = 0;
  ProfilePosition max_overbreak;  // the largest normal overbreak (valid if max_overbreak_m > 0)

  // Issue 38: what the figures count, what they leave out, how sure they are.
  // Only cells whose deviation lies beyond the noise threshold (noise_sigmas
  // x the stated depth sigma; 0 when none was stated), in a patch the patch
  // rule keeps (min_break_chainage_m x min_break_outline_m) and deeper than
  // the lining around it is rough (break_significance.h), count as over- or
  // underbreak, with their break's flanks followed down to the design
  // (break_flanks.h): in the volumes, the areas and the largest of each.
  double noise_threshold_m = 0;
  // Patches the patch rule kept that were no deeper on average than
  // noise_sigmas x the larger of their predicted sigma and the spread of the
  // lining around them: left out as the reconstruction's noise, and said
  // (their count and their volume of each sign, m3).
  std::size_t noise_patches = 0;
  double noise_patches_overbreak_m3 = 0, noise_patches_underbreak_m3 = 0;
  // The lining's offset from the design as a whole (the median of the cells
  // within the noise threshold of the median of all, so that the breaks do
  // not pull it; its standard error from their spread). When
  // it lies within the noise threshold it cannot be told from the
  // reconstruction's bias and is removed from every cell; beyond it the
  // lining really lies off the design (a round excavated all round wide) and
  // it is kept, and stated.
  LiningOffset lining_offset;
  bool lining_offset_removed = false;
  std::size_t cells_off_lining = 0;  // left out: stray cells and pieces (plausible_slope)
  // Left out: a wall or roof ray met them below the invert, or a floor ray
  // more than max_invert_overbreak_m below the design.
  std::size_t cells_below_invert = 0;
  double max_invert_overbreak_m = 0;  // the bound applied (options)
  std::vector<SectionsLeftOut> sections_left_out;
  // One sigma of the volumes (the depth sigma and the offset's standard
  // error over the counted area, and each interpolated cell's own sigma
  // over its area, taken as fully correlated) and of a single measured
  // cell's deviation; absent when no depth sigma was stated.
  std::optional<double> overbreak_volume_sigma_m3, underbreak_volume_sigma_m3, cell_sigma_m;
  // Deepest first. A patch's area is that of its cells on the developed
  // view (ray spacing x section spacing each; one section: the spacing
  // asked for).
  std::vector<UnderbreakPatch> beyond_tolerance;
  double underbreak_tolerance_m = 0;
  DevelopedView view;
  std::size_t rays_cast = 0, triangles = 0;
};

// Throws InputError naming the option or input ("options.ray_spacing_m",
// "surface.triangles[12]") when it is unusable; an empty mesh is not an
// error: it is reported as no_walls_in_view.
ProfileDeviation profile_deviation(const SurfaceInput& surface, const Alignment& alignment,
                                   const DesignProfile& profile, const DeviationOptions& options);
// The same with the mesh's ray caster built once by the caller (built from
// surface.vertices and surface.triangles): for several rounds or repeated
// views of one mesh, the build dominates large meshes
// (docs/accuracy-cost.md, "The tunnel drive").
ProfileDeviation profile_deviation(const MeshRaycaster& caster, const SurfaceInput& surface,
                                   const Alignment& alignment, const DesignProfile& profile,
                                   const DeviationOptions& options);

}  // namespace rockface::tunnel
