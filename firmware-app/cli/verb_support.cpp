// `rockface support PROJECT --visit N [--classes FILE] [--esr USE]
// [--decide CLASS --by NAME [--reason TEXT] [--change "WHAT: FROM -> TO:
// REASON"]...] --out F.json [--png F.png]`:
// the round's support: what the Q chart and Bieniawski's table call for,
// the designer's class the visit meets, the proposed and the chosen class
// checked on the visit's wedges and the face's moving blocks, and the
// decision stored with the visit.
#include <iostream>
#include <memory>

#include "core/common/atomic_file.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/support/support_change_text.h"
#include "firmware-app/support/support_json.h"
#include "firmware-app/support/visit_support.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/support_pictures.h"

namespace rockface::app {
namespace {

struct SupportOptions {
  SupportRequest request;
  long long visit = 0;
  std::string out;
  std::optional<std::string> png;
  std::vector<std::string> changes;  // as typed: support_change_text.h
};

VerbRun setup_support(CLI::App& sub) {
  auto o = std::make_shared<SupportOptions>();
  auto& q = o->request;
  sub.add_option("PROJECT", q.project, "the project (*.rockface)")->required();
  sub.add_option("--visit", o->visit, "the visit (the round's face)")->required();
  sub.add_option("--classes", q.classes_file,
                 "the designer's support classes (JSON, rockface-support-classes/1): stored for "
                 "the tunnel");
  sub.add_option("--esr", q.esr_use,
                 "the excavation's use for the ESR (NGI 2015 table: road_rail_major, "
                 "road_rail_minor, permanent_mine, ...); default: the form's ESR");
  sub.add_option("--decide", q.decide, "the class chosen for the round (stored with the visit)");
  sub.add_option("--by", q.by, "who decided");
  sub.add_option("--reason", q.reason, "why (required when the class is not the proposed one)");
  sub.add_option("--change", o->changes,
                 "a change to the chosen class for this round, \"WHAT: FROM -> TO: REASON\" "
                 "(e.g. \"bolt spacing: 1.5 m -> 1.2 m: wedge W3\"); repeat for each");
  sub.add_option("--out", o->out, "the support, a JSON file")->required();
  sub.add_option("--png", o->png, "the Q chart with the visit's point, a PNG file");
  return [o] {
    o->request.visit = o->visit;
    for (const auto& text : o->changes)
      o->request.changes.push_back(parse_support_change(text, "--change"));
    const VisitSupport s = visit_support(o->request);
    write_text_atomically(o->out, support_json(s).dump(2) + "\n");
    for (const auto& line : support_summary(s)) std::cout << line << "\n";
    std::cout << "support: " << o->out << "\n";
    if (o->png) {
      storage::write_image_file(*o->png, storage::q_chart_picture(s.q_point), ".png");
      std::cout << "picture: " << *o->png << "\n";
    }
    return 0;
  };
}

const VerbRegistrar support_verb{
    "support",
    "the round's support: the Q chart's and Bieniawski's, the designer's class the visit meets, "
    "checked on the wedges and the face's blocks, and the decision",
    setup_support};

}  // namespace
}  // namespace rockface::app
