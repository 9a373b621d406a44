// `rockface wedges SCENE.json|PROJECT [--visit N] [--axis TREND/PLUNGE]
// --out WEDGES.json [--png]`: the removable wedges around the excavation
// (roof, walls, floor, face) that three of the joint sets form, their size,
// mode and factor of safety with the support asked for.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/atomic_file.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/wedges/wedges_json.h"
#include "firmware-app/wedges/wedges_workflow.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/wedge_pictures.h"

namespace rockface::app {
namespace {

struct WedgesOptions {
  WedgesRequest request;
  std::string out;
  bool png = false;
};

VerbRun setup_wedges(CLI::App& sub) {
  auto o = std::make_shared<WedgesOptions>();
  auto& q = o->request;
  sub.add_option("INPUT", q.input, "a scene with a wedges section, or a project (*.rockface)")
      ->required();
  sub.add_option("--visit", q.visit,
                 "project: the visit whose sets are used (default: the latest)");
  sub.add_option("--axis", q.axis,
                 "TREND/PLUNGE of the drive in degrees (default: the scene's or the tunnel's)");
  sub.add_option("--out", o->out, "the wedges, a JSON file")->required();
  sub.add_flag("--png", o->png, "also the section and perspective picture, beside --out (.png)");
  sub.add_option("--preset", q.preset, "fast | standard | precise: how finely arcs are drawn");
  sub.add_option("--friction", q.friction_deg, "project: the sets' friction angle, deg (30)");
  sub.add_option("--cohesion", q.cohesion_pa, "project: the sets' cohesion, Pa (0)");
  sub.add_option("--trace-length", q.trace_length_m, "project: the joints' trace-length limit, m");
  sub.add_option("--bolts", q.bolts, "project: pattern bolts LENGTH,SPACING,CAPACITY[,BOND]");
  sub.add_option("--shotcrete", q.shotcrete, "project: shotcrete THICKNESS,SHEAR_STRENGTH");
  return [o] {
    const WedgesResult r = wedges_from_input(o->request);
    write_text_atomically(o->out, wedges_json(r.run, r.analysis));
    for (const auto& line : wedges_summary(r.run, r.analysis)) std::cout << line << "\n";
    std::cout << "wedges: " << o->out << "\n";
    if (o->png) {
      const auto png = std::filesystem::path(o->out).replace_extension(".png");
      storage::write_image_file(png, storage::wedges_picture(r.analysis), ".png");
      std::cout << "picture: " << png.string() << "\n";
    }
    return 0;
  };
}

const VerbRegistrar wedges_verb{
    "wedges",
    "the removable wedges that the joint sets form around the excavation (roof, walls, floor, "
    "face): size, apex, mode and factor of safety with water, seismic, bolts and shotcrete",
    setup_wedges};

}  // namespace
}  // namespace rockface::app
