// `rockface propose PROJECT [--visit N] --out PROPOSALS.json [--png]
// [--preset P] [--report REPORT.pdf]`: planar facets found on the visit's
// 3D image and the joint sets they form, proposed to the geologist (nothing
// is stored; accepted ones are measured from a picks file by `rockface
// measure`, as hand-picked ones).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/propose/proposals_json.h"
#include "firmware-app/propose/proposals_picture.h"
#include "firmware-app/propose/propose_workflow.h"
#include "firmware-app/propose/report_facets.h"
#include "firmware-app/records/visit_field_report.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_store.h"

namespace rockface::app {
namespace {

struct ProposeOptions {
  std::string project, out, preset = "standard", report;
  std::optional<storage::RecordId> visit;
  bool png = false;
  ProposeRequest request;
};

VerbRun setup_propose(CLI::App& sub) {
  auto o = std::make_shared<ProposeOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--visit", o->visit, "visit id (default: the newest visit with a 3D image)");
  sub.add_option("--out", o->out, "the proposals, a JSON file (rockface-proposals/1)")->required();
  sub.add_flag("--png", o->png,
               "also the picture of the facets by set over the photograph, beside --out (.png)");
  sub.add_option("--preset", o->preset,
                 "fast | standard | precise: angle tolerance, minimum area, smoothing");
  sub.add_option("--angle", o->request.angle_tolerance_deg,
                 "knob: angle tolerance of the growing, deg (over the preset's)");
  sub.add_option("--min-area", o->request.min_area_m2, "knob: smallest facet kept, m2");
  sub.add_option("--planarity", o->request.planarity_in_sigmas,
                 "knob: planarity gate in point sigmas");
  sub.add_option("--smoothing", o->request.smoothing_passes,
                 "knob: passes of normal smoothing over the triangles' neighbours");
  sub.add_option("--report", o->report,
                 "also the visit's field report (PDF) with a section on the facets");
  return [o] {
    ProposeRequest request = o->request;
    request.project = o->project;
    request.visit = o->visit;
    request.preset = parse_preset(o->preset, "--preset");
    NoProgress progress;
    const ProposeResult r = propose_for_visit(request, progress);
    write_text_atomically(o->out, proposals_json(r, request.preset));
    for (const auto& line : proposals_summary(r)) std::cout << line << "\n";
    std::cout << "proposals: " << o->out << "\n";
    if (o->png) {
      const auto png = std::filesystem::path(o->out).replace_extension(".png");
      storage::write_image_file(png, proposals_picture(r));
      std::cout << "picture: " << png.string() << "\n";
    }
    if (!o->report.empty()) {
      storage::OpenOptions read;
      read.read_only = true;
      storage::ProjectStore store = storage::ProjectStore::open(o->project, read);
      storage::FieldReport report = collect_visit_report(store, r.visit);
      add_facets_to_report(r, request.preset, report);
      storage::write_field_report_pdf(report, o->report);
      std::cout << "field report of visit " << r.visit << ": " << o->report << "\n";
    }
    return 0;
  };
}

const VerbRegistrar propose_verb{
    "propose",
    "planar facets found on a visit's 3D image and the joint sets they form (Fisher K, "
    "spacing), proposed for the geologist to accept by picks",
    setup_propose};

}  // namespace
}  // namespace rockface::app
