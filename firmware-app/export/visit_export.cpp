#include "firmware-app/export/visit_export.h"

#include <algorithm>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/export/visit_drawing.h"
#include "firmware-app/records/project_visit.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "storage/exchange/deviation_csv.h"
#include "storage/exchange/dxf_drawing.h"
#include "storage/exchange/export_joints_csv.h"
#include "storage/exchange/export_obj.h"
#include "storage/exchange/export_ply.h"
#include "storage/exchange/traces_csv.h"

namespace rockface::app {

namespace {

bool asked(const std::vector<std::string>& what, const std::string& item) {
  return what.empty() || std::find(what.begin(), what.end(), item) != what.end();
}

// An item the visit lacks: an error when asked for by name, a note otherwise.
void lacking(const ExportRequest& request, const std::string& item, const std::string& why,
             ExportResult& result) {
  if (!request.what.empty())
    throw InputError("--what " + item, "visit " + std::to_string(request.visit) + " " + why);
  result.notes.push_back(item + " not exported: visit " + std::to_string(request.visit) + " " +
                         why);
}

std::string datum_words(const Eigen::Vector3d& datum) {
  return "datum (added to every coordinate) E " + format_fixed(datum.x(), 4) + " N " +
         format_fixed(datum.y(), 4) + " Z " + format_fixed(datum.z(), 4);
}

}  // namespace

const std::vector<std::string>& export_items() {
  static const std::vector<std::string> items{"mesh",   "cloud",  "traces",
                                              "joints", "blocks", "profile"};
  return items;
}

ExportResult export_visit(storage::ProjectStore& store, const ExportRequest& request) {
  require_visit(store, request.visit);
  for (const auto& item : request.what)
    if (std::find(export_items().begin(), export_items().end(), item) == export_items().end())
      throw InputError("--what", "no export item '" + item +
                                     "' (one or more of mesh, cloud, traces, joints, blocks, "
                                     "profile)");
  std::error_code ec;
  std::filesystem::create_directories(request.out_dir, ec);
  if (ec || !std::filesystem::is_directory(request.out_dir))
    throw Error(request.out_dir.string() + ": cannot make the export folder (" +
                (ec ? ec.message() : std::string("not a folder")) + ")");

  ExportResult result;
  const storage::ProjectInfo project = store.project();
  const Eigen::Vector3d datum = project.datum;
  const std::string stem = "visit-" + std::to_string(request.visit);
  const auto path = [&](const std::string& name) { return request.out_dir / name; };

  const auto models = store.list_visit_models(request.visit);
  for (const std::string item : {"mesh", "cloud"}) {
    if (!asked(request.what, item)) continue;
    if (models.empty()) {
      lacking(request, item, "has no 3D image", result);
      continue;
    }
    for (const auto& m : models) {
      const std::string name = stem + "-model-" + std::to_string(m.id);
      if (std::string(item) == "mesh") {
        export_model_obj(store, m.id, path(name + ".obj"));
        storage::export_model_ply(store, m.id, path(name + ".ply"));
        result.files.push_back(path(name + ".obj"));
        result.files.push_back(path(name + ".ply"));
      } else {
        storage::PlyOptions cloud;
        cloud.with_faces = false;
        storage::export_model_ply(store, m.id, path(name + "-cloud.ply"), cloud);
        result.files.push_back(path(name + "-cloud.ply"));
      }
    }
  }

  storage::DxfDrawing drawing;
  drawing.add_comment("rockface: project " + project.name + ", visit " +
                      std::to_string(request.visit) + "; x East, y North, z Up, metres" +
                      (project.datum_crs.empty() ? std::string() : ", " + project.datum_crs));
  drawing.add_comment(datum_words(datum));
  const auto measurements = store.list_measurements(request.visit);
  const auto joints = store.list_joints(request.visit);
  const bool any_trace = std::any_of(
      measurements.begin(), measurements.end(),
      [](const storage::Measurement& m) { return m.kind == storage::Measurement::Kind::trace; });
  if (asked(request.what, "traces")) {
    if (!any_trace) {
      lacking(request, "traces", "has no traces", result);
    } else {
      add_traces(drawing, measurements, joints, datum, result.notes);
      write_file_atomically(path(stem + "-traces.csv"), [&](std::ostream& out) {
        storage::write_traces_csv(out, measurements, joints, datum);
      });
      result.files.push_back(path(stem + "-traces.csv"));
    }
  }
  if (asked(request.what, "joints")) {
    if (joints.empty()) {
      lacking(request, "joints", "has no joints", result);
    } else {
      add_joint_discs(drawing, joints, store.list_joint_sets(request.visit), measurements, datum,
                      result.notes);
      storage::export_joints_csv(store, path(stem + "-joints.csv"), request.visit);
      result.files.push_back(path(stem + "-joints.csv"));
    }
  }
  if (asked(request.what, "blocks")) {
    const auto runs = store.list_analyses(request.visit);
    if (runs.empty()) {
      lacking(request, "blocks", "has no block analysis", result);
    } else {
      // The latest run is the visit's verdict (the tablet's and the report's).
      const storage::AnalysisRun run = store.load_analysis(runs.back().id);
      if (run.blocks.empty())
        lacking(request, "blocks", "has an analysis that found no blocks", result);
      else
        add_blocks(drawing, run.blocks, result.notes);
    }
  }
  if (asked(request.what, "profile")) {
    std::optional<VisitProfile> profile;
    try {
      profile = visit_profile(store, request.visit, request.preset, request.drive);
    } catch (const InputError& e) {
      lacking(request, "profile", std::string("has no profile: ") + e.what(), result);
    }
    if (profile) {
      add_profile(drawing, *profile, datum, result.notes);
      write_file_atomically(path(stem + "-profile.csv"), [&](std::ostream& out) {
        storage::write_deviation_csv(out, profile->deviation);
      });
      result.files.push_back(path(stem + "-profile.csv"));
    }
  }
  if (drawing.entity_count() > 0) {
    drawing.write(path(stem + ".dxf"));
    result.files.push_back(path(stem + ".dxf"));
  }
  if (!store.read_only())
    store.log_action(request.visit, "export",
                     std::to_string(result.files.size()) + " files to " + request.out_dir.string());
  return result;
}

}  // namespace rockface::app
