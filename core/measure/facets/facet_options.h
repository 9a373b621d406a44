#pragma once
// The knobs of facet detection (qFacets, Dewez et al. 2016; DSE, Riquelme
// et al. 2014) and their values per preset. docs/accuracy-cost.md
// ("Facets on the 3D image") measures what each costs and buys.
#include "core/common/preset.h"

namespace rockface::measure {

struct FacetOptions {
  // A triangle joins a facet when its (smoothed) normal is within this
  // angle of the facet's mean normal. Wider: fewer, larger facets that
  // may bend over a rounded edge; narrower: more, smaller, flatter ones.
  double angle_tolerance_deg = 10.0;
  // Facets smaller than this (m^2) are dropped: a joint face a geologist
  // would measure with a compass is at least a hand's width.
  double min_area_m2 = 0.05;
  // The planarity test of measuring (plane_measurement.h): a triangle joins
  // only when its centre lies within this many point sigmas of the facet's
  // plane, and a facet is kept only when its points' RMS off the fitted
  // plane is within it (tolerances.h kMaxPlanarityInSigmas for traces).
  double planarity_in_sigmas = 4.0;
  // Triangle normals are as noisy as their three vertices, and dense
  // matching leaves terraces (sub-pixel "pixel locking") a few pixels wide
  // on a face seen square: each normal is averaged with its neighbours'
  // this many times, a diffusion over about sqrt(passes) point spacings.
  // More passes cost time and round off steps and small facets.
  int smoothing_passes = 3;
  // A facet's plane is refitted every time it has grown by this factor
  // (the running plane the distance test uses).
  double refit_growth = 1.5;
};

// fast: coarse (wide angle, big facets, light smoothing); standard;
// precise: narrow angle, small facets, more smoothing.
FacetOptions facet_options(Preset preset);

// Throws InputError naming the field when a knob is out of range.
void check_facet_options(const FacetOptions& options);

}  // namespace rockface::measure
