#include "core/analysis/preset_options.h"

#include <gtest/gtest.h>

#include "core/kinematics/remote_axis.h"
#include "core/tunnel/wedge_analysis.h"

namespace rockface::analysis {
namespace {

constexpr Preset kPresets[] = {Preset::fast, Preset::standard, Preset::precise};

// The one place gives each component's options exactly as the component's
// own mapping does: the knobs each mapping sets per preset, compared one by
// one (exact: they are copies).
TEST(PresetOptions, EachComponentsOptionsAreItsOwnMappings) {
  for (const Preset p : kPresets) {
    SCOPED_TRACE(std::string(preset_name(p)));
    const PresetOptions o = preset_options(p);
    EXPECT_EQ(o.preset, p);

    const auto rec = photogrammetry::reconstruction_preset(p);
    EXPECT_EQ(o.reconstruction.name, rec.name);
    EXPECT_EQ(o.reconstruction.feature_max_width, rec.feature_max_width);
    EXPECT_EQ(o.reconstruction.max_features, rec.max_features);
    EXPECT_EQ(o.reconstruction.ratio_test, rec.ratio_test);
    EXPECT_EQ(o.reconstruction.refine_iterations, rec.refine_iterations);
    EXPECT_EQ(o.reconstruction.dense_max_width, rec.dense_max_width);
    EXPECT_EQ(o.reconstruction.max_disparities, rec.max_disparities);
    EXPECT_EQ(o.reconstruction.sgbm_block_size, rec.sgbm_block_size);
    EXPECT_EQ(o.reconstruction.sgbm_three_way, rec.sgbm_three_way);
    EXPECT_EQ(o.reconstruction.disparity_sigma_px, rec.disparity_sigma_px);
    EXPECT_EQ(o.reconstruction.lattice_step, rec.lattice_step);

    const auto facets = measure::facet_options(p);
    EXPECT_EQ(o.facets.angle_tolerance_deg, facets.angle_tolerance_deg);
    EXPECT_EQ(o.facets.min_area_m2, facets.min_area_m2);
    EXPECT_EQ(o.facets.smoothing_passes, facets.smoothing_passes);
    EXPECT_EQ(o.facets.refit_growth, facets.refit_growth);
    EXPECT_EQ(o.facets.planarity_in_sigmas, facets.planarity_in_sigmas);

    const auto proposals = measure::proposal_options(p);
    EXPECT_EQ(o.proposals.line_widths_m, proposals.line_widths_m);
    EXPECT_EQ(o.proposals.pixels_per_line, proposals.pixels_per_line);
    EXPECT_EQ(o.proposals.min_length_m, proposals.min_length_m);
    EXPECT_EQ(o.proposals.measure.sample_step_px, proposals.measure.sample_step_px);

    EXPECT_EQ(o.remote_axis_starts, kinematics::remote_axis_starts(p));

    const auto mech = mechanics::mechanics_options(p);
    EXPECT_EQ(o.mechanics.contact_density, mech.contact_density);
    EXPECT_EQ(o.mechanics.step, mech.step);
    EXPECT_EQ(o.mechanics.max_steps, mech.max_steps);

    const auto dyn = mechanics::dynamics_options(p);
    EXPECT_EQ(o.dynamics.abs_tol, dyn.abs_tol);
    EXPECT_EQ(o.dynamics.rel_tol, dyn.rel_tol);
    EXPECT_EQ(o.dynamics.max_step, dyn.max_step);

    const auto dev = tunnel::deviation_options(p);
    EXPECT_EQ(o.deviation.section_spacing_m, dev.section_spacing_m);
    EXPECT_EQ(o.deviation.ray_spacing_m, dev.ray_spacing_m);
    EXPECT_EQ(o.deviation.max_overbreak_m, dev.max_overbreak_m);

    EXPECT_EQ(o.wedge_sagitta_m, tunnel::wedge_sagitta(p));
  }
}

// The standard preset is each struct's defaults where the component says so
// (reconstruction/preset.h: "the defaults of the struct are the standard
// preset"; facets, proposals, mechanics, dynamics and deviation likewise).
TEST(PresetOptions, StandardIsTheComponentsDefaults) {
  const PresetOptions o = preset_options(Preset::standard);
  const photogrammetry::ReconstructionPreset rec;
  EXPECT_EQ(o.reconstruction.max_features, rec.max_features);
  EXPECT_EQ(o.reconstruction.dense_max_width, rec.dense_max_width);
  EXPECT_EQ(o.reconstruction.max_disparities, rec.max_disparities);
  const measure::FacetOptions facets;
  EXPECT_EQ(o.facets.angle_tolerance_deg, facets.angle_tolerance_deg);
  EXPECT_EQ(o.facets.min_area_m2, facets.min_area_m2);
  const measure::ProposalOptions proposals;
  EXPECT_EQ(o.proposals.line_widths_m, proposals.line_widths_m);
  EXPECT_EQ(o.proposals.pixels_per_line, proposals.pixels_per_line);
  const mechanics::MechanicsOptions mech;
  EXPECT_EQ(o.mechanics.contact_density, mech.contact_density);
  EXPECT_EQ(o.mechanics.step, mech.step);
  const mechanics::DynamicsOptions dyn;
  EXPECT_EQ(o.dynamics.abs_tol, dyn.abs_tol);
  EXPECT_EQ(o.dynamics.max_step, dyn.max_step);
  const tunnel::DeviationOptions dev;
  EXPECT_EQ(o.deviation.section_spacing_m, dev.section_spacing_m);
  EXPECT_EQ(o.deviation.ray_spacing_m, dev.ray_spacing_m);
  const tunnel::WedgeOptions wedges;
  EXPECT_EQ(o.wedge_sagitta_m, wedges.sagitta_m);
}

// Each monotonic knob moves one way from fast to standard to precise: more
// work (features, image width, disparities, starts, contact points, passes)
// or a finer step (spacing, tolerances, sagitta).
TEST(PresetOptions, PreciseDoesAtLeastTheWorkOfStandardAndStandardOfFast) {
  const PresetOptions fast = preset_options(Preset::fast);
  const PresetOptions standard = preset_options(Preset::standard);
  const PresetOptions precise = preset_options(Preset::precise);
  const auto more = [](const char* knob, double f, double s, double p) {
    EXPECT_LE(f, s) << knob;
    EXPECT_LE(s, p) << knob;
    EXPECT_LT(f, p) << knob << " does not change with the preset";
  };
  const auto finer = [&](const char* knob, double f, double s, double p) {
    more(knob, -f, -s, -p);
  };
  more("feature_max_width", fast.reconstruction.feature_max_width,
       standard.reconstruction.feature_max_width, precise.reconstruction.feature_max_width);
  more("max_features", fast.reconstruction.max_features, standard.reconstruction.max_features,
       precise.reconstruction.max_features);
  more("refine_iterations", fast.reconstruction.refine_iterations,
       standard.reconstruction.refine_iterations, precise.reconstruction.refine_iterations);
  more("dense_max_width", fast.reconstruction.dense_max_width,
       standard.reconstruction.dense_max_width, precise.reconstruction.dense_max_width);
  more("max_disparities", fast.reconstruction.max_disparities,
       standard.reconstruction.max_disparities, precise.reconstruction.max_disparities);
  finer("lattice_step", fast.reconstruction.lattice_step, standard.reconstruction.lattice_step,
        precise.reconstruction.lattice_step);
  finer("ratio_test", fast.reconstruction.ratio_test, standard.reconstruction.ratio_test,
        precise.reconstruction.ratio_test);
  finer("sgbm_block_size", fast.reconstruction.sgbm_block_size,
        standard.reconstruction.sgbm_block_size, precise.reconstruction.sgbm_block_size);
  finer("disparity_sigma_px", fast.reconstruction.disparity_sigma_px,
        standard.reconstruction.disparity_sigma_px, precise.reconstruction.disparity_sigma_px);
  finer("facets.angle_tolerance_deg", fast.facets.angle_tolerance_deg,
        standard.facets.angle_tolerance_deg, precise.facets.angle_tolerance_deg);
  finer("facets.min_area_m2", fast.facets.min_area_m2, standard.facets.min_area_m2,
        precise.facets.min_area_m2);
  finer("facets.refit_growth", fast.facets.refit_growth, standard.facets.refit_growth,
        precise.facets.refit_growth);
  more("facets.smoothing_passes", fast.facets.smoothing_passes, standard.facets.smoothing_passes,
       precise.facets.smoothing_passes);
  more("proposals.line_widths", static_cast<double>(fast.proposals.line_widths_m.size()),
       static_cast<double>(standard.proposals.line_widths_m.size()),
       static_cast<double>(precise.proposals.line_widths_m.size()));
  more("proposals.pixels_per_line", fast.proposals.pixels_per_line,
       standard.proposals.pixels_per_line, precise.proposals.pixels_per_line);
  finer("proposals.min_length_m", fast.proposals.min_length_m, standard.proposals.min_length_m,
        precise.proposals.min_length_m);
  more("remote_axis_starts", fast.remote_axis_starts, standard.remote_axis_starts,
       precise.remote_axis_starts);
  more("mechanics.contact_density", fast.mechanics.contact_density,
       standard.mechanics.contact_density, precise.mechanics.contact_density);
  finer("mechanics.step", fast.mechanics.step, standard.mechanics.step, precise.mechanics.step);
  finer("dynamics.abs_tol", fast.dynamics.abs_tol, standard.dynamics.abs_tol,
        precise.dynamics.abs_tol);
  finer("dynamics.rel_tol", fast.dynamics.rel_tol, standard.dynamics.rel_tol,
        precise.dynamics.rel_tol);
  finer("dynamics.max_step", fast.dynamics.max_step, standard.dynamics.max_step,
        precise.dynamics.max_step);
  finer("deviation.section_spacing_m", fast.deviation.section_spacing_m,
        standard.deviation.section_spacing_m, precise.deviation.section_spacing_m);
  finer("deviation.ray_spacing_m", fast.deviation.ray_spacing_m, standard.deviation.ray_spacing_m,
        precise.deviation.ray_spacing_m);
  finer("wedge_sagitta_m", fast.wedge_sagitta_m, standard.wedge_sagitta_m, precise.wedge_sagitta_m);
}

}  // namespace
}  // namespace rockface::analysis
