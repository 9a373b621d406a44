#include "core/tunnel/deviation_message.h"

#include "core/common/number_format.h"

namespace rockface::tunnel {

void tell_the_geologist(ProfileDeviation& out, const DeviationOptions& options, std::size_t seen,
                        std::size_t excluded, const std::string& clipped,
                        const CellPrecisionFigures* per_cell) {
  bool walls_or_roof = false;
  std::size_t thin = 0;
  for (const auto& s : out.sections) {
    walls_or_roof = walls_or_roof || s.walls_seen > 0 || s.roof_seen > 0;
    if (s.seen_fraction < options.min_seen_fraction) ++thin;
  }
  const std::string range = "chainage " + format_fixed(out.view.chainage.front(), 3) + " to " +
                            format_fixed(out.view.chainage.back(), 3) + clipped;
  if (!walls_or_roof) {
    out.status = DeviationStatus::no_walls_in_view;
    out.message = (seen == 0 ? std::string("nothing of the profile was in view")
                             : std::string("only the floor was in view")) +
                  " (" + range + ", " + std::to_string(out.rays_cast) + " rays cast, " +
                  std::to_string(excluded) +
                  " stopped by what is not rock): no over- or underbreak can be given, not zero";
    return;
  }
  if (thin > 0) {
    out.status = DeviationStatus::partly_seen;
    out.message =
        std::to_string(thin) + " of " + std::to_string(out.sections.size()) +
        " cross-sections saw less than " + format_fixed(100 * options.min_seen_fraction, 0) +
        " % of the profile; areas and volumes cover only what was seen (" +
        format_fixed(100 * out.seen_fraction, 1) + " % of the outline over " + range + ")";
  } else {
    out.status = DeviationStatus::ok;
    out.message = format_fixed(100 * out.seen_fraction, 1) + " % of the outline seen over " + range;
  }
  // What the figures leave out, and why (issue 38).
  for (const auto& l : out.sections_left_out)
    out.message += "; " + std::to_string(l.sections) + " cross-section" +
                   (l.sections == 1 ? "" : "s") + " at chainage " +
                   format_fixed(l.chainage_from, 2) + " to " + format_fixed(l.chainage_to, 2) +
                   " left out: " + l.why;
  if (out.cells_off_lining + out.cells_below_invert > 0)
    out.message +=
        "; left out: " + std::to_string(out.cells_off_lining) +
        " cells off any plausible lining (stray: no neighbour agrees with them, or a piece "
        "smaller than the smallest break counted that jumps off the lining all "
        "round), " +
        std::to_string(out.cells_below_invert) +
        " below the invert (wall or roof rays that met the surface below it, floor "
        "rays more than " +
        format_fixed(options.max_invert_overbreak_m, 2) + " m below the design)";
  if (out.interpolated_fraction > 0)
    out.message += "; " + format_fixed(100 * out.interpolated_fraction, 1) +
                   " % of the outline interpolated across holes of the 3D image up to " +
                   format_fixed(options.max_interpolated_hole_m, 2) + " m wide (" +
                   format_fixed(out.interpolated_overbreak_m3, 3) + " m³ of the overbreak, " +
                   format_fixed(out.interpolated_underbreak_m3, 3) + " m³ of the underbreak)";
  if (per_cell)
    out.message += "; deviations within " + format_fixed(options.noise_sigmas, 0) +
                   " sigma of each cell's predicted depth precision (from its distance to the "
                   "cameras and its incidence: sigma " +
                   format_fixed(1000 * per_cell->min_sigma_m, 1) + " to " +
                   format_fixed(1000 * per_cell->max_sigma_m, 1) + " mm, median " +
                   format_fixed(1000 * per_cell->median_sigma_m, 1) +
                   " mm) are not counted, but for the flanks of a break beyond them, followed "
                   "down to the design";
  else if (out.noise_threshold_m > 0)
    out.message += "; deviations within " + format_fixed(1000 * out.noise_threshold_m, 1) +
                   " mm (" + format_fixed(options.noise_sigmas, 0) +
                   " sigma of the 3D image's stated depth precision) are not counted, "
                   "but for the flanks of a break beyond them, followed down to the design";
  else
    out.message += "; the 3D image states no depth precision: every deviation is counted";
  if (out.noise_patches > 0)
    out.message += "; " + std::to_string(out.noise_patches) + " patch" +
                   (out.noise_patches == 1 ? "" : "es") + " beyond the noise left out (" +
                   format_fixed(out.noise_patches_overbreak_m3, 3) + " m³ over, " +
                   format_fixed(out.noise_patches_underbreak_m3, 3) +
                   " m³ under): no deeper than " + format_fixed(options.noise_sigmas, 0) +
                   " sigma of the lining around them, whose measured spread can exceed the "
                   "predicted precision where the rock is poorly textured";
  if (out.lining_offset.cells > 0)
    out.message +=
        "; the lining lies " + format_fixed(1000 * out.lining_offset.median_m, 1) + " ± " +
        format_fixed(1000 * out.lining_offset.standard_error_m, 1) +
        " mm off the design as a whole" +
        (out.lining_offset_removed ? " (within the noise: taken as the 3D image's bias and removed)"
         : out.noise_threshold_m > 0 ? " (beyond the noise: kept)"
                                     : "");
}

}  // namespace rockface::tunnel
