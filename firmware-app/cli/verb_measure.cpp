// `rockface measure MODEL.ply|PROJECT --traces PICKS.json --out MEASURES.json
//  [--png STEREONET.png] [--csv DIPS.csv] [--sets N|auto]
//  [--visit N | --model ID | --add-to-visit N]`
//
// Measures the picks on a 3D image: a model file (with the camera it was
// reconstructed with) or a project's visit, each pick on the 3D image of its
// pair (core/measure/picks.h `pair`), all in the face frame (the first pair's),
// stored as a new visit or, with --add-to-visit, in the visit measured on. Everything
// is measured before anything is written: a bad pick stops the verb (exit 2)
// naming it, with nothing stored and no output file
// (firmware-app/measure/measure_workflow.h). The options are read into the
// request by measure_options.h.
#include <cstdio>
#include <iostream>
#include <memory>

#include "core/common/units.h"
#include "core/measure/joined_traces.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/measure/measure_options.h"
#include "firmware-app/measure/measure_records.h"
#include "firmware-app/measure/measure_workflow.h"

namespace rockface::app {
namespace {

int run_measure(const MeasureOptions& o) {
  MeasureRequest request = measure_request(o);
  request.stored = [&](storage::RecordId visit) {
    std::cout << (request.add_to_visit ? "added to " : "stored in ") << request.on.source
              << ", visit " << visit << "\n";
  };
  const measure::MeasuredPicks measured = measure_picks_file(request).measured;
  std::size_t known = 0;
  for (const auto& t : measured.traces) known += t.m.plane.known ? 1 : 0;
  std::cout << measured.traces.size() << " traces (" << known << " with a known plane), "
            << measured.areas.size() << " areas, " << measured.points.size() << " points; "
            << measured.sets.size() << " joint sets\n";
  for (const auto& j : measured.joined) std::cout << measure::joined_note(j) << "\n";
  // The joints the traces name: the plane fitted to all their traces, or
  // why they give none.
  for (const auto& said : named_joint_notes(measured)) std::cout << said << "\n";
  // Issue 27: a plane given as a compass reading, and how the trace lies in it.
  for (const auto& t : measured.traces)
    if (t.compass)
      std::printf("%s: compass %.1f/%.1f%s: %s\n", t.m.id.c_str(), t.compass->reading.dip_deg,
                  t.compass->reading.dip_direction_deg, t.compass->marginal() ? " (marginal)" : "",
                  t.m.plane.problem.c_str());
  // A free face: its rock side, where it came from and how the camera saw it.
  for (const auto& a : measured.areas)
    if (!a.rock_side.empty() && a.m.plane.known)
      std::printf("%s: free face %.1f/%.1f, rock %s (%s, seen at %.1f deg, %.1f needed)%s%s\n",
                  a.m.id.c_str(), rad_to_deg(a.m.plane.orientation.dip),
                  rad_to_deg(a.m.plane.orientation.dipdir), a.rock_side.c_str(),
                  a.rock_side_from == "photograph" ? "behind the face photographed"
                                                   : "the pick's, marginal",
                  a.sight.least_deg, a.sight.needed_deg, a.m.plane.problem.empty() ? "" : ": ",
                  a.m.plane.problem.c_str());
  for (const auto& s : measured.sets) {
    const auto pl = s.fisher.plane();
    std::printf("set %s: %zu planes, mean %.1f/%.1f, K %.1f, alpha95 %.1f deg\n", s.label.c_str(),
                s.fisher.count, rad_to_deg(pl.dip), rad_to_deg(pl.dipdir), s.fisher.kappa,
                rad_to_deg(s.fisher.alpha95));
  }
  return 0;
}

VerbRun setup_measure(CLI::App& sub) {
  auto o = std::make_shared<MeasureOptions>();
  MeasureRequest& r = o->request;
  sub.add_option("MODEL", r.on.source,
                 "a model file (MODEL.ply of `rockface reconstruct`) or a project (*.rockface)")
      ->required();
  sub.add_option("--traces", r.picks, "the picks (rockface-picks/1, docs/scene-extensions.md)")
      ->required();
  sub.add_option("--out", r.out, "the measurements (rockface-measures/1)")->required();
  sub.add_option("--png", r.png, "stereonet picture (lower hemisphere, equal area)");
  sub.add_option("--csv", r.csv, "Dips-style CSV of the measured planes");
  sub.add_option("--sets", o->sets,
                 "number of joint sets, or auto (default: the picks', else auto)");
  sub.add_option("--visit", r.on.visit,
                 "project: the visit whose 3D images (one per pair; picks name theirs with "
                 "\"pair\") are measured on (default: the newest visit with a model)");
  sub.add_option("--model", r.on.model, "project: measure on this one model instead (pair 1 only)");
  sub.add_option("--add-to-visit", o->add_to_visit,
                 "project: measure on this visit's 3D images and store the measurements in it "
                 "(not in a new visit), so that one visit carries its camera, scale, north and "
                 "traces; refused for a visit without a 3D image or a label it already holds");
  sub.add_option("--geologist", r.geologist,
                 "project: the geologist who mapped the new visit, by name")
      ->type_name("NAME");
  sub.add_option("--camera", r.on.camera, "model file: the camera it was reconstructed with");
  sub.add_option("--photo", r.on.photo,
                 "model file: the left photograph (default: the model's TextureFile)");
  sub.add_option("--point-sigma", r.on.point_sigma,
                 "precision of a picked point, m (default: the reconstruction's sigma_Z)");
  sub.add_option("--friction", r.friction_deg,
                 "friction angle for the stereonet's sliding overlay, degrees (default 30)");
  return [o] { return run_measure(*o); };
}

const VerbRegistrar measure_verb{"measure", "measure traces, areas and points picked on a 3D image",
                                 setup_measure};

}  // namespace
}  // namespace rockface::app
