// `rockface export PROJECT --visit N --out DIR [--what mesh,cloud,...]`: what
// the office opens of one visit (firmware-app/export/visit_export.h): the 3D
// image as OBJ and PLY, traces, joints, blocks and the profile in one DXF,
// traces, joints and the over / underbreak as CSV.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/export/visit_export.h"

namespace rockface::app {
namespace {

struct ExportOptions {
  std::string project, preset = "standard";
  ExportRequest request;
};

VerbRun setup_export(CLI::App& sub) {
  auto o = std::make_shared<ExportOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--visit", o->request.visit, "visit id")->required();
  sub.add_option("--out", o->request.out_dir, "folder to write into (made when missing)")
      ->required();
  sub.add_option("--what", o->request.what,
                 "items, comma-separated: mesh, cloud, traces, joints, blocks, profile "
                 "(default: all the visit has)")
      ->delimiter(',');
  sub.add_option("--preset", o->preset, "the profile's cross-sections: fast | standard | precise");
  return [o] {
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    o->request.preset = parse_preset(o->preset, "--preset");
    storage::ProjectStore store = storage::ProjectStore::open(o->project);
    const ExportResult r = export_visit(store, o->request);
    for (const auto& f : r.files) std::cout << "wrote " << f.string() << "\n";
    for (const auto& n : r.notes) std::cout << "note: " << n << "\n";
    if (r.files.empty()) {
      std::cerr << "rockface export: nothing to export for visit " << o->request.visit << "\n";
      return 2;
    }
    return 0;
  };
}

const VerbRegistrar export_verb{
    "export",
    "writes a visit's 3D image, traces, joints, blocks and profile for the office's tools",
    setup_export};

}  // namespace
}  // namespace rockface::app
