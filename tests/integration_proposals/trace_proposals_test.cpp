#include <chrono>
#include <cstdio>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/photogrammetry/camera/camera_cv.h"
#include "tests/integration_proposals/proposal_faces.h"

namespace rm = rockface::measure;
namespace rt = rockface::testing;

TEST(TraceProposals, Tune) {
  for (auto d : {rt::JointDensity::none, rt::JointDensity::sparse, rt::JointDensity::medium,
                 rt::JointDensity::dense}) {
    auto t0 = std::chrono::steady_clock::now();
    const rt::ProposalFace f = rt::build_proposal_face(d, rockface::Preset::fast);
    auto t1 = std::chrono::steady_clock::now();
    const rm::MeshPicker picker(f.rec.mesh);
    rockface::NoProgress progress;
    auto options = rm::proposal_options(rockface::Preset::fast);
    options.measure.point_sigma = f.rec.accuracy.sigma_z;
    const auto r = rm::propose_traces(f.rec.mesh, picker, f.left, f.render.images[0], f.facets,
                                      options, progress, "test");
    auto t2 = std::chrono::steady_clock::now();
    const auto s = rt::score_proposals(f, r.proposals, picker, 0.05);
    std::printf(
        "%s: build %.1f s, propose %.2f s; %zu proposals, precision %.3f recall %.3f, "
        "proposed %.2f m false %.2f m truth %.2f m area %.1f m2; noise %.2f dark px %zu "
        "fold px %zu scale %.2f sigma_z %.4f\n",
        rt::density_name(d), std::chrono::duration<double>(t1 - t0).count(),
        std::chrono::duration<double>(t2 - t1).count(), s.proposals, s.precision, s.recall,
        s.proposed_m, s.false_m, s.truth_m, s.mapped_area_m2, r.line_noise, r.dark_pixels,
        r.fold_pixels, r.pixel_scale, f.rec.accuracy.sigma_z);
    for (const auto& n : r.notes) std::printf("  note: %s\n", n.c_str());
    for (const auto& p : r.proposals)
      std::printf(
          "  %s conf %.2f cue %s len %.2f dark %.2f (%.1f grey) fold %.2f (%.1f deg) "
          "facet %d plane %s\n",
          p.id.c_str(), p.confidence, rm::proposal_cue_name(p.cue), p.trace.length, p.dark_fraction,
          p.contrast_grey, p.fold_fraction, p.fold_deg, p.facet_id.value_or(0),
          p.trace.plane.known ? "known" : "unknown");
    if (d == rt::JointDensity::medium) {
      cv::imwrite("/tmp/prop_medium.png", f.render.images[0]);
    }
  }
}
