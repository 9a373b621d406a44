// `rockface report PROJECT --visit N --out REPORT.pdf`: the field report of
// one visit (storage/field_report).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/records/visit_field_report.h"
#include "storage/field_report/field_report.h"
#include "storage/field_report/field_report_pdf.h"
#include "storage/project/project_store.h"

namespace rockface::app {
namespace {

struct ReportOptions {
  std::string project, out;
  std::optional<storage::RecordId> visit;
};

VerbRun setup_report(CLI::App& sub) {
  auto o = std::make_shared<ReportOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--visit", o->visit, "visit id (default: the latest visit)");
  sub.add_option("--out", o->out, "the report, a PDF file")->required();
  return [o] {
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    storage::OpenOptions read;
    read.read_only = true;
    storage::ProjectStore store = storage::ProjectStore::open(o->project, read);
    const auto visit = o->visit ? o->visit : store.latest_visit();
    if (!visit) throw InputError(o->project, "the project has no visit to report");
    const storage::FieldReport report = collect_visit_report(store, *visit);
    storage::write_field_report_pdf(report, o->out);
    std::cout << "field report of visit " << *visit << ": " << o->out << " ("
              << report.blocks.size() << " blocks, " << report.joints.size() << " joints)\n";
    return 0;
  };
}

const VerbRegistrar report_verb{
    "report",
    "the field report of a visit as a PDF: face with traces and blocks, stereonet, "
    "joint sets, blocks, accuracy, camera and preset",
    setup_report};

}  // namespace
}  // namespace rockface::app
